#pragma once
// The clips the robot's clip file must have, in one place: the game looks up six of them by name
// (robot_build.cpp, RobotSystem::find_clips) and the Dojo's key 0 plays `reset`. The editor refuses to delete
// or rename them, giving the reason, and check_required_clips lists the missing ones.
//
// A separate check, not part of anim::validate: validate() judges any animation file, and these names are
// the robot's (what assets/animations/robot.json must hold), so the editor's save and live check and the
// tests run both, while the loader stays generic.
#include "anim/clip_io.h"

#include <span>
#include <string_view>
#include <vector>

namespace ks::anim {

struct RequiredClip {
    const char* name;
    const char* reason; // why it is needed: "the game plays 'death' when a robot dies"
};

// In the order the reference's Dojo keys list them, `idle` first.
std::span<const RequiredClip> required_robot_clips();
// The entry for `name`, or null when the clip is not required.
const RequiredClip* find_required_clip(std::string_view name);
// One issue (at "clips") naming every required clip `file` lacks; empty when it has them all.
std::vector<Issue> check_required_clips(const AnimationFile& file);

} // namespace ks::anim
