#pragma once
// <model>.lods.json: the asset generator's list of a shipped model's levels of detail (docs/assets.md,
// "Levels of detail"). Level 0 is the model itself; each coarser level is a glTF file beside it with the
// same nodes, built from the same recipe with fewer segments, and `deviation` bounds how far it lies from
// level 0, in the model's units.
#include "core/result.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace ks::render {

struct ModelLodEntry {
    std::string file;       // a file name in the model's folder
    float deviation = 0.0f; // a bound on its distance from level 0, model units
    int triangles = 0;
};

// The most levels a list may name (the generator writes at most four).
inline constexpr int kMaxModelLods = 8;

// Reads a level list for `model_file` (its file name, "robot.gltf"). Refused, with the place and a fix:
// not this format or version, another model's list, no levels, more than kMaxModelLods, a first level
// that is not the model itself at deviation 0, a file that is not a plain .gltf/.glb name in the same
// folder, a deviation that is not a finite number >= 0 or that shrinks from one level to the next.
Result<std::vector<ModelLodEntry>> parse_model_lods(std::string_view text, const std::string& list_file,
                                                    const std::string& model_file);

// Where a model's level list is: assets/models/robot.gltf -> assets/models/robot.lods.json.
std::filesystem::path model_lods_path(const std::filesystem::path& model);

} // namespace ks::render
