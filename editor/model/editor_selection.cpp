// Editor: selection (view state, not history steps), and hiding and locking one entity (saved steps).
#include "model/editor.h"

#include <unordered_set>

namespace ks::editor {
namespace {
void apply_mode(std::vector<int>& selection, const std::vector<int>& ids, SelectMode mode) {
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
}
} // namespace

Editor::Editor() : prefabs_(default_prefab_folders()) {}

Result<void> Editor::select(const std::vector<int>& ids, SelectMode mode) {
    for (int id : ids) {
        if (id == kPlayerStartId) continue; // always there, never locked
        if (!doc_.level.find(id))
            return Error("no entity with id " + std::to_string(id), Location{path_.string()},
                         "ids are listed in the outliner; the level's highest is " +
                             std::to_string(doc_.level.next_id - 1));
        if (doc_.locked.contains(id))
            return Error("entity " + std::to_string(id) + " is locked", Location{path_.string()},
                         "unlock it in the outliner to select it");
    }
    apply_mode(doc_.selection, ids, mode);
    return ok();
}

int Editor::select_where(const std::function<bool(const level::Entity&)>& accept, SelectMode mode) {
    std::vector<int> ids;
    for (const auto& e : doc_.level.entities)
        if (!doc_.hidden.contains(e.id) && !doc_.locked.contains(e.id) && accept(e)) ids.push_back(e.id);
    apply_mode(doc_.selection, ids, mode);
    return static_cast<int>(ids.size());
}

int Editor::select_in_box(const geometry::Aabb& box, SelectMode mode) {
    return select_where([&](const level::Entity& e) { return entity_obb(e).aabb().overlaps(box); }, mode);
}

int Editor::select_all_of_type(level::EntityType type, SelectMode mode) {
    return select_where([&](const level::Entity& e) { return e.type() == type; }, mode);
}

int Editor::select_all() {
    return select_where([](const level::Entity&) { return true; }, SelectMode::Replace);
}

std::vector<const level::Entity*> Editor::selected_entities() const {
    std::vector<const level::Entity*> out;
    for (int id : doc_.selection)
        if (const auto* e = doc_.level.find(id)) out.push_back(e);
    return out;
}

Result<void> Editor::set_hidden(int id, bool hidden) {
    return set_entity_flag(id, &level::EditorData::hidden, hidden, hidden ? "Hide" : "Show");
}

Result<void> Editor::set_locked(int id, bool locked) {
    return set_entity_flag(id, &level::EditorData::locked, locked, locked ? "Lock" : "Unlock");
}

Result<void> Editor::set_entity_flag(int id, std::vector<int> level::EditorData::*list, bool on,
                                     const char* what) {
    const level::Entity* e = doc_.level.find(id);
    if (!e) return Error(std::string(what) + ": no entity with id " + std::to_string(id));
    level::EditorData data = doc_.level.editor;
    if (on)
        insert_sorted(data.*list, id);
    else
        std::erase(data.*list, id);
    std::vector<int> selection = doc_.selection;
    if (on && list == &level::EditorData::locked) std::erase(selection, id); // a locked entity is not picked
    std::string name =
        std::string(what) + " " + std::string(level::type_name(e->type())) + " " + std::to_string(id);
    change_structure(std::move(name), std::move(data), std::move(selection));
    return ok();
}

int Editor::select_picked_where(const std::function<bool(const level::Entity&)>& accept, SelectMode mode) {
    std::vector<int> ids;
    std::unordered_set<int> taken; // a group's members come once, however many of them the box holds
    int accepted = 0;
    for (const auto& e : doc_.level.entities) {
        if (doc_.hidden.contains(e.id) || doc_.locked.contains(e.id) || !accept(e)) continue;
        ++accepted;
        if (taken.contains(e.id)) continue;
        for (int id : pick_unit_entities(doc_.level.editor, doc_.open_group, e.id))
            if (!doc_.locked.contains(id) && taken.insert(id).second) ids.push_back(id);
    }
    apply_mode(doc_.selection, ids, mode);
    return accepted;
}

Result<void> Editor::select_picked(int entity_id, SelectMode mode) {
    if (!doc_.level.find(entity_id)) return Error("no entity with id " + std::to_string(entity_id));
    const level::EditorData& data = doc_.level.editor;
    if (doc_.open_group != 0) {
        const int parent = parent_group_of_entity(data, entity_id);
        if (parent == 0 || !group_within(data, parent, doc_.open_group)) doc_.open_group = 0;
    }
    std::vector<int> ids;
    for (int id : pick_unit_entities(data, doc_.open_group, entity_id))
        if (!doc_.locked.contains(id)) ids.push_back(id);
    if (ids.empty()) return Error("entity " + std::to_string(entity_id) + " is locked");
    apply_mode(doc_.selection, ids, mode);
    return ok();
}

} // namespace ks::editor
