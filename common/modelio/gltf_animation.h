#pragma once
// Node animations in glTF 2.0 files (.gltf or .glb), written and read through assimp: a node hierarchy with
// rest transforms, and named animations of per-node translation and rotation keys (linear). Plain data, no
// clips and no rig (the editor's dojo turns clips into these tracks and back: editor/model/dojo_gltf.h), so
// this module keeps seeing only core and geometry. Every bad file is an Error naming the file and the place
// (the animation, channel and key); nothing here throws or aborts on bad input (docs/animation.md).
#include "core/math.h"
#include "core/result.h"

#include <filesystem>
#include <string>
#include <vector>

namespace ks::modelio {

struct AnimNode {
    std::string name;
    int parent = -1; // an earlier node's index, or -1 for a root
    Vec3 translation{0};
    Quat rotation{1, 0, 0, 0};
    Vec3 scale{1};
};

// How the keys of a sampler join (glTF's sampler.interpolation).
enum class KeyInterpolation { Linear, Step, CubicSpline };

// One node's keys in one animation: translation and rotation keys, each list with its own times (seconds,
// increasing). An empty list: the file does not animate that property.
struct NodeTrack {
    std::string node;
    std::vector<double> translation_times;
    std::vector<Vec3> translations;
    KeyInterpolation translation_interpolation = KeyInterpolation::Linear;
    std::vector<double> rotation_times;
    std::vector<Quat> rotations;
    KeyInterpolation rotation_interpolation = KeyInterpolation::Linear;
};

struct NodeAnimation {
    std::string name;
    std::vector<NodeTrack> tracks;
};

struct AnimatedScene {
    std::vector<AnimNode> nodes; // parents before children
    std::vector<NodeAnimation> animations;
    // What the file holds that the tracks do not carry: scale and morph-weight channels, cubic-spline
    // tangents. One line each, naming the animation and node.
    std::vector<std::string> ignored;
};

// Writes `scene` as glTF 2.0: binary .glb or .gltf (JSON with the keys in a .bin beside it), chosen by the
// extension (assimp writes each node's translation/rotation/scale, as glTF requires of animated nodes).
// Refuses non-finite values and tracks naming a node the scene has not.
Result<void> write_gltf_animations(const std::filesystem::path& path, const AnimatedScene& scene);

// Reads every node (with its name and rest transform) and every animation's translation and rotation keys.
// Errors: no such file, not glTF, truncated or corrupt (assimp's message), no animation, a non-finite key
// (naming animation, node, channel and key), times not increasing.
Result<AnimatedScene> read_gltf_animations(const std::filesystem::path& path);

} // namespace ks::modelio
