#pragma once
// The robot's rig with the model's true joint offsets, read headless from the generated glTF through
// anim/gltf_rig.h (the reader the editor uses too), so robot shots leave from the real hand_r_tip. The clip
// file's rig supplies names and parents; the model overrides rest transforms of the nodes it has.
#include "anim/clip_io.h"
#include "core/result.h"

#include <filesystem>
#include <memory>

namespace ks::game {

// Rest transforms from `gltf` applied to `rig` (names must match; nodes the model lacks keep theirs).
Result<anim::Rig> rig_with_model_offsets(const anim::Rig& rig, const std::filesystem::path& gltf);

// assets/animations/robot.json (or `clips`: a copy, for tests and tools) compiled for the rig of
// assets/models/robot.gltf (falls back to the clip file's own rig, with a warning, when the model is missing
// or unreadable).
Result<std::shared_ptr<const anim::AnimationLibrary>> load_robot_animations();
Result<std::shared_ptr<const anim::AnimationLibrary>>
load_robot_animations(const std::filesystem::path& clips);

} // namespace ks::game
