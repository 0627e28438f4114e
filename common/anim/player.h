#pragma once
// Plays clips on one rig instance with transitions from whatever pose it is in.
//
// play(clip): the current pose and its velocity are captured; the new clip starts from that pose (its first
// keys ease away from it) and, over the blend time, the output moves from an inertial continuation of the
// old motion (pose + velocity, the velocity fading to zero) to the new clip with a smoothstep weight. The
// pose never jumps, and with a blend time > 0 the velocity is continuous too. crossfade(clip): the old clip
// keeps running underneath while the new one fades in.
//
// Time is kept in flicks (1/705,600,000 s, divisible by every common frame rate), so the same sequence of
// calls lands on bit-identical poses at 24, 30, 60, 120, 144 or 240 fps; a pose is a pure function of that
// time and the captured start pose. Nothing is allocated after construction.
#include "anim/clip.h"
#include "anim/rig.h"

#include <cstdint>
#include <span>
#include <vector>

namespace ks::anim {

inline constexpr std::int64_t kFlicksPerSecond = 705'600'000;
std::int64_t to_flicks(double seconds);
inline double to_seconds(std::int64_t flicks) {
    return static_cast<double>(flicks) / kFlicksPerSecond;
}

// One clip sampled t seconds after it started from `start` (Euler and position per node). Nodes the clip has
// no channel for keep their start values. Velocities (per second) are written when the spans are non-empty.
void sample_clip(const Clip& clip, std::span<const Vec3> start_euler, std::span<const Vec3> start_position,
                 double t, std::span<Vec3> out_euler, std::span<Vec3> out_position,
                 std::span<Vec3> velocity_euler = {}, std::span<Vec3> velocity_position = {});

// A clip event (marker) the player passed: which clip, and the event in that clip's ClipEvent list.
struct FiredEvent {
    int clip = -1;
    const ClipEvent* event = nullptr;
};

class Player {
  public:
    // Starts at the rig's rest pose with nothing playing. `clips` and `rig` must outlive the player.
    Player(const ClipSet& clips, const Rig& rig);

    void play(int clip);                      // blend time from the clip set (per pair, else its default)
    void play(int clip, float blend_seconds); // 0 = start from the captured pose with no blend
    void crossfade(int clip, float seconds);  // mid-blend it falls back to play(clip, seconds)
    // Moves time forward (dt <= 0 or NaN: no change). Clips with LoopMode::Next hand over at their exact end.
    void advance(double dt_seconds);

    const Pose& pose() const { return pose_; }
    // Euler-angle and position rates of the output at the current time (analytic).
    void velocity(std::span<Vec3> euler_rate, std::span<Vec3> position_rate);

    int current_clip() const { return current_.clip; }
    double clip_time() const { return to_seconds(now_ - current_.start); }
    std::int64_t ticks() const { return now_; }
    double time() const { return to_seconds(now_); }
    bool blending() const { return source_ != Source::None && now_ - blend_start_ < blend_length_; }
    // A Once clip past its end (a looping or ping-pong clip never finishes).
    bool finished() const;
    // The clip events passed by the last advance(), in time order: (previous time, new time] of the clip's
    // own time, every loop iteration crossed (up to a bound), an event at 0 s once the clip has started. A
    // ping-pong clip fires its events on the way there and on the way back (one at a turn fires once).
    std::span<const FiredEvent> fired_events() const { return fired_; }

  private:
    struct Instance {
        int clip = -1;
        std::int64_t start = 0;
        std::vector<Vec3> start_euler, start_position;
    };
    enum class Source : std::uint8_t { None, Inertial, Crossfade };

    void evaluate(std::span<Vec3> euler, std::span<Vec3> position, std::span<Vec3> vel_euler,
                  std::span<Vec3> vel_position);
    void sample_instance(const Instance& inst, std::span<Vec3> euler, std::span<Vec3> position,
                         std::span<Vec3> vel_euler, std::span<Vec3> vel_position) const;
    void refresh_pose();
    void collect_events(std::int64_t until);

    const ClipSet& clips_;
    const Rig& rig_;
    std::int64_t now_ = 0;
    Instance current_, fading_;
    Source source_ = Source::None;
    std::int64_t blend_start_ = 0, blend_length_ = 0;
    std::vector<Vec3> inertial_euler_, inertial_position_, inertial_vel_euler_, inertial_vel_position_;
    // Scratch for blending and captures (sized once).
    std::vector<Vec3> a_euler_, a_position_, a_vel_euler_, a_vel_position_;
    std::vector<Vec3> b_euler_, b_position_, b_vel_euler_, b_vel_position_;
    Pose pose_;
    std::int64_t events_done_ = -1; // current clip's time (flicks) up to which events were reported
    std::vector<FiredEvent> fired_; // capacity fixed at construction
};

} // namespace ks::anim
