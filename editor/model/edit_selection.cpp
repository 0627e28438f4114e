// Selection (view state, not history steps): edit_selection.h.
#include "model/edit_selection.h"

#include "model/bounds.h"
#include "model/groups.h"

#include <algorithm>
#include <unordered_set>

namespace ks::editor {
namespace {
std::vector<int> with_mode(std::vector<int> selection, const std::vector<int>& ids, SelectMode mode) {
    auto has = [&](int id) { return std::find(selection.begin(), selection.end(), id) != selection.end(); };
    switch (mode) {
    case SelectMode::Replace:
        selection.clear();
        for (int id : ids)
            if (!has(id)) selection.push_back(id);
        break;
    case SelectMode::Add:
        for (int id : ids)
            if (!has(id)) selection.push_back(id);
        break;
    case SelectMode::Toggle:
        for (int id : ids) {
            if (has(id))
                std::erase(selection, id);
            else
                selection.push_back(id);
        }
        break;
    case SelectMode::Remove:
        for (int id : ids) std::erase(selection, id);
        break;
    }
    return selection;
}

void apply_mode(Editor& editor, const std::vector<int>& ids, SelectMode mode) {
    editor.set_selection(with_mode(editor.doc().selection, ids, mode));
}
} // namespace

Result<void> select(Editor& editor, const std::vector<int>& ids, SelectMode mode) {
    const Document& doc = editor.doc();
    for (int id : ids) {
        if (id == kPlayerStartId) continue; // always there, never locked
        if (!doc.level.find(id))
            return Error("no entity with id " + std::to_string(id), Location{editor.file_path().string()},
                         "ids are listed in the outliner; the level's highest is " +
                             std::to_string(doc.level.next_id - 1));
        if (doc.locked.contains(id))
            return Error("entity " + std::to_string(id) + " is locked", Location{editor.file_path().string()},
                         "unlock it in the outliner to select it");
    }
    apply_mode(editor, ids, mode);
    return ok();
}

int select_where(Editor& editor, const std::function<bool(const level::Entity&)>& accept, SelectMode mode) {
    const Document& doc = editor.doc();
    std::vector<int> ids;
    for (const auto& e : doc.level.entities)
        if (!doc.hidden.contains(e.id) && !doc.locked.contains(e.id) && accept(e)) ids.push_back(e.id);
    apply_mode(editor, ids, mode);
    return static_cast<int>(ids.size());
}

int select_in_box(Editor& editor, const geometry::Aabb& box, SelectMode mode) {
    return select_where(
        editor, [&](const level::Entity& e) { return entity_obb(e).aabb().overlaps(box); }, mode);
}

int select_all_of_type(Editor& editor, level::EntityType type, SelectMode mode) {
    return select_where(
        editor, [&](const level::Entity& e) { return e.type() == type; }, mode);
}

int select_all(Editor& editor) {
    return select_where(
        editor, [](const level::Entity&) { return true; }, SelectMode::Replace);
}

std::vector<const level::Entity*> selected_entities(const Editor& editor) {
    std::vector<const level::Entity*> out;
    for (int id : editor.doc().selection)
        if (const auto* e = editor.level().find(id)) out.push_back(e);
    return out;
}

int select_picked_where(Editor& editor, const std::function<bool(const level::Entity&)>& accept,
                        SelectMode mode) {
    const Document& doc = editor.doc();
    std::vector<int> ids;
    std::unordered_set<int> taken; // a group's members come once, however many of them the box holds
    int accepted = 0;
    for (const auto& e : doc.level.entities) {
        if (doc.hidden.contains(e.id) || doc.locked.contains(e.id) || !accept(e)) continue;
        ++accepted;
        if (taken.contains(e.id)) continue;
        for (int id : pick_unit_entities(doc.level.editor, doc.open_group, e.id))
            if (!doc.locked.contains(id) && taken.insert(id).second) ids.push_back(id);
    }
    apply_mode(editor, ids, mode);
    return accepted;
}

Result<void> select_picked(Editor& editor, int entity_id, SelectMode mode) {
    const Document& doc = editor.doc();
    if (!doc.level.find(entity_id)) return Error("no entity with id " + std::to_string(entity_id));
    const level::EditorData& data = doc.level.editor;
    if (doc.open_group != 0) {
        const int parent = parent_group_of_entity(data, entity_id);
        if (parent == 0 || !group_within(data, parent, doc.open_group)) editor.set_open_group(0);
    }
    std::vector<int> ids;
    for (int id : pick_unit_entities(data, doc.open_group, entity_id))
        if (!doc.locked.contains(id)) ids.push_back(id);
    if (ids.empty()) return Error("entity " + std::to_string(entity_id) + " is locked");
    apply_mode(editor, ids, mode);
    return ok();
}

Result<void> select_issue(Editor& editor, const Issue& issue) {
    if (issue.entity_id == 0)
        return issue.rule == Rule::PlayerStart ? select(editor, {kPlayerStartId}) : ok();
    return select(editor, {issue.entity_id});
}

} // namespace ks::editor
