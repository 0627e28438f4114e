#pragma once
// Prefabs, window-free: a reusable piece of level (a doorway with its door and lintel, a stair to a
// platform) saved as prefabs/NAME.json in the level format's entity schema, placed as linked instances.
// An instance is a group (level::Group with a PrefabLink) whose frame (position, yaw) says where the
// prefab's origin lies; its members follow the prefab except for the fields the instance overrides.
// This file holds the file format, the frame maths and the member refresh; the edits are Editor methods
// (edit_prefabs.h) and the folder listing is PrefabLibrary (prefab_library.h).
#include "core/result.h"
#include "level/level.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace ks::editor {

struct Prefab {
    std::string name;                    // the file's stem: a-z, 0-9, _ and -
    std::string title;                   // shown in the palette ("Doorway with door")
    std::vector<level::Entity> entities; // in the prefab's own frame (origin on the floor), ids 1..n
    bool operator==(const Prefab&) const = default;
};
inline constexpr size_t kMaxPrefabEntities = 4096;
inline constexpr size_t kMaxPrefabNameLength = 64;

// "" when `name` may name a prefab file, else why not (with what is allowed).
std::string prefab_name_problem(std::string_view name);

// {"format": "killswitch-prefab", "version": 1, "name": ..., "title": ..., "entities": [...]}: each entity
// exactly as a level file writes it, read by the level's reader (jsonio::Document, jsonio::ObjectReader):
// errors name the file, line:column, the JSON path and the fix; warnings (an unknown field) go to
// `warnings`, or to the log when it is null.
Result<Prefab> prefab_from_text(std::string_view text, const std::string& file_name,
                                std::vector<Error>* warnings = nullptr);
std::string prefab_to_text(const Prefab& prefab);

// A group's frame: the prefab origin's place and the turn about y (degrees).
struct Frame {
    Vec3 position{0.0f};
    float yaw = 0.0f;
};
// An entity moved from world space into `frame` (and back): position, rotation and patrol points.
level::Entity entity_into_frame(const level::Entity& world, const Frame& frame);
level::Entity entity_out_of_frame(const level::Entity& local, const Frame& frame);

// The field names (as field_access names them, plus "links") in which `a` and `b` differ; numbers within
// 1e-3 count as equal, so a frame moved with its members records nothing. `a` and `b` have the same type.
std::vector<std::string> differing_fields(const level::Entity& a, const level::Entity& b);

// What an instance member becomes when its prefab entity is `local`: the prefab's fields placed in
// `frame`, with the fields listed in `overrides` (and the name, which is always the instance's) kept from
// `current`; `renames` maps the prefab's entity names to the instance's, so links inside the prefab keep
// pointing inside the instance.
Result<level::Entity> refreshed_member(const level::Entity& local, const level::Entity& current,
                                       const Frame& frame, const std::vector<std::string>& overrides,
                                       const std::unordered_map<std::string, std::string>& renames);
// A prefab entity's links with their targets renamed (a name not in `renames` is kept).
std::vector<level::Link> renamed_links(const std::vector<level::Link>& links,
                                       const std::unordered_map<std::string, std::string>& renames);

} // namespace ks::editor
