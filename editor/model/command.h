#pragma once
// Every edit is a command that can be applied and reverted exactly. LevelChange is the one concrete edit: it
// records entity insertions and removals with their indices, entity updates as before/after copies, and the
// level fields (name, settings, player start, next_id, the level's own links, the objectives, the editor
// section) before and
// after, so undo restores entity order, ids and next_id bit for bit. CompoundCommand groups several into one
// history step (transactions).
#include "model/document.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ks::editor {

class Command {
  public:
    virtual ~Command() = default;
    virtual void apply(Document& doc) const = 0;
    virtual void revert(Document& doc) const = 0;
    const std::string& name() const { return name_; }
    void set_name(std::string name) { name_ = std::move(name); }

    // The selection before and after the edit, restored by undo and redo.
    std::vector<int> selection_before, selection_after;

  protected:
    std::string name_;
};

struct EntityAtIndex {
    size_t index = 0;
    level::Entity entity;
};
struct EntityUpdate {
    level::Entity before, after; // same id
};
template <class T>
struct Change {
    T before, after;
};

class LevelChange final : public Command {
  public:
    // Applied in this order: updates, removals (by their index before the edit, highest first), insertions
    // (by their index after the edit, lowest first), level fields. Revert runs the exact inverse.
    std::vector<EntityUpdate> updates;
    std::vector<EntityAtIndex> removals;   // sorted by index, ascending
    std::vector<EntityAtIndex> insertions; // sorted by index, ascending
    std::optional<Change<std::string>> level_name;
    std::optional<Change<level::Settings>> settings;
    std::optional<Change<level::PlayerStart>> player_start;
    std::optional<Change<int>> next_id;
    std::optional<Change<std::vector<level::Link>>> level_links;
    std::optional<Change<std::vector<level::Objective>>> objectives; // the whole list (at most a few dozen)
    // The editor section (layers, groups, prefab links, hide/lock): whole, before and after; it holds ids,
    // not entities, so a copy stays small next to the entities an edit records.
    std::optional<Change<level::EditorData>> editor_data;

    // Commands with the same non-empty key that follow each other may merge (a slider dragged in the
    // inspector: one step, not one per frame).
    std::string merge_key;

    void apply(Document& doc) const override;
    void revert(Document& doc) const override;
    bool empty() const;
    // Folds `next` (applied after this) into this command. Only updates/level-field edits merge.
    bool try_merge(const LevelChange& next);
};

class CompoundCommand final : public Command {
  public:
    std::vector<std::unique_ptr<Command>> children;
    void apply(Document& doc) const override;
    void revert(Document& doc) const override;
};

} // namespace ks::editor
