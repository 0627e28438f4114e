// Prefabs in the level: edit_prefabs.h. Each edit is one step through Editor::execute_prefab_sync (members
// follow their prefab, recording no overrides) or Editor::change_structure.
#include "model/edit_prefabs.h"

#include "model/groups.h"
#include "model/prefab.h"
#include "model/prefab_sync.h"
#include "model/rotation.h"

#include <algorithm>
#include <map>

namespace ks::editor {
namespace {
using level::EditorData;
using level::Group;

Error instance_error(const std::string& what, int group_id) {
    return Error(what + ": group " + std::to_string(group_id) + " is not a prefab instance", Location{},
                 "select a placed prefab (its outliner row shows the prefab's name)");
}

} // namespace

int prefab_instance_of(const Editor& editor, int entity_id) {
    const Document& doc = editor.doc();
    const Group* g = doc.level.editor.find_group(parent_group_of_entity(doc.level.editor, entity_id));
    return g && g->has_prefab ? g->id : 0;
}

Result<std::filesystem::path> save_prefab(Editor& editor, const std::string& name, std::string title,
                                          bool replace) {
    const Document& doc = editor.doc();
    if (std::string problem = prefab_name_problem(name); !problem.empty())
        return Error("Save as prefab: " + problem, Location{}, "choose another name");
    std::vector<const level::Entity*> chosen;
    for (const level::Entity& e : doc.level.entities)
        if (doc.is_selected(e.id) && !doc.locked.contains(e.id)) chosen.push_back(&e);
    if (chosen.empty())
        return Error("Save as prefab: nothing is selected", Location{}, "select entities first");
    editor.prefabs().rescan();
    if (editor.prefabs().find(name) && !replace)
        return Error("Save as prefab: a prefab named '" + name + "' exists", Location{},
                     "choose another name, or replace it (its instances follow)");
    Vec3 lo = chosen.front()->position, hi = lo;
    for (const auto* e : chosen) lo = glm::min(lo, e->position), hi = glm::max(hi, e->position);
    const Frame frame{doc.grid.snap_point(Vec3((lo.x + hi.x) * 0.5f, lo.y, (lo.z + hi.z) * 0.5f)), 0.0f};
    Prefab prefab{name, title.empty() ? name : std::move(title), {}};
    Group instance;
    instance.name = prefab.title;
    instance.position = frame.position;
    instance.has_prefab = true;
    instance.prefab.prefab = name;
    for (const auto* e : chosen) {
        level::Entity local = entity_into_frame(*e, frame);
        local.id = static_cast<int>(prefab.entities.size()) + 1;
        prefab.entities.push_back(std::move(local));
        instance.entities.push_back(e->id);
        instance.prefab.members.push_back(e->id);
        instance.prefab.overrides.emplace_back();
    }
    std::sort(instance.entities.begin(), instance.entities.end());
    auto path = editor.prefabs().save(prefab);
    if (!path) return path.error();
    EditorData data = doc.level.editor;
    for (Group& g : data.groups)
        for (int id : instance.entities) {
            std::erase(g.entities, id);
            if (g.has_prefab) std::replace(g.prefab.members.begin(), g.prefab.members.end(), id, 0);
        }
    prune_empty_groups(data);
    instance.id = data.next_group_id++;
    if (Group* parent = data.find_group(doc.open_group); parent && !parent->has_prefab)
        insert_sorted(parent->groups, instance.id);
    data.groups.push_back(instance);
    PrefabSync sync(doc.level); // a replaced prefab's other instances follow it
    for (Group& g : data.groups)
        if (g.has_prefab && g.prefab.prefab == name && g.id != instance.id)
            if (auto r = sync.sync(g, prefab); !r) return r.error();
    editor.execute_prefab_sync("Save prefab " + name, sync, std::move(data), doc.selection);
    return *path;
}

Result<int> place_prefab(Editor& editor, const std::string& name, Vec3 position, float yaw_degrees) {
    const Document& doc = editor.doc();
    if (!is_finite(position) || !std::isfinite(yaw_degrees))
        return Error("place prefab: position and yaw must be finite numbers");
    editor.prefabs().rescan();
    auto prefab = editor.prefabs().get(name);
    if (!prefab)
        return Error("place prefab: " + prefab.error().message, prefab.error().where, prefab.error().hint);
    EditorData data = doc.level.editor;
    Group instance;
    instance.id = data.next_group_id++;
    instance.name = prefab->title;
    instance.position = doc.grid.snap_point(position);
    instance.yaw = wrap_degrees(doc.grid.snap_angle(yaw_degrees));
    instance.has_prefab = true;
    instance.prefab.prefab = name;
    PrefabSync sync(doc.level);
    if (auto r = sync.sync(instance, *prefab); !r) return r.error();
    const int id = instance.id;
    if (Group* parent = data.find_group(doc.open_group); parent && !parent->has_prefab)
        insert_sorted(parent->groups, id);
    data.groups.push_back(std::move(instance));
    editor.execute_prefab_sync("Place prefab " + name, sync, std::move(data), sync.added_ids());
    return id;
}

Result<std::filesystem::path> apply_instance_to_prefab(Editor& editor, int group_id) {
    const Document& doc = editor.doc();
    const Group* source = doc.level.editor.find_group(group_id);
    if (!source || !source->has_prefab) return instance_error("Apply to prefab", group_id);
    const std::string name = source->prefab.prefab;
    editor.prefabs().rescan();
    const auto old = editor.prefabs().get(name);
    const Frame frame{source->position, source->yaw};
    // Instance names back to the prefab's, so links inside the prefab keep naming its own entities.
    std::unordered_map<std::string, std::string> back;
    std::vector<size_t> kept;
    Prefab prefab{name, old ? old->title : name, {}};
    for (size_t i = 0; i < source->prefab.members.size(); ++i) {
        const level::Entity* e = doc.level.find(source->prefab.members[i]);
        if (!e) continue;
        kept.push_back(i);
        const bool had = old && i < old->entities.size();
        if (had && !e->name.empty()) back.emplace(e->name, old->entities[i].name);
    }
    for (size_t i : kept) {
        const level::Entity& e = *doc.level.find(source->prefab.members[i]);
        level::Entity local = entity_into_frame(e, frame);
        local.id = static_cast<int>(prefab.entities.size()) + 1;
        if (old && i < old->entities.size()) local.name = old->entities[i].name;
        local.links = renamed_links(e.links, back);
        prefab.entities.push_back(std::move(local));
    }
    if (prefab.entities.empty())
        return Error("Apply to prefab: the instance has no members left", Location{},
                     "delete the instance instead, or unlink it");
    auto path = editor.prefabs().save(prefab);
    if (!path) return path.error();
    EditorData data = doc.level.editor;
    PrefabSync sync(doc.level);
    for (Group& g : data.groups) {
        if (!g.has_prefab || g.prefab.prefab != name) continue;
        level::PrefabLink relinked{name, {}, {}};
        for (size_t i : kept) {
            const bool has = i < g.prefab.members.size();
            relinked.members.push_back(has ? g.prefab.members[i] : 0);
            relinked.overrides.push_back(has && g.id != group_id ? g.prefab.overrides[i]
                                                                 : std::vector<std::string>{});
        }
        // Members of indices the applied instance had deleted leave the prefab, and every instance.
        for (size_t i = 0; i < g.prefab.members.size(); ++i)
            if (std::find(kept.begin(), kept.end(), i) == kept.end() && g.prefab.members[i] != 0)
                relinked.members.push_back(g.prefab.members[i]), relinked.overrides.emplace_back();
        g.prefab = std::move(relinked);
        if (auto r = sync.sync(g, prefab); !r) return r.error();
    }
    editor.execute_prefab_sync("Apply to prefab " + name, sync, std::move(data), doc.selection);
    return *path;
}

Result<int> update_prefab_instances(Editor& editor) {
    const Document& doc = editor.doc();
    editor.prefabs().rescan();
    EditorData data = doc.level.editor;
    PrefabSync sync(doc.level);
    std::vector<std::string> names;
    for (Group& g : data.groups) {
        if (!g.has_prefab) continue;
        auto prefab = editor.prefabs().get(g.prefab.prefab);
        if (!prefab) continue; // a missing prefab leaves its instances as they are (validation reports it)
        const int before = sync.changed_count();
        if (auto r = sync.sync(g, *prefab); !r) return r.error();
        if (sync.changed_count() != before &&
            std::find(names.begin(), names.end(), g.prefab.prefab) == names.end())
            names.push_back(g.prefab.prefab);
    }
    std::string step = "Update prefab instances";
    for (size_t i = 0; i < names.size(); ++i) step += (i ? ", " : " (") + names[i];
    editor.execute_prefab_sync(names.empty() ? step : step + ")", sync, std::move(data), doc.selection);
    return sync.changed_count();
}

Result<void> revert_prefab_overrides(Editor& editor, int group_id, int entity_id, std::string field) {
    const Document& doc = editor.doc();
    EditorData data = doc.level.editor;
    Group* g = data.find_group(group_id);
    if (!g || !g->has_prefab) return instance_error("Revert to prefab", group_id);
    editor.prefabs().rescan();
    auto prefab = editor.prefabs().get(g->prefab.prefab);
    if (!prefab)
        return Error("Revert to prefab: " + prefab.error().message, prefab.error().where,
                     prefab.error().hint);
    bool any = false;
    for (size_t i = 0; i < g->prefab.members.size(); ++i) {
        if (entity_id != 0 && g->prefab.members[i] != entity_id) continue;
        auto& list = g->prefab.overrides[i];
        any |= field.empty() ? !list.empty() : std::find(list.begin(), list.end(), field) != list.end();
        if (field.empty())
            list.clear();
        else
            std::erase(list, field);
    }
    if (!any)
        return Error("Revert to prefab: nothing to revert", Location{},
                     "only fields the instance changed (shown in the inspector) can be reverted");
    PrefabSync sync(doc.level);
    if (auto r = sync.sync(*g, *prefab); !r) return r.error();
    std::string step = "Revert to prefab " + g->prefab.prefab;
    editor.execute_prefab_sync(std::move(step), sync, std::move(data), doc.selection);
    return ok();
}

Result<void> unlink_prefab(Editor& editor, int group_id) {
    const Document& doc = editor.doc();
    EditorData data = doc.level.editor;
    Group* g = data.find_group(group_id);
    if (!g || !g->has_prefab) return instance_error("Unlink", group_id);
    const std::string name = g->prefab.prefab;
    g->has_prefab = false;
    g->prefab = {};
    editor.change_structure("Unlink prefab " + name, std::move(data), doc.selection);
    return ok();
}

} // namespace ks::editor
