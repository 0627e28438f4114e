#pragma once
// The dojo panel's curve view, free of any window: one node's channel (a rotation or position component)
// over a clip's time, sampled from the compiled clip, with its keys (a key is the end of a phase, shared by
// every node) and each segment's easing; and the key edits made on the curve: a key dragged in time or in
// value. Edits leave the file unchanged on error; wrap them in apply_dojo_edit (dojo_clips.h) for undo.
#include "anim/clip.h"
#include "core/result.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace ks::editor {

enum class CurveChannel : std::uint8_t { RotX, RotY, RotZ, PosX, PosY, PosZ };
inline bool is_position(CurveChannel c) {
    return c >= CurveChannel::PosX;
}
inline int component(CurveChannel c) {
    return static_cast<int>(c) % 3;
}
// "rot.x" ... "pos.z" and back.
const char* curve_channel_name(CurveChannel c);
std::optional<CurveChannel> curve_channel_from_name(std::string_view name);

struct CurvePoint {
    double time = 0;  // seconds from the clip's start
    double value = 0; // rotation: Euler degrees; position: offset from the node's rest position
};

// The key at the end of phase `phase` (the implicit key at t = 0 is ClipCurve::start_value).
struct CurveKey {
    std::size_t phase = 0;
    double time = 0;    // the phase's end
    double value = 0;   // the curve's value there
    anim::Ease ease;    // easing of the segment that ends here (target's, else node_ease, else the phase's)
    bool keyed = false; // the phase's target for this node sets this channel (rot/add_rot or pos/add_pos)
    bool relative = false;   // keyed by add_rot / add_pos
    double target_value = 0; // keyed: the target's component as the file stores it (absolute or offset)
};

struct ClipCurve {
    double duration = 0;
    double start_value = 0;         // at t = 0: the rest pose's value (the dojo starts clips from rest)
    std::vector<CurvePoint> points; // `samples` points from 0 to duration (one when the clip has no length)
    std::vector<CurveKey> keys;     // one per phase
};

// Samples clip `clip`'s channel for `node` from the rest pose (anim::compile and anim::sample_clip on the
// file's own rig), over one pass of the clip: 0..duration. Errors name a clip out of range, a node the rig
// lacks, or a file that does not compile.
Result<ClipCurve> clip_curve(const anim::AnimationFile& file, std::size_t clip, const std::string& node,
                             CurveChannel channel, int samples = 64);

// A channel of one node, for several curves at once.
struct NodeChannel {
    std::string node;
    CurveChannel channel = CurveChannel::RotX;
    bool operator==(const NodeChannel&) const = default;
    auto operator<=>(const NodeChannel&) const = default;
};
// clip_curve for each of `channels` (the file compiled once), in their order.
Result<std::vector<ClipCurve>> clip_curves(const anim::AnimationFile& file, std::size_t clip,
                                           std::span<const NodeChannel> channels, int samples = 64);

// The channel's value (as ClipCurve shows it) `seconds` after the clip starts from the rest pose, past its
// end too (a loop repeats, a ping-pong clip comes back, a once clip holds): a readout, and what scripts
// check.
Result<double> curve_value(const anim::AnimationFile& file, std::size_t clip, const std::string& node,
                           CurveChannel channel, double seconds);

// Moves key `phase` (the end of that phase) to `seconds` from the clip's start: that phase's duration and
// the next one's change so every other key stays where it is; the last key changes the clip's length.
// Refused when it would cross (not meet) a neighbouring key, leave an event outside the clip, or give a
// looping clip zero length.
Result<void> move_key_time(anim::AnimationFile& file, std::size_t clip, std::size_t phase, double seconds);
// Sets one component of `node`'s key in phase `phase`: an absolute target's rot/pos component (degrees, or
// the offset from rest), a relative target's add_rot/add_pos offset. A target that keys the node but not
// this channel's kind gets a relative one (zero offsets but this component). Refused when the phase has no
// target for `node` (add one first: add_node_key) or the value is not finite / out of range.
Result<void> set_key_value(anim::AnimationFile& file, std::size_t clip, std::size_t phase,
                           const std::string& node, CurveChannel channel, double value);

// After `node`'s value at key `phase` changed by `delta` on `channel`: the node's next relative key on the
// channel takes it back, unless an absolute key or the rest rule comes first, so every later key reaches
// what it did (set_key_value does this for a relative key; the graph for a key it adds).
void keep_later_keys(anim::AnimationFile& file, std::size_t clip, std::size_t phase, const std::string& node,
                     CurveChannel channel, double delta);

} // namespace ks::editor
