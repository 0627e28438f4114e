// Editor: the core every operation goes through: executing changes (with the editor section following
// them), the selection-wide edit, structure steps, prefab syncs, the file state and the cached issues.
#include "model/editor.h"

#include "core/log.h"
#include "model/edit_faces.h"
#include "model/groups.h"
#include "model/logic_edit.h"
#include "model/prefab.h"
#include "model/prefab_sync.h"
#include "model/recent_files.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace ks::editor {
namespace {
using level::EditorData;
using level::Entity;
using level::Group;

std::string edit_subject(const Entity& e) {
    return std::string(level::type_name(e.type())) + " " + std::to_string(e.id);
}

Frame group_frame(const Group& g) {
    return {g.position, g.yaw};
}

} // namespace

Editor::Editor() : prefabs_(default_prefab_folders()) {}

void Editor::execute(std::unique_ptr<LevelChange> change, std::vector<int> selection_after) {
    follow_entity_renames(doc_.level, *change);
    follow_structure(*change);
    change->selection_after = std::move(selection_after);
    history_.execute(doc_, std::move(change));
    follow_face_selection(doc_);
}

bool Editor::undo() {
    const bool undone = history_.undo(doc_);
    follow_face_selection(doc_);
    return undone;
}
bool Editor::redo() {
    const bool redone = history_.redo(doc_);
    follow_face_selection(doc_);
    return redone;
}

void Editor::cancel_transaction() {
    history_.cancel_transaction(doc_);
    follow_face_selection(doc_);
}

Result<void> Editor::modify_selection(std::string name, const EntityEdit& edit, std::string merge_key,
                                      const StartEdit& start_edit, const FrameEdit& frame_edit) {
    if (doc_.selection.empty())
        return Error(name + ": nothing is selected", Location{}, "select entities first");
    auto change = std::make_unique<LevelChange>();
    // Selection order (the primary first), with one id lookup table instead of a scan per entity.
    std::unordered_map<int, const Entity*> by_id;
    by_id.reserve(doc_.level.entities.size());
    for (const auto& e : doc_.level.entities) by_id.emplace(e.id, &e);
    for (int id : doc_.selection) {
        auto found = by_id.find(id);
        const Entity* current = found == by_id.end() ? nullptr : found->second;
        if (!current || doc_.locked.contains(id)) continue;
        Entity after = *current;
        auto r = edit(after);
        if (r && face_session_.texture_lock) r = keep_textures_on_world(*current, after);
        if (!r) {
            Error e = r.error();
            e.message = name + ": " + edit_subject(*current) + ": " + e.message;
            return e;
        }
        if (!(after == *current)) change->updates.push_back({*current, std::move(after)});
    }
    if (start_edit && doc_.player_start_selected()) {
        level::PlayerStart after = doc_.level.player_start;
        if (auto r = start_edit(after); !r) {
            Error e = r.error();
            e.message = name + ": player start: " + e.message;
            return e;
        }
        if (!is_finite(after.position) || !std::isfinite(after.yaw))
            return Error(name + ": the player start would leave the finite numbers");
        if (!(after == doc_.level.player_start))
            change->player_start = Change<level::PlayerStart>{doc_.level.player_start, after};
    }
    if (frame_edit && !change->updates.empty() && !doc_.level.editor.groups.empty()) {
        std::vector<int> moved;
        for (const EntityUpdate& u : change->updates) moved.push_back(u.after.id);
        std::sort(moved.begin(), moved.end());
        EditorData data = doc_.level.editor;
        for (int id : groups_wholly_in(data, moved)) frame_edit(*data.find_group(id));
        if (data != doc_.level.editor) change->editor_data = Change<EditorData>{doc_.level.editor, data};
    }
    if (change->empty()) return ok(); // nothing actually changed: no history step
    change->set_name(std::move(name));
    change->merge_key = std::move(merge_key);
    execute(std::move(change), doc_.selection);
    return ok();
}

void Editor::change_structure(std::string name, EditorData data, std::vector<int> selection_after) {
    if (data == doc_.level.editor) {
        doc_.selection = std::move(selection_after);
        return;
    }
    auto change = std::make_unique<LevelChange>();
    change->set_name(std::move(name));
    change->editor_data = Change<EditorData>{doc_.level.editor, std::move(data)};
    execute(std::move(change), std::move(selection_after));
}

void Editor::execute_prefab_sync(std::string name, const PrefabSync& sync, EditorData data,
                                 std::vector<int> selection_after) {
    auto change = std::make_unique<LevelChange>();
    change->set_name(std::move(name));
    sync.write(*change);
    if (data != doc_.level.editor)
        change->editor_data = Change<EditorData>{doc_.level.editor, std::move(data)};
    if (change->empty()) return;
    syncing_prefabs_ = true;
    execute(std::move(change), std::move(selection_after));
    syncing_prefabs_ = false;
}

void Editor::follow_structure(LevelChange& change) const {
    const EditorData& before = doc_.level.editor;
    EditorData data = change.editor_data ? change.editor_data->after : before;
    if (!change.removals.empty()) {
        for (const EntityAtIndex& removed : change.removals) {
            const int id = removed.entity.id;
            for (level::Layer& layer : data.layers) std::erase(layer.entities, id);
            std::erase(data.hidden, id);
            std::erase(data.locked, id);
            for (Group& g : data.groups) {
                std::erase(g.entities, id);
                if (g.has_prefab) std::replace(g.prefab.members.begin(), g.prefab.members.end(), id, 0);
            }
        }
        prune_empty_groups(data);
    }
    const int active = data.active_layer;
    if (active > 0 && active < static_cast<int>(data.layers.size()) && !change.insertions.empty()) {
        const auto table = layer_table(data);
        for (const EntityAtIndex& inserted : change.insertions)
            if (!table.contains(inserted.entity.id))
                insert_sorted(data.layers[static_cast<size_t>(active)].entities, inserted.entity.id);
    }
    bool any_prefab = false;
    for (const Group& g : data.groups) any_prefab |= g.has_prefab;
    if (any_prefab && !syncing_prefabs_ && !change.updates.empty()) {
        for (const EntityUpdate& update : change.updates) {
            const int id = update.after.id;
            for (Group& g : data.groups) {
                if (!g.has_prefab) continue;
                auto at = std::find(g.prefab.members.begin(), g.prefab.members.end(), id);
                if (at == g.prefab.members.end()) continue;
                const Group* old = before.find_group(g.id);
                const Frame frame_before = old ? group_frame(*old) : group_frame(g);
                auto& overrides = g.prefab.overrides[static_cast<size_t>(at - g.prefab.members.begin())];
                for (std::string& field : differing_fields(entity_into_frame(update.before, frame_before),
                                                           entity_into_frame(update.after, group_frame(g))))
                    if (std::find(overrides.begin(), overrides.end(), field) == overrides.end())
                        overrides.push_back(std::move(field));
                std::sort(overrides.begin(), overrides.end());
            }
        }
    }
    if (data != before)
        change.editor_data = Change<EditorData>{before, std::move(data)};
    else
        change.editor_data.reset();
}

const std::vector<Issue>& Editor::issues() {
    return validation_.issues(doc_.level, prefabs_, revision(), history_.in_transaction());
}

void Editor::replace_level(level::Level level, std::filesystem::path path, DiskFingerprint disk) {
    doc_ = Document{std::move(level), {}, {}, {}, doc_.grid, 0, {}};
    refresh_view_sets(doc_);
    history_.clear();
    path_ = std::move(path);
    disk_ = disk;
    recovery_.reset();
    ++reloads_;
}

void Editor::mark_saved(std::filesystem::path path, DiskFingerprint disk) {
    disk_ = disk;
    path_ = std::move(path);
    history_.mark_saved();
    ++reloads_; // the title changes even when the level did not
}

void Editor::remember_recent(const std::filesystem::path& path) {
    if (!recent_) return;
    recent_->add(path);
    if (auto r = recent_->save(); !r) log::warn("could not save the recent files list: ", r.error().str());
}

} // namespace ks::editor
