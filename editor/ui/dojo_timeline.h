#pragma once
// The dojo's transport (play, pause, stop, step, loop, sounds, speed) and its timeline: ticks every 0.1 s,
// a marker at the end of every key (phase), the blend window of the transition test, the playhead, and the
// clip's event lane below (drawn by the caller's function, dojo_events.h); dragging on the ticks scrubs.
// Also the transition tester's row (dojo_transition.cpp).
#include "ui/dojo_context.h"

#include <functional>

namespace ks::editor::ui {

// Draws the event lane at `origin`, `width` x `height`, for a timeline `length` seconds long.
using DojoEventLane = std::function<void(Vec2 origin, float width, float height, double length)>;

class DojoTimeline {
  public:
    void transport(const DojoContext& dojo);
    void timeline(const DojoContext& dojo, float width, const DojoEventLane& lane);
    // The transport's Sounds toggle: play the events' sounds as the playhead passes them.
    bool event_sounds() const { return event_sounds_; }

  private:
    bool event_sounds_ = true;
};

// The transition tester: play `from`, switch to `to` at a time with a blend time (the file's, or one being
// tried), looping, so the hand-over can be watched and scrubbed. It keeps no state of its own: what it
// tests is the playback's plan (the blend grid's cells set it too).
void dojo_transition_tester(const DojoContext& dojo);

} // namespace ks::editor::ui
