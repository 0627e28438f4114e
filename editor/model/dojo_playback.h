#pragma once
// The dojo's playback, free of any window: what is played (one clip, or the transition test: `from`, then
// `to` from the switch time on, blended over the blend time) and how a player gets to a time. Scrubbing
// restarts from the rest pose (a pose is a pure function of the time since play()); playing advances by dt
// and hands over from `from` to `to` when a step crosses the switch time, so both reach the same pose.
// DojoPlayback holds the compiled clips, the rig and the player with the transport's state (play, loop,
// speed, the playhead); the dojo's panels drive it and draw from it.
#include "anim/clip.h"
#include "anim/player.h"
#include "anim/rig.h"

#include <functional>
#include <memory>

namespace ks::editor {

struct DojoPlayPlan {
    bool transition = false;
    int clip = 0;           // played alone when not testing a transition
    int from = 0, to = 0;   // the transition test's clips
    double switch_at = 0.5; // seconds after `from` starts
    float blend = 0.2f;     // the hand-over's blend time
};

// Starts `player` over with the plan and advances it to `seconds`.
void dojo_restart_at(anim::Player& player, const DojoPlayPlan& plan, double seconds);

// Advances `player`, which stands at `now` seconds into the plan, by `step` seconds; in a transition test
// a step that crosses the switch time plays `to` from there. `after_advance` runs after each advance of
// the player (there are two when the step is split), so no fired event is missed.
void dojo_advance(anim::Player& player, const DojoPlayPlan& plan, double now, double step,
                  const std::function<void(const anim::Player&)>& after_advance = {});

// The playhead within one pass of a clip `duration` long: a looping clip's time within its pass, a
// ping-pong's folded back on its way home, a once (or next) clip's held at its end.
double dojo_pass_time(anim::LoopMode loop, double duration, double time);

// The keys either side of the playhead in `clip` (its start, t = 0, and each phase end), the playhead taken
// within the first pass (a once clip's held at its end); -1 where there is none. A playhead on a key
// (within 1e-4 s) has the keys around it as neighbours.
struct DojoKeysAround {
    double previous = -1.0, next = -1.0;
};
DojoKeysAround dojo_keys_around(const anim::ClipDef& clip, double time);

class DojoPlayback {
  public:
    DojoPlayback() = default;
    DojoPlayback(const DojoPlayback&) = delete; // the player refers to the clips and rig held here
    DojoPlayback& operator=(const DojoPlayback&) = delete;

    // The rig the clips are compiled against (the robot model's); drops the clips and player.
    void set_rig(anim::Rig rig);
    const anim::Rig& rig() const { return rig_; }
    // New clips (after an edit): the chosen clips are kept in range and the player restarts at the playhead.
    void set_clips(anim::ClipSet clips);
    const anim::ClipSet& clips() const { return clips_; }
    bool has_clips() const { return player_ && !clips_.clips.empty(); }
    const anim::Player* player() const { return player_.get(); }

    const DojoPlayPlan& plan() const { return plan_; }
    int clip() const { return plan_.clip; }
    bool transition() const { return plan_.transition; }
    // Plays `index` from the start, leaving the transition test; false (nothing changes) when out of range.
    bool show_clip(int index);
    // Makes `index` the shown clip without restarting: the recompile after an edit that made it (a copy)
    // keeps it in range and restarts at the playhead.
    void choose_clip(int index) { plan_.clip = index; }
    // Loops from -> to with the file's blend time for the pair; false when either is out of range.
    bool test_transition(int from, int to);
    // The transition tester's settings as its widgets edit them (clips out of range are ignored); the
    // playhead stays where it is until restart_at.
    void set_transition(bool on, int from, int to, double switch_at, float blend);

    // The transport.
    bool playing() const { return playing_; }
    void set_playing(bool on) { playing_ = on; }
    bool loop() const { return loop_; }
    void set_loop(bool on) { loop_ = on; }
    float speed() const { return speed_; }
    void set_speed(float speed) { speed_ = speed; }
    double time() const { return time_; }
    // Scrubs: the player starts over and is advanced to `seconds`.
    void restart_at(double seconds);
    // Plays on by dt × speed while playing: a once clip (or the transition test) starts over when Loop is
    // on and the step would pass its end; `after_advance` sees each advance of the player (fired events).
    void advance(double dt, const std::function<void(const anim::Player&)>& after_advance = {});
    // The timeline's length: the clip's, or the transition test's switch + blend + `to`'s.
    double timeline_length() const;

  private:
    anim::Rig rig_;
    anim::ClipSet clips_;
    std::unique_ptr<anim::Player> player_;
    DojoPlayPlan plan_;
    bool playing_ = true;
    bool loop_ = true;
    float speed_ = 1.0f;
    double time_ = 0.0; // seconds into the clip (or into the transition test)
};

} // namespace ks::editor
