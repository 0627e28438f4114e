#pragma once
// The dojo's speed aids, window-free: a key's node values (or the pose at the playhead) copied, and pasted
// into a key as they were or mirrored left <-> right. The robot's sideways axis is its nodes' local z
// (arm_r at z +0.6, arm_l at -0.6, rests without rotation), so a mirror swaps the nodes named _l/_r (also
// _L/_R, .l/.r, .L/.R, left/right, _l_/_r_ inside) and reflects z: Euler XYZ (x, y, z) becomes (-x, -y, z),
// since M Rx(a) Ry(b) Rz(c) M = Rx(-a) Ry(-b) Rz(c) for M = diag(1, 1, -1), and an offset (x, y, z) becomes
// (x, y, -z). Each paste is one undo step through apply_dojo_edit.
#include "anim/clip.h"
#include "core/result.h"
#include "model/dojo_clips.h"

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace ks::editor {

struct DojoKeyClipboard {
    std::vector<anim::TargetDef> targets; // one per node, easing kept
};

// Key `key` (a phase) of clip `clip`: its targets as they are.
Result<DojoKeyClipboard> copy_key(const anim::AnimationFile& file, std::size_t clip, std::size_t key);
// A pose (pose_values or clip_pose_values) as absolute rot + pos targets.
DojoKeyClipboard copy_pose(std::span<const NodePoseValue> pose);

// The node named as `name`'s other side ("arm_l" for "arm_r"), or `name` itself for a centre node.
std::string mirror_node_name(const std::string& name);
// `clipboard` reflected left <-> right: names swapped where the file's rig has the other side, values
// reflected (see above).
DojoKeyClipboard mirrored(const DojoKeyClipboard& clipboard, const anim::AnimationFile& file);

// Sets key `key` of clip `clip` to the clipboard's values: each node's target replaced (others kept).
// Refused, with the file unchanged: an unknown clip or key, an empty clipboard, a node not in the rig.
Result<void> paste_key(anim::AnimationFile& file, std::size_t clip, std::size_t key,
                       const DojoKeyClipboard& clipboard);

} // namespace ks::editor
