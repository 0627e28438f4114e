// The frame loop's pacing (common/shell/frame_pacing.h): when it draws, when it waits, for how long.
#include "shell/frame_pacing.h"

#include <doctest/doctest.h>

using ks::shell::FramePacer;
using ks::shell::PacingSettings;

namespace {
// Draws every frame the pacer says is due at `now` (no animation); returns how many.
int draw_while_due(FramePacer& pacer, double now) {
    int frames = 0;
    while (pacer.frame_due(false, now) && frames < 100) {
        pacer.drew(now);
        ++frames;
    }
    return frames;
}
} // namespace

TEST_CASE("frame pacing: an idle window draws its first frames, then waits until an event") {
    PacingSettings settings;
    settings.settle_frames = 3;
    FramePacer pacer(settings);
    CHECK(draw_while_due(pacer, 0.0) == 4); // the first picture and three to settle
    CHECK_FALSE(pacer.frame_due(false, 10.0));
    pacer.on_event();
    CHECK(draw_while_due(pacer, 10.0) == 4); // the event's frame and three more
    CHECK_FALSE(pacer.frame_due(false, 10.5));
    pacer.request_frame();
    CHECK(draw_while_due(pacer, 11.0) == 1);
    // A request while an event still settles does not cut the settling short.
    pacer.on_event();
    pacer.drew(12.0);
    pacer.request_frame();
    CHECK(draw_while_due(pacer, 12.0) == 3);
}

TEST_CASE("frame pacing: animating draws every frame, at most max_fps a second") {
    PacingSettings settings;
    settings.max_fps = 50.0;
    FramePacer pacer(settings);
    draw_while_due(pacer, 0.0);
    CHECK(pacer.frame_due(true, 5.0));
    pacer.drew(5.0);
    CHECK(pacer.cap_wait(5.0) == doctest::Approx(0.02));
    CHECK(pacer.cap_wait(5.015) == doctest::Approx(0.005));
    CHECK(pacer.cap_wait(5.03) == 0.0); // a slow frame: the next one at once
    CHECK(pacer.frame_interval() == doctest::Approx(0.02));
}

TEST_CASE("frame pacing: the idle poll and the heartbeat bound the wait") {
    PacingSettings settings;
    settings.idle_poll_seconds = 0.5;
    FramePacer pacer(settings);
    draw_while_due(pacer, 0.0);
    CHECK(pacer.take_idle_poll(0.5));
    CHECK_FALSE(pacer.take_idle_poll(0.7)); // done at 0.5: the next at 1.0
    CHECK(pacer.wait_seconds(0.7) == doctest::Approx(0.3));
    CHECK(pacer.take_idle_poll(1.0));

    settings.heartbeat_seconds = 0.1;
    FramePacer beating(settings);
    draw_while_due(beating, 0.0);
    CHECK(beating.wait_seconds(0.04) == doctest::Approx(0.06));
    CHECK_FALSE(beating.frame_due(false, 0.05));
    CHECK(beating.frame_due(false, 0.1));
    beating.drew(0.1);
    CHECK_FALSE(beating.frame_due(false, 0.15));
}

TEST_CASE("frame pacing: settings out of range fall back to sane ones") {
    PacingSettings settings;
    settings.max_fps = 0.0;
    settings.idle_poll_seconds = -1.0;
    settings.settle_frames = -5;
    FramePacer pacer(settings);
    CHECK(pacer.frame_interval() == doctest::Approx(1.0 / 60.0));
    CHECK(draw_while_due(pacer, 0.0) == 1);
    CHECK(pacer.wait_seconds(0.0) == doctest::Approx(0.5));
}
