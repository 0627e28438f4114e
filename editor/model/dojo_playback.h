#pragma once
// The dojo's playback, free of any window: what is played (one clip, or the transition test: `from`, then
// `to` from the switch time on, blended over the blend time) and how a player gets to a time. Scrubbing
// restarts from the rest pose (a pose is a pure function of the time since play()); playing advances by dt
// and hands over from `from` to `to` when a step crosses the switch time, so both reach the same pose.
#include "anim/player.h"

#include <functional>

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

} // namespace ks::editor
