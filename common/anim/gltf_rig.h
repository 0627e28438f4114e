#pragma once
// The one place a model's rig is read: the node hierarchy of a glTF 2.0 file (.gltf JSON) with each node's
// rest translation, rotation and scale, rotations turned into the Euler XYZ the clips animate
// (anim/rotation.h). Plain JSON, no assimp and no GL, so the game, the editor and tests read the same rig.
#include "anim/rig.h"
#include "core/result.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace ks::anim {

// Nodes in parent-before-child order (depth first from the roots, roots in file order). Nodes without a
// name, or repeating an earlier name, are named "_node<index>_<name>" so every rig name is unique. Errors
// name the file and the JSON path of the bad value.
Result<Rig> load_gltf_rig(const std::filesystem::path& gltf);
Result<Rig> parse_gltf_rig(std::string_view json_text, const std::string& file_name);

} // namespace ks::anim
