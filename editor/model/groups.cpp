#include "model/groups.h"

#include "model/document.h"

#include "level/editor_data_io.h"

#include "core/math.h"

#include <algorithm>

namespace ks::editor {

using level::EditorData;
using level::Group;

int parent_group_of_entity(const EditorData& data, int entity_id) {
    for (const Group& g : data.groups)
        if (std::find(g.entities.begin(), g.entities.end(), entity_id) != g.entities.end()) return g.id;
    return 0;
}

int parent_group_of_group(const EditorData& data, int group_id) {
    for (const Group& g : data.groups)
        if (std::find(g.groups.begin(), g.groups.end(), group_id) != g.groups.end()) return g.id;
    return 0;
}

std::vector<int> group_ancestry(const EditorData& data, int group_id) {
    std::vector<int> chain;
    // Bounded by the group count: the reader breaks cycles, and this stays finite even if one slipped in.
    for (int g = group_id; g != 0 && chain.size() <= data.groups.size(); g = parent_group_of_group(data, g))
        chain.push_back(g);
    return chain;
}

bool group_within(const EditorData& data, int group_id, int ancestor) {
    const auto chain = group_ancestry(data, group_id);
    return std::find(chain.begin(), chain.end(), ancestor) != chain.end();
}

std::vector<int> group_entities_deep(const EditorData& data, int group_id) {
    std::vector<int> out, pending{group_id};
    size_t visited = 0;
    while (!pending.empty() && visited++ <= data.groups.size()) {
        const Group* g = data.find_group(pending.back());
        pending.pop_back();
        if (!g) continue;
        out.insert(out.end(), g->entities.begin(), g->entities.end());
        pending.insert(pending.end(), g->groups.begin(), g->groups.end());
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

int pick_unit(const EditorData& data, int open_group, int entity_id) {
    const int parent = parent_group_of_entity(data, entity_id);
    if (parent == 0) return 0;
    const auto chain = group_ancestry(data, parent); // innermost first
    auto open = std::find(chain.begin(), chain.end(), open_group);
    if (open_group == 0 || open == chain.end()) return chain.back(); // the outermost group
    if (open == chain.begin()) return 0;                             // a direct member of the open group
    return *(open - 1);                                              // the open group's child holding it
}

std::vector<int> pick_unit_entities(const EditorData& data, int open_group, int entity_id) {
    const int unit = pick_unit(data, open_group, entity_id);
    return unit == 0 ? std::vector<int>{entity_id} : group_entities_deep(data, unit);
}

std::vector<int> groups_wholly_in(const EditorData& data, const std::vector<int>& sorted_ids) {
    std::vector<std::pair<size_t, int>> found; // (depth, id): outermost first
    for (const Group& g : data.groups) {
        const auto members = group_entities_deep(data, g.id);
        if (members.empty()) continue;
        if (std::includes(sorted_ids.begin(), sorted_ids.end(), members.begin(), members.end()))
            found.emplace_back(group_ancestry(data, g.id).size(), g.id);
    }
    std::sort(found.begin(), found.end());
    std::vector<int> out;
    for (const auto& [depth, id] : found) out.push_back(id);
    return out;
}

void copy_structure(EditorData& data, const std::unordered_map<int, int>& copies, Vec3 offset) {
    std::vector<int> originals;
    for (const auto& [old_id, new_id] : copies) originals.push_back(old_id);
    std::sort(originals.begin(), originals.end());
    const auto whole = groups_wholly_in(data, originals); // outermost first
    std::unordered_map<int, int> group_copies;
    for (int g : whole) group_copies[g] = data.next_group_id++;
    auto copy_of = [](const std::unordered_map<int, int>& map, int id) {
        auto it = map.find(id);
        return it == map.end() ? 0 : it->second;
    };
    std::vector<Group> made;
    std::vector<std::pair<int, int>> joins; // (parent group, new child group)
    for (int g : whole) {
        Group copy = *data.find_group(g);
        copy.id = group_copies[g];
        copy.position += offset;
        std::vector<int> entities, groups;
        for (int id : copy.entities)
            if (int c = copy_of(copies, id)) entities.push_back(c);
        for (int id : copy.groups)
            if (int c = copy_of(group_copies, id)) groups.push_back(c);
        std::sort(entities.begin(), entities.end());
        std::sort(groups.begin(), groups.end());
        copy.entities = std::move(entities);
        copy.groups = std::move(groups);
        for (int& member : copy.prefab.members) member = member == 0 ? 0 : copy_of(copies, member);
        if (const int parent = parent_group_of_group(data, g); parent && !group_copies.contains(parent))
            joins.emplace_back(parent, copy.id);
        made.push_back(std::move(copy));
    }
    for (const auto& [old_id, new_id] : copies) {
        const int parent = parent_group_of_entity(data, old_id);
        if (Group* p = data.find_group(parent); p && !group_copies.contains(parent) && !p->has_prefab)
            insert_sorted(p->entities, new_id);
        if (const int layer = layer_of(data, old_id); layer > 0)
            insert_sorted(data.layers[static_cast<size_t>(layer)].entities, new_id);
    }
    for (const auto& [parent, child] : joins) insert_sorted(data.find_group(parent)->groups, child);
    for (Group& g : made) data.groups.push_back(std::move(g));
}

nlohmann::json copied_structure(const Document& doc) {
    const EditorData& data = doc.level.editor;
    if (data.groups.empty()) return nullptr;
    std::vector<int> ids;
    for (int id : doc.selection)
        if (id != kPlayerStartId && doc.level.find(id)) ids.push_back(id);
    std::sort(ids.begin(), ids.end());
    const auto whole = groups_wholly_in(data, ids);
    if (whole.empty()) return nullptr;
    EditorData copy;
    for (int id : whole) {
        Group g = *data.find_group(id);
        std::erase_if(g.groups,
                      [&](int child) { return std::find(whole.begin(), whole.end(), child) == whole.end(); });
        copy.next_group_id = std::max(copy.next_group_id, g.id + 1);
        copy.groups.push_back(std::move(g));
    }
    return nlohmann::json(level::write_editor_data(copy));
}

void paste_structure(EditorData& data, const nlohmann::json& copied,
                     const std::unordered_map<int, int>& pasted, int open_group) {
    level::DiagnosticSink sink("clipboard"); // a hand-edited clipboard's mistakes leave those groups out
    const EditorData clip = level::read_editor_data(nlohmann::ordered_json(copied), "editor", sink);
    std::unordered_map<int, int> group_ids;
    std::vector<int> children;
    for (const Group& g : clip.groups) {
        group_ids[g.id] = data.next_group_id++;
        children.insert(children.end(), g.groups.begin(), g.groups.end());
    }
    auto mapped = [](const std::unordered_map<int, int>& map, int id) {
        auto it = map.find(id);
        return it == map.end() ? 0 : it->second;
    };
    for (Group g : clip.groups) {
        const bool top = std::find(children.begin(), children.end(), g.id) == children.end();
        g.id = group_ids[g.id];
        std::vector<int> entities, groups;
        for (int id : g.entities)
            if (int n = mapped(pasted, id)) entities.push_back(n);
        for (int id : g.groups)
            if (int n = mapped(group_ids, id)) groups.push_back(n);
        std::sort(entities.begin(), entities.end());
        std::sort(groups.begin(), groups.end());
        g.entities = std::move(entities);
        g.groups = std::move(groups);
        for (int& member : g.prefab.members) member = member == 0 ? 0 : mapped(pasted, member);
        if (g.entities.empty() && g.groups.empty()) continue;
        if (Group* parent = data.find_group(open_group); top && parent && !parent->has_prefab)
            insert_sorted(parent->groups, g.id);
        data.groups.push_back(std::move(g));
    }
}

void insert_sorted(std::vector<int>& ids, int id) {
    auto at = std::lower_bound(ids.begin(), ids.end(), id);
    if (at == ids.end() || *at != id) ids.insert(at, id);
}

void prune_empty_groups(EditorData& data) {
    for (bool pruned = true; pruned;) {
        pruned = false;
        for (size_t i = 0; i < data.groups.size(); ++i) {
            const Group& g = data.groups[i];
            if (!g.entities.empty() || !g.groups.empty()) continue;
            const int id = g.id;
            data.groups.erase(data.groups.begin() + static_cast<std::ptrdiff_t>(i));
            for (Group& other : data.groups) std::erase(other.groups, id);
            pruned = true;
            break;
        }
    }
}

int layer_of(const EditorData& data, int entity_id) {
    for (size_t i = 1; i < data.layers.size(); ++i)
        if (std::binary_search(data.layers[i].entities.begin(), data.layers[i].entities.end(), entity_id))
            return static_cast<int>(i);
    return 0;
}

std::unordered_map<int, int> layer_table(const EditorData& data) {
    std::unordered_map<int, int> table;
    for (size_t i = 1; i < data.layers.size(); ++i)
        for (int id : data.layers[i].entities) table.emplace(id, static_cast<int>(i));
    return table;
}

void refresh_view_sets(Document& doc) {
    const EditorData& data = doc.level.editor;
    doc.hidden.clear();
    doc.locked.clear();
    for (int id : data.hidden) doc.hidden.insert(id);
    for (int id : data.locked) doc.locked.insert(id);
    bool any_layer_off = false;
    for (const level::Layer& layer : data.layers) any_layer_off |= !layer.visible || layer.locked;
    if (any_layer_off) {
        const auto table = layer_table(data);
        for (const level::Entity& e : doc.level.entities) {
            auto it = table.find(e.id);
            const level::Layer& layer = data.layers[it == table.end() ? 0 : static_cast<size_t>(it->second)];
            if (!layer.visible) doc.hidden.insert(e.id);
            if (layer.locked) doc.locked.insert(e.id);
        }
    }
    std::erase_if(doc.selection, [&](int id) { return id != kPlayerStartId && doc.locked.contains(id); });
    if (doc.open_group != 0 && !data.find_group(doc.open_group)) doc.open_group = 0;
}

} // namespace ks::editor
