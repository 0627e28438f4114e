// Editor: selection, visibility and locks (view state, not history steps).
#include "model/editor.h"

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

Editor::Editor() = default;

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

void Editor::set_hidden(int id, bool hidden) {
    if (hidden)
        doc_.hidden.insert(id);
    else
        doc_.hidden.erase(id);
}

void Editor::set_locked(int id, bool locked) {
    if (locked) {
        doc_.locked.insert(id);
        std::erase(doc_.selection, id);
    } else {
        doc_.locked.erase(id);
    }
}

} // namespace ks::editor
