// Groups (Ctrl+G, Ctrl+Shift+G, entering a group): edit_groups.h. The bookkeeping every edit goes through
// (deleted entities leave groups, new ones join the active layer) is Editor::follow_structure (editor.cpp).
#include "model/edit_groups.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace ks::editor {
namespace {
using level::EditorData;
using level::Group;

void erase_id(std::vector<int>& ids, int id) {
    std::erase(ids, id);
}

} // namespace

std::vector<int> selected_groups(const Editor& editor) {
    const Document& doc = editor.doc();
    const EditorData& data = doc.level.editor;
    if (data.groups.empty()) return {};
    std::vector<int> sorted_selection = doc.selection;
    std::sort(sorted_selection.begin(), sorted_selection.end());
    std::vector<int> out;
    for (int id : doc.selection) {
        if (id == kPlayerStartId) continue;
        const int unit = pick_unit(data, doc.open_group, id);
        if (unit == 0 || std::find(out.begin(), out.end(), unit) != out.end()) continue;
        const auto members = group_entities_deep(data, unit);
        if (std::includes(sorted_selection.begin(), sorted_selection.end(), members.begin(), members.end()))
            out.push_back(unit);
    }
    return out;
}

Result<int> group_selection(Editor& editor, std::string name) {
    const Document& doc = editor.doc();
    EditorData data = doc.level.editor;
    const int open = doc.open_group;
    if (const Group* g = data.find_group(open); g && g->has_prefab)
        return Error("Group: the entered group is a prefab instance", Location{},
                     "unlink the instance first (its members follow the prefab)");
    std::vector<int> entity_units, group_units;
    std::vector<Vec3> positions;
    for (int id : doc.selection) {
        const level::Entity* e = doc.level.find(id);
        if (!e || doc.locked.contains(id)) continue;
        positions.push_back(e->position);
        const int unit = pick_unit(data, open, id);
        auto& list = unit == 0 ? entity_units : group_units;
        if (std::find(list.begin(), list.end(), unit == 0 ? id : unit) == list.end())
            list.push_back(unit == 0 ? id : unit);
    }
    if (positions.empty()) return Error("Group: nothing is selected", Location{}, "select entities first");
    if (entity_units.empty() && group_units.size() == 1)
        return Error("Group: the selection is one group already", Location{},
                     "select more entities or groups to group them together");
    Group group;
    group.id = data.next_group_id++;
    group.name = name.empty() ? "Group " + std::to_string(group.id) : std::move(name);
    Vec3 lo = positions.front(), hi = lo;
    for (const Vec3& p : positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    group.position = doc.grid.snap_point(Vec3((lo.x + hi.x) * 0.5f, lo.y, (lo.z + hi.z) * 0.5f));
    std::sort(entity_units.begin(), entity_units.end());
    std::sort(group_units.begin(), group_units.end());
    group.entities = entity_units;
    group.groups = group_units;
    for (Group& g : data.groups) {
        for (int id : entity_units) erase_id(g.entities, id);
        for (int id : group_units) erase_id(g.groups, id);
    }
    if (Group* parent = data.find_group(open)) insert_sorted(parent->groups, group.id);
    const int new_id = group.id;
    data.groups.push_back(std::move(group));
    const auto members = group_entities_deep(data, new_id);
    editor.change_structure("Group " + std::to_string(members.size()) + " entities", std::move(data),
                            members);
    return new_id;
}

Result<void> ungroup_selection(Editor& editor) {
    const Document& doc = editor.doc();
    const std::vector<int> groups = selected_groups(editor);
    if (groups.empty())
        return Error("Ungroup: no group is selected", Location{}, "click a group's member to select it");
    EditorData data = doc.level.editor;
    for (int id : groups) {
        const Group* g = data.find_group(id);
        if (!g) continue;
        const Group dissolved = *g;
        if (Group* parent = data.find_group(parent_group_of_group(data, id))) {
            erase_id(parent->groups, id);
            for (int child : dissolved.groups) insert_sorted(parent->groups, child);
            for (int entity : dissolved.entities) insert_sorted(parent->entities, entity);
        }
        std::erase_if(data.groups, [&](const Group& other) { return other.id == id; });
    }
    editor.change_structure(groups.size() == 1 ? "Ungroup"
                                               : "Ungroup " + std::to_string(groups.size()) + " groups",
                            std::move(data), doc.selection);
    return ok();
}

Result<void> enter_group(Editor& editor, int group_id) {
    const Document& doc = editor.doc();
    if (!doc.level.editor.find_group(group_id))
        return Error("no group with id " + std::to_string(group_id), Location{},
                     "groups are listed in the outliner");
    editor.set_open_group(group_id);
    return ok();
}

void exit_group(Editor& editor) {
    const Document& doc = editor.doc();
    if (doc.open_group != 0) editor.set_open_group(parent_group_of_group(doc.level.editor, doc.open_group));
}

Result<void> rename_group(Editor& editor, int group_id, std::string name) {
    const Document& doc = editor.doc();
    EditorData data = doc.level.editor;
    Group* g = data.find_group(group_id);
    if (!g) return Error("rename: no group with id " + std::to_string(group_id));
    if (name.empty() || name.size() > 128)
        return Error("rename: a group's name has 1 to 128 characters", Location{}, "type a name");
    g->name = std::move(name);
    editor.change_structure("Rename group", std::move(data), doc.selection);
    return ok();
}

} // namespace ks::editor
