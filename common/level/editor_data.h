#pragma once
// The editor's own part of a level file, saved under its "editor" key: layers, groups, prefab instances and
// the entities hidden or locked one by one. The game reads past it (level_reader keeps it so a file
// round-trips, and a mistake in it is a warning, never an error: a broken editor section must not stop a
// level loading). Nothing here changes how the level plays.
#include "core/math.h"

#include <string>
#include <vector>

namespace ks::level {

// A named set of entities the designer shows, hides, locks and unlocks together. An entity in no layer's
// list is in the first layer (the "Default" layer, which always exists once any layer does).
struct Layer {
    std::string name;
    bool visible = true;
    bool locked = false;
    std::vector<int> entities; // entity ids, sorted
    bool operator==(const Layer&) const = default;
};
inline constexpr int kMaxLayers = 64;
inline constexpr int kMaxLayerNameLength = 64;

// A prefab instance: a group whose members were made from the prefab file prefabs/NAME.json and follow it.
// `members[i]` is the entity made from the prefab's entity i (0: the designer deleted it; it stays deleted
// when the prefab changes); `overrides[i]` lists the fields of that entity the instance keeps as its own
// (property names as the level file spells them, "name", "links"), sorted. The instance's own placement is
// its group's position and yaw.
struct PrefabLink {
    std::string prefab; // the prefab's name, without folder or ".json"
    std::vector<int> members;
    std::vector<std::vector<std::string>> overrides; // same length as members
    bool operator==(const PrefabLink&) const = default;
};

// Entities (and groups) that are selected, moved, turned and duplicated as one. Groups nest: `groups` are
// the ids of child groups, each in exactly one parent. position/yaw are the group's own frame (the pivot
// rotations turn about; for a prefab instance, where its prefab's origin is placed and how it is turned).
struct Group {
    int id = 0; // unique among the level's groups, never reused (EditorData::next_group_id)
    std::string name;
    Vec3 position{0.0f};
    float yaw = 0.0f;          // degrees
    std::vector<int> entities; // member entity ids (a prefab instance: the live ones of prefab->members)
    std::vector<int> groups;   // child group ids
    bool has_prefab = false;   // a prefab instance (then `prefab` is meaningful)
    PrefabLink prefab;
    bool operator==(const Group&) const = default;
};

struct EditorData {
    std::vector<Layer> layers; // empty: no layers yet (everything in an implicit Default layer)
    int active_layer = 0;      // where new entities go (an index into layers)
    std::vector<Group> groups;
    int next_group_id = 1;
    std::vector<int> hidden; // entity ids hidden one by one (the outliner's eye), sorted
    std::vector<int> locked; // entity ids locked one by one, sorted

    bool empty() const {
        return layers.empty() && groups.empty() && hidden.empty() && locked.empty() && next_group_id == 1;
    }
    const Group* find_group(int id) const {
        for (const Group& g : groups)
            if (g.id == id) return &g;
        return nullptr;
    }
    Group* find_group(int id) {
        for (Group& g : groups)
            if (g.id == id) return &g;
        return nullptr;
    }
    bool operator==(const EditorData&) const = default;
};

} // namespace ks::level
