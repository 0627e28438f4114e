// Editor: groups (Ctrl+G, Ctrl+Shift+G, entering a group) and the editor section's bookkeeping that every
// edit goes through (follow_structure: deleted entities leave layers and groups, new ones join the active
// layer, edited prefab members record their overrides).
#include "model/editor.h"

#include "model/prefab.h"

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

Frame frame_of(const Group& g) {
    return {g.position, g.yaw};
}

} // namespace

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

void Editor::follow_structure(LevelChange& change) const {
    const EditorData& before = doc_.level.editor;
    EditorData data = change.editor_data ? change.editor_data->after : before;
    if (!change.removals.empty()) {
        for (const EntityAtIndex& removed : change.removals) {
            const int id = removed.entity.id;
            for (level::Layer& layer : data.layers) erase_id(layer.entities, id);
            erase_id(data.hidden, id);
            erase_id(data.locked, id);
            for (Group& g : data.groups) {
                erase_id(g.entities, id);
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
                const Frame frame_before = old ? frame_of(*old) : frame_of(g);
                auto& overrides = g.prefab.overrides[static_cast<size_t>(at - g.prefab.members.begin())];
                for (std::string& field : differing_fields(entity_into_frame(update.before, frame_before),
                                                           entity_into_frame(update.after, frame_of(g))))
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

std::vector<int> Editor::selected_groups() const {
    const EditorData& data = doc_.level.editor;
    if (data.groups.empty()) return {};
    std::vector<int> sorted_selection = doc_.selection;
    std::sort(sorted_selection.begin(), sorted_selection.end());
    std::vector<int> out;
    for (int id : doc_.selection) {
        if (id == kPlayerStartId) continue;
        const int unit = pick_unit(data, doc_.open_group, id);
        if (unit == 0 || std::find(out.begin(), out.end(), unit) != out.end()) continue;
        const auto members = group_entities_deep(data, unit);
        if (std::includes(sorted_selection.begin(), sorted_selection.end(), members.begin(), members.end()))
            out.push_back(unit);
    }
    return out;
}

Result<int> Editor::group_selection(std::string name) {
    EditorData data = doc_.level.editor;
    const int open = doc_.open_group;
    if (const Group* g = data.find_group(open); g && g->has_prefab)
        return Error("Group: the entered group is a prefab instance", Location{},
                     "unlink the instance first (its members follow the prefab)");
    std::vector<int> entity_units, group_units;
    std::vector<Vec3> positions;
    for (int id : doc_.selection) {
        const level::Entity* e = doc_.level.find(id);
        if (!e || doc_.locked.contains(id)) continue;
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
    group.position = doc_.grid.snap_point(Vec3((lo.x + hi.x) * 0.5f, lo.y, (lo.z + hi.z) * 0.5f));
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
    change_structure("Group " + std::to_string(members.size()) + " entities", std::move(data), members);
    return new_id;
}

Result<void> Editor::ungroup_selection() {
    const std::vector<int> groups = selected_groups();
    if (groups.empty())
        return Error("Ungroup: no group is selected", Location{}, "click a group's member to select it");
    EditorData data = doc_.level.editor;
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
    change_structure(groups.size() == 1 ? "Ungroup" : "Ungroup " + std::to_string(groups.size()) + " groups",
                     std::move(data), doc_.selection);
    return ok();
}

Result<void> Editor::enter_group(int group_id) {
    if (!doc_.level.editor.find_group(group_id))
        return Error("no group with id " + std::to_string(group_id), Location{},
                     "groups are listed in the outliner");
    doc_.open_group = group_id;
    return ok();
}

void Editor::exit_group() {
    if (doc_.open_group != 0) doc_.open_group = parent_group_of_group(doc_.level.editor, doc_.open_group);
}

Result<void> Editor::rename_group(int group_id, std::string name) {
    EditorData data = doc_.level.editor;
    Group* g = data.find_group(group_id);
    if (!g) return Error("rename: no group with id " + std::to_string(group_id));
    if (name.empty() || name.size() > 128)
        return Error("rename: a group's name has 1 to 128 characters", Location{}, "type a name");
    g->name = std::move(name);
    change_structure("Rename group", std::move(data), doc_.selection);
    return ok();
}

} // namespace ks::editor
