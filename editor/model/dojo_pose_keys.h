#pragma once
// Keying a pose at the playhead, window-free: the dojo's Key button, K and auto-key. Keys are the ends of
// phases (dojo_keys.h), so a playhead on a key (within kKeyTimeTolerance) keys that phase; a playhead between
// two keys splits the phase there first, the first half ending at the playhead with every node the phase
// moves keyed to where it is at that time (absolute targets at their value, relative ones split into two
// offsets that add up to the old one), so no pose of the clip at a key time changes and the later keys stay
// where they were. The clip's start (t = 0) is not a key: a clip starts from the pose it is entered in.
#include "anim/clip.h"
#include "core/result.h"

#include <cstddef>
#include <span>
#include <string>

namespace ks::editor {

inline constexpr double kKeyTimeTolerance = 1e-4; // seconds: a playhead this close to a key is on it

// A node's rotation to key: Euler XYZ degrees, absolute (as the key table shows it).
struct NodeRotation {
    std::string node;
    DVec3 degrees{0.0};
};

// Keys `rotations` in clip `clip` at `seconds` (within one pass of the clip: 0 < seconds <= duration):
// each node's target in the key at that time gets the rotation (a relative target keeps being relative: its
// offset becomes what reaches the rotation); a node without a target there gets an absolute one. Returns
// the key's (phase's) index. Refused, the file unchanged: an unknown clip or node, no rotations, a time
// outside the clip or at its start, a value that is not finite.
Result<std::size_t> key_rotations_at(anim::AnimationFile& file, std::size_t clip, double seconds,
                                     std::span<const NodeRotation> rotations);

// The undo step's name: "Key forearm_l at 0.50 s", "Key 3 nodes at 0.50 s".
std::string key_step_name(std::span<const NodeRotation> rotations, double seconds);

} // namespace ks::editor
