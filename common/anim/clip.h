#pragma once
// Clips, in two forms.
//
// AnimationFile is the authored form, exactly what assets/animations/*.json holds and the editor's dojo panel
// edits: a rig description, blend times and clips made of phases (the reference's createGeneralAnimation
// steps). Angles are Euler XYZ degrees and times seconds, kept as doubles so load -> save is byte-identical.
//
// ClipSet is the compiled form bound to one Rig: per-node channels of keyframes in radians, each key eased
// from the previous one, ready for allocation-free sampling.
#include "anim/easing.h"
#include "anim/rig.h"
#include "core/math.h"
#include "core/result.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ks::anim {

enum class LoopMode : std::uint8_t {
    Once,     // play once and hold the last pose
    Loop,     // repeat forever; each iteration starts from the previous one's end pose
    Next,     // play once, then continue with the clip named by `next`
    PingPong, // forward, then backward to the start, forever (the pose at t equals the pose at 2d - t)
};

// What a phase does to a node it does not name.
enum class UnlistedRule : std::uint8_t {
    Rest, // ease back to the rest rotation (the reference's rule) -- applies to the file's rest_nodes only
    Hold, // keep the value it has
};

struct TargetDef {
    std::string node;
    std::optional<DVec3> rot;     // absolute Euler XYZ, degrees
    std::optional<DVec3> add_rot; // relative to the value at the phase's start (Tween.js "+x" strings)
    std::optional<DVec3> pos;     // offset from the node's rest position
    std::optional<DVec3> add_pos; // relative to the value at the phase's start
    std::optional<Ease> ease;     // overrides node_ease and the phase's easing for this node
};

struct PhaseDef {
    double duration = 0; // seconds; 0 = set instantly
    Ease ease = Ease::named(EaseFamily::Quadratic, EaseMode::In);
    std::vector<TargetDef> targets;
};

// A named marker at a time in a clip (muzzle flash, footstep, sound cue). The game reports each marker the
// clip passes; a marker with a sound plays it at the robot.
struct ClipEvent {
    double time = 0; // seconds from the clip's start, 0..duration
    std::string name;
    std::string sound; // a sound name (assets/sounds/<sound>.wav), empty for none
    bool operator==(const ClipEvent&) const = default;
};

struct ClipDef {
    std::string name;
    LoopMode loop = LoopMode::Once;
    std::string next; // LoopMode::Next only
    UnlistedRule unlisted = UnlistedRule::Rest;
    std::vector<PhaseDef> phases;
    std::vector<ClipEvent> events; // sorted by time when compiled
    // The frame rate the animator works at (frames per second, 1..1000): the dojo shows this clip in frames
    // and puts the times it writes on that grid. Absent: seconds (the game ignores it either way).
    std::optional<double> frame_rate;

    double duration() const;
};

struct RigNodeDef {
    std::string name;
    std::string parent; // empty = root
    DVec3 position{0};  // rest translation (the renderer's glTF values replace these)
    DVec3 rotation{0};  // rest rotation, Euler XYZ degrees
};

struct BlendPair {
    std::string from, to; // clip names, or "*" for any clip
    double time = 0;      // seconds
};

// A node's easing in every phase unless its target names one (the reference tweens the head without easing,
// i.e. Linear, whatever the phase's easing, including when the Rest rule sends it home).
struct NodeEase {
    std::string node;
    Ease ease;
};

struct AnimationFile {
    std::vector<RigNodeDef> rig;
    std::vector<std::string> rest_nodes; // nodes the Rest rule sends home
    std::vector<NodeEase> node_ease;
    double default_blend = 0.1; // seconds, for pairs not listed in `blends`
    std::vector<BlendPair> blends;
    bool wrap_captured_angles = true; // captured start angles move into (-180, 180] (same rotation)
    std::vector<ClipDef> clips;

    const ClipDef* find_clip(const std::string& name) const;
};

// --- compiled form ---------------------------------------------------------------------------------------

enum class KeyMode : std::uint8_t {
    Absolute,  // value is the channel's value
    FromStart, // value is added to the channel's value when the clip (iteration) started
};

struct Key {
    double time = 0; // seconds from the clip's start (double: loop phases stay exact over hours)
    Vec3 value{0};
    KeyMode mode = KeyMode::Absolute;
    Ease ease; // easing of the segment that ends at this key
};

struct Channel {
    int node = 0;
    bool is_position = false;                   // else the Euler rotation
    std::uint32_t first_key = 0, key_count = 0; // keys[first_key] is the implicit start key at t = 0
};

struct Clip {
    std::string name;
    double duration = 0;
    LoopMode loop = LoopMode::Once;
    int next = -1; // clip index for LoopMode::Next
    std::vector<Channel> channels;
    std::vector<Key> keys;
    std::vector<ClipEvent> events; // by time
};

class ClipSet {
  public:
    std::vector<Clip> clips;
    bool wrap_captured_angles = true;

    int find(std::string_view name) const;    // -1 if absent
    float blend_time(int from, int to) const; // from may be -1 (nothing playing): the default
    int node_count() const { return node_count_; }

  private:
    friend Result<ClipSet> compile(const AnimationFile& file, const Rig& rig);
    std::vector<float> blend_; // clips.size()^2, row = from
    float default_blend_ = 0;
    int node_count_ = 0;
};

// The rig the file describes (headless use; the renderer builds its own from the model).
Result<Rig> build_rig(const AnimationFile& file);
// Binds clips to a rig: every node a clip or the rest list names must exist in it (a model missing a node is
// reported, not ignored). Rest values come from the rig.
Result<ClipSet> compile(const AnimationFile& file, const Rig& rig);

} // namespace ks::anim
