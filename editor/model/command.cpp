#include "model/command.h"

#include "model/groups.h"

#include <algorithm>
#include <cassert>
#include <unordered_map>

namespace ks::editor {
namespace {
// Writes before- or after-copies of updated entities. Large edits (a drag of hundreds of entities) look ids
// up through one index instead of a scan per entity.
void write_updates(Document& doc, const std::vector<EntityUpdate>& updates, bool after) {
    auto& entities = doc.level.entities;
    auto value = [&](size_t i) -> const level::Entity& {
        return after ? updates[i].after : updates[i].before;
    };
    if (updates.size() <= 16) {
        for (size_t i = 0; i < updates.size(); ++i) {
            level::Entity* e = doc.level.find(value(i).id);
            assert(e && "an update refers to an entity that is not in the level");
            if (e) *e = value(i);
        }
        return;
    }
    std::unordered_map<int, size_t> index;
    index.reserve(entities.size());
    for (size_t i = 0; i < entities.size(); ++i) index.emplace(entities[i].id, i);
    for (size_t i = 0; i < updates.size(); ++i) {
        auto it = index.find(value(i).id);
        assert(it != index.end() && "an update refers to an entity that is not in the level");
        if (it != index.end()) entities[it->second] = value(i);
    }
}

template <class T>
void merge_field(std::optional<Change<T>>& into, const std::optional<Change<T>>& next) {
    if (!next) return;
    if (into)
        into->after = next->after;
    else
        into = next;
}
} // namespace

void LevelChange::apply(Document& doc) const {
    auto& entities = doc.level.entities;
    write_updates(doc, updates, true);
    for (auto it = removals.rbegin(); it != removals.rend(); ++it) {
        assert(it->index < entities.size() && entities[it->index].id == it->entity.id);
        entities.erase(entities.begin() + static_cast<std::ptrdiff_t>(it->index));
    }
    for (const auto& ins : insertions)
        entities.insert(entities.begin() + static_cast<std::ptrdiff_t>(ins.index), ins.entity);
    if (level_name) doc.level.name = level_name->after;
    if (settings) doc.level.settings = settings->after;
    if (player_start) doc.level.player_start = player_start->after;
    if (next_id) doc.level.next_id = next_id->after;
    if (level_links) doc.level.links = level_links->after;
    if (objectives) doc.level.objectives = objectives->after;
    if (editor_data) doc.level.editor = editor_data->after;
    doc.selection = selection_after;
    if (editor_data) refresh_view_sets(doc);
}

void LevelChange::revert(Document& doc) const {
    auto& entities = doc.level.entities;
    if (level_name) doc.level.name = level_name->before;
    if (settings) doc.level.settings = settings->before;
    if (player_start) doc.level.player_start = player_start->before;
    if (next_id) doc.level.next_id = next_id->before;
    if (level_links) doc.level.links = level_links->before;
    if (objectives) doc.level.objectives = objectives->before;
    if (editor_data) doc.level.editor = editor_data->before;
    for (auto it = insertions.rbegin(); it != insertions.rend(); ++it) {
        assert(it->index < entities.size() && entities[it->index].id == it->entity.id);
        entities.erase(entities.begin() + static_cast<std::ptrdiff_t>(it->index));
    }
    for (const auto& rem : removals)
        entities.insert(entities.begin() + static_cast<std::ptrdiff_t>(rem.index), rem.entity);
    write_updates(doc, updates, false); // ids are distinct, so order does not matter
    doc.selection = selection_before;
    if (editor_data) refresh_view_sets(doc);
}

bool LevelChange::empty() const {
    return updates.empty() && removals.empty() && insertions.empty() && !level_name && !settings &&
           !player_start && !next_id && !level_links && !objectives && !editor_data;
}

bool LevelChange::try_merge(const LevelChange& next) {
    if (merge_key.empty() || merge_key != next.merge_key) return false;
    if (!removals.empty() || !insertions.empty() || !next.removals.empty() || !next.insertions.empty())
        return false;
    for (const auto& u : next.updates) {
        auto it = std::find_if(updates.begin(), updates.end(),
                               [&](const EntityUpdate& mine) { return mine.after.id == u.after.id; });
        if (it != updates.end())
            it->after = u.after;
        else
            updates.push_back(u);
    }
    merge_field(level_name, next.level_name);
    merge_field(settings, next.settings);
    merge_field(player_start, next.player_start);
    merge_field(next_id, next.next_id);
    merge_field(level_links, next.level_links);
    merge_field(objectives, next.objectives);
    merge_field(editor_data, next.editor_data);
    selection_after = next.selection_after;
    return true;
}

void CompoundCommand::apply(Document& doc) const {
    for (const auto& c : children) c->apply(doc);
}

void CompoundCommand::revert(Document& doc) const {
    for (auto it = children.rbegin(); it != children.rend(); ++it) (*it)->revert(doc);
}

} // namespace ks::editor
