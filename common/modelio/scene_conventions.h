#pragma once
// What an assimp scene says about itself, turned into the level's terms: the file's units and axes as one
// matrix into level units with +Y up. Internal to modelio (model_import.cpp uses it).
#include "modelio/model_import.h"

#include <filesystem>

struct aiScene;

namespace ks::modelio {

struct SceneBasis {
    Mat4 to_level{1.0f};     // file coordinates -> level units, +Y up
    float unit_scale = 1.0f; // the scale part of to_level
    bool mirrored = false;   // the axes change handedness: triangle windings must be reversed
    std::string axes;        // for messages
};

// glTF: +Y up, metres (the format says so). OBJ: no units in the format; read as metres, +Y up (Blender's
// and most tools' OBJ export). FBX: the file's GlobalSettings (UpAxis/Sign, FrontAxis/Sign, CoordAxis/Sign,
// UnitScaleFactor in centimetres per file unit), which assimp passes on as scene metadata but does not apply.
// An FBX whose axes are not three distinct ones is an Error.
Result<SceneBasis> scene_basis(const aiScene& scene, const std::filesystem::path& path);

} // namespace ks::modelio
