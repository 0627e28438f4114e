// Editor: prefabs (prefab.h). Saving a selection as a prefab, placing linked instances, applying an
// instance back to its prefab, following prefab files that changed, reverting overrides and unlinking;
// each one undoable step (the prefab file a save or an apply writes stays written).
#include "model/editor.h"

#include "model/prefab_sync.h"

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

// While a prefab sync runs, members change because the prefab did: follow_structure records no overrides.
struct Editor::SyncScope {
    explicit SyncScope(Editor& e) : editor(e) { editor.syncing_prefabs_ = true; }
    ~SyncScope() { editor.syncing_prefabs_ = false; }
    Editor& editor;
};

int Editor::prefab_instance_of(int entity_id) const {
    const Group* g = doc_.level.editor.find_group(parent_group_of_entity(doc_.level.editor, entity_id));
    return g && g->has_prefab ? g->id : 0;
}

void Editor::execute_sync(std::string name, const PrefabSync& sync, EditorData data,
                          std::vector<int> selection_after) {
    auto change = std::make_unique<LevelChange>();
    change->set_name(std::move(name));
    sync.write(*change);
    if (data != doc_.level.editor)
        change->editor_data = Change<EditorData>{doc_.level.editor, std::move(data)};
    if (change->empty()) return;
    SyncScope scope(*this);
    execute(std::move(change), std::move(selection_after));
}

Result<std::filesystem::path> Editor::save_prefab(const std::string& name, std::string title, bool replace) {
    if (std::string problem = prefab_name_problem(name); !problem.empty())
        return Error("Save as prefab: " + problem, Location{}, "choose another name");
    std::vector<const level::Entity*> chosen;
    for (const level::Entity& e : doc_.level.entities)
        if (doc_.is_selected(e.id) && !doc_.locked.contains(e.id)) chosen.push_back(&e);
    if (chosen.empty())
        return Error("Save as prefab: nothing is selected", Location{}, "select entities first");
    prefabs_.rescan();
    if (prefabs_.find(name) && !replace)
        return Error("Save as prefab: a prefab named '" + name + "' exists", Location{},
                     "choose another name, or replace it (its instances follow)");
    Vec3 lo = chosen.front()->position, hi = lo;
    for (const auto* e : chosen) lo = glm::min(lo, e->position), hi = glm::max(hi, e->position);
    const Frame frame{doc_.grid.snap_point(Vec3((lo.x + hi.x) * 0.5f, lo.y, (lo.z + hi.z) * 0.5f)), 0.0f};
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
    auto path = prefabs_.save(prefab);
    if (!path) return path.error();
    EditorData data = doc_.level.editor;
    for (Group& g : data.groups)
        for (int id : instance.entities) {
            std::erase(g.entities, id);
            if (g.has_prefab) std::replace(g.prefab.members.begin(), g.prefab.members.end(), id, 0);
        }
    prune_empty_groups(data);
    instance.id = data.next_group_id++;
    if (Group* parent = data.find_group(doc_.open_group); parent && !parent->has_prefab)
        insert_sorted(parent->groups, instance.id);
    data.groups.push_back(instance);
    PrefabSync sync(doc_.level); // a replaced prefab's other instances follow it
    for (Group& g : data.groups)
        if (g.has_prefab && g.prefab.prefab == name && g.id != instance.id)
            if (auto r = sync.sync(g, prefab); !r) return r.error();
    execute_sync("Save prefab " + name, sync, std::move(data), doc_.selection);
    return *path;
}

Result<int> Editor::place_prefab(const std::string& name, Vec3 position, float yaw_degrees) {
    if (!is_finite(position) || !std::isfinite(yaw_degrees))
        return Error("place prefab: position and yaw must be finite numbers");
    prefabs_.rescan();
    auto prefab = prefabs_.get(name);
    if (!prefab)
        return Error("place prefab: " + prefab.error().message, prefab.error().where, prefab.error().hint);
    EditorData data = doc_.level.editor;
    Group instance;
    instance.id = data.next_group_id++;
    instance.name = prefab->title;
    instance.position = doc_.grid.snap_point(position);
    instance.yaw = wrap_degrees(doc_.grid.snap_angle(yaw_degrees));
    instance.has_prefab = true;
    instance.prefab.prefab = name;
    PrefabSync sync(doc_.level);
    if (auto r = sync.sync(instance, *prefab); !r) return r.error();
    const int id = instance.id;
    if (Group* parent = data.find_group(doc_.open_group); parent && !parent->has_prefab)
        insert_sorted(parent->groups, id);
    data.groups.push_back(std::move(instance));
    execute_sync("Place prefab " + name, sync, std::move(data), sync.added_ids());
    return id;
}

Result<std::filesystem::path> Editor::apply_instance_to_prefab(int group_id) {
    const Group* source = doc_.level.editor.find_group(group_id);
    if (!source || !source->has_prefab) return instance_error("Apply to prefab", group_id);
    const std::string name = source->prefab.prefab;
    prefabs_.rescan();
    const auto old = prefabs_.get(name);
    const Frame frame{source->position, source->yaw};
    // Instance names back to the prefab's, so links inside the prefab keep naming its own entities.
    std::unordered_map<std::string, std::string> back;
    std::vector<size_t> kept;
    Prefab prefab{name, old ? old->title : name, {}};
    for (size_t i = 0; i < source->prefab.members.size(); ++i) {
        const level::Entity* e = doc_.level.find(source->prefab.members[i]);
        if (!e) continue;
        kept.push_back(i);
        const bool had = old && i < old->entities.size();
        if (had && !e->name.empty()) back.emplace(e->name, old->entities[i].name);
    }
    for (size_t i : kept) {
        const level::Entity& e = *doc_.level.find(source->prefab.members[i]);
        level::Entity local = entity_into_frame(e, frame);
        local.id = static_cast<int>(prefab.entities.size()) + 1;
        if (old && i < old->entities.size()) local.name = old->entities[i].name;
        local.links = renamed_links(e.links, back);
        prefab.entities.push_back(std::move(local));
    }
    if (prefab.entities.empty())
        return Error("Apply to prefab: the instance has no members left", Location{},
                     "delete the instance instead, or unlink it");
    auto path = prefabs_.save(prefab);
    if (!path) return path.error();
    EditorData data = doc_.level.editor;
    PrefabSync sync(doc_.level);
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
    execute_sync("Apply to prefab " + name, sync, std::move(data), doc_.selection);
    return *path;
}

Result<int> Editor::update_prefab_instances() {
    prefabs_.rescan();
    EditorData data = doc_.level.editor;
    PrefabSync sync(doc_.level);
    std::vector<std::string> names;
    for (Group& g : data.groups) {
        if (!g.has_prefab) continue;
        auto prefab = prefabs_.get(g.prefab.prefab);
        if (!prefab) continue; // a missing prefab leaves its instances as they are (validation reports it)
        const int before = sync.changed_count();
        if (auto r = sync.sync(g, *prefab); !r) return r.error();
        if (sync.changed_count() != before &&
            std::find(names.begin(), names.end(), g.prefab.prefab) == names.end())
            names.push_back(g.prefab.prefab);
    }
    std::string step = "Update prefab instances";
    for (size_t i = 0; i < names.size(); ++i) step += (i ? ", " : " (") + names[i];
    execute_sync(names.empty() ? step : step + ")", sync, std::move(data), doc_.selection);
    return sync.changed_count();
}

Result<void> Editor::revert_prefab_overrides(int group_id, int entity_id, std::string field) {
    EditorData data = doc_.level.editor;
    Group* g = data.find_group(group_id);
    if (!g || !g->has_prefab) return instance_error("Revert to prefab", group_id);
    prefabs_.rescan();
    auto prefab = prefabs_.get(g->prefab.prefab);
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
    PrefabSync sync(doc_.level);
    if (auto r = sync.sync(*g, *prefab); !r) return r.error();
    std::string step = "Revert to prefab " + g->prefab.prefab;
    execute_sync(std::move(step), sync, std::move(data), doc_.selection);
    return ok();
}

Result<void> Editor::unlink_prefab(int group_id) {
    EditorData data = doc_.level.editor;
    Group* g = data.find_group(group_id);
    if (!g || !g->has_prefab) return instance_error("Unlink", group_id);
    const std::string name = g->prefab.prefab;
    g->has_prefab = false;
    g->prefab = {};
    change_structure("Unlink prefab " + name, std::move(data), doc_.selection);
    return ok();
}

} // namespace ks::editor
