// The gamepad without a pad: synthetic GamepadState (core/gamepad_state.h mirrors GLFWgamepadstate) through
// GamepadInput (runtime/model/gamepad_input.h) into the game's Input — movement, look per step, jump, shots
// on the trigger's pull, interact, the menus' B and Start — and the radial dead zone (inside, the edge,
// diagonals, NaN and out-of-range axes). The menus' navigation is the shell's (test_gamepad_nav.cpp).
#include "core/gamepad_state.h"
#include "runtime/model/gamepad_input.h"
#include "runtime/model/input_script.h"
#include "runtime/model/keyboard_mouse_input.h"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>

using namespace ks;
using namespace ks::runtime;

namespace {
constexpr float kPadStep = 1.0f / 120.0f;

GamepadState pad() {
    GamepadState s;
    s.connected = true;
    return s;
}

game::Input step(GamepadInput& g, const Options& o = Options{}) {
    game::Input in;
    g.add_to(in, kPadStep, o);
    return in;
}
} // namespace

TEST_CASE(
    "dead zone: nothing inside, zero at the edge rising to one at full tilt, diagonals keep their angle") {
    const float dz = 0.2f;
    Stick s = apply_dead_zone(0.1f, 0.1f, dz); // length 0.14: inside
    CHECK(s.x == 0.0f);
    CHECK(s.y == 0.0f);
    s = apply_dead_zone(0.2f, 0.0f, dz); // exactly on the edge
    CHECK(s.x == 0.0f);
    s = apply_dead_zone(0.21f, 0.0f, dz); // just past: barely moves (no jump to 0.2)
    CHECK(s.x == doctest::Approx(0.0125f).epsilon(0.01));
    s = apply_dead_zone(0.6f, 0.0f, dz);
    CHECK(s.x == doctest::Approx(0.5f));
    s = apply_dead_zone(-1.0f, 0.0f, dz);
    CHECK(s.x == doctest::Approx(-1.0f));
    // A diagonal: the rescaled length, the same direction.
    const float d = 0.6f / std::sqrt(2.0f);
    s = apply_dead_zone(d, -d, dz);
    CHECK(std::sqrt(s.x * s.x + s.y * s.y) == doctest::Approx(0.5f));
    CHECK(s.x == doctest::Approx(-s.y));
    // Per-axis dead zones would drop this small sideways part of a mostly-forward push; radial keeps it.
    s = apply_dead_zone(0.15f, -0.9f, dz);
    CHECK(s.x > 0.05f);
    // A corner of a square gate (length 1.41) is capped at 1.
    s = apply_dead_zone(1.0f, 1.0f, dz);
    CHECK(std::sqrt(s.x * s.x + s.y * s.y) == doctest::Approx(1.0f));
}

TEST_CASE("dead zone: NaN, infinities and out-of-range values are safe") {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    Stick s = apply_dead_zone(nan, 0.5f, 0.15f);
    CHECK(s.x == 0.0f);
    CHECK(s.y == 0.0f);
    s = apply_dead_zone(inf, -inf, 0.15f);
    CHECK(s.x == 0.0f);
    s = apply_dead_zone(7.0f, 0.0f, 0.15f); // clamped to full tilt
    CHECK(s.x == doctest::Approx(1.0f));
    s = apply_dead_zone(0.5f, 0.0f, nan); // a NaN dead zone: none
    CHECK(s.x == doctest::Approx(0.5f));
    s = apply_dead_zone(0.95f, 0.0f, 5.0f); // an absurd dead zone is held at 0.9
    CHECK(s.x == doctest::Approx(0.5f));
    s = apply_dead_zone(0.5f, 0.0f, -1.0f);
    CHECK(s.x == doctest::Approx(0.5f));
    // The state's own reading: NaN sticks at rest, NaN triggers released, values clamped.
    GamepadState p = pad();
    p.axes[kPadLeftX] = nan;
    p.axes[kPadRightTrigger] = nan;
    p.axes[kPadLeftY] = -3.0f;
    CHECK(p.axis(kPadLeftX) == 0.0f);
    CHECK(p.axis(kPadRightTrigger) == -1.0f);
    CHECK(p.axis(kPadLeftY) == -1.0f);
    CHECK(p.axis(99) == 0.0f);
    CHECK_FALSE(p.button(-1));
    CHECK_FALSE(p.button(99));
    GamepadInput g;
    g.poll(p);
    const game::Input in = step(g);
    CHECK(in.move_forward == doctest::Approx(1.0f));
    CHECK(in.move_right == 0.0f);
    CHECK_FALSE(in.fire);
}

TEST_CASE("gamepad: left stick moves, right stick looks by rate x step, sensitivity and invert Y") {
    Options o;
    o.pad_dead_zone = 0.1f;
    GamepadInput g;
    GamepadState p = pad();
    p.axes[kPadLeftY] = -1.0f; // pushed up: forward
    p.axes[kPadLeftX] = 0.0f;
    p.axes[kPadRightX] = 1.0f; // full right: turn right (yaw negative)
    g.poll(p);
    game::Input in = step(g, o);
    CHECK(in.move_forward == doctest::Approx(1.0f));
    CHECK(in.move_right == 0.0f);
    CHECK(in.look_yaw == doctest::Approx(-GamepadInput::kLookRate * kPadStep));
    CHECK(in.look_pitch == 0.0f);
    // Half tilt past the dead zone turns a quarter as fast (the curve is tilt squared).
    p.axes[kPadRightX] = 0.1f + 0.9f * 0.5f;
    g.poll(p);
    in = step(g, o);
    CHECK(in.look_yaw == doctest::Approx(-GamepadInput::kLookRate * kPadStep * 0.25f));
    // Right stick up looks up; invert Y flips it; sensitivity scales it.
    p.axes[kPadRightX] = 0.0f;
    p.axes[kPadRightY] = -1.0f;
    g.poll(p);
    CHECK(step(g, o).look_pitch == doctest::Approx(GamepadInput::kLookRate * kPadStep));
    o.invert_y = true;
    o.pad_look_sensitivity = 2.0f;
    CHECK(step(g, o).look_pitch == doctest::Approx(-2.0f * GamepadInput::kLookRate * kPadStep));
    // Sticks inside the dead zone: nothing at all.
    p.axes = {0.05f, -0.05f, 0.05f, 0.05f, -1.0f, -1.0f};
    g.poll(p);
    in = step(g, o);
    CHECK(in == game::Input{});
    // Keys and pad together stay within -1..1.
    p.axes[kPadLeftY] = -1.0f;
    g.poll(p);
    game::Input both;
    both.move_forward = 1.0f;
    g.add_to(both, kPadStep, o);
    CHECK(both.move_forward == 1.0f);
    // A disconnected pad adds nothing.
    GamepadInput none;
    none.poll(GamepadState{});
    CHECK(step(none) == game::Input{});
}

TEST_CASE("gamepad: A jumps while held, X interacts once, the trigger shoots once per pull") {
    GamepadInput g;
    GamepadState p = pad();
    p.buttons[kPadA] = true;
    p.buttons[kPadX] = true;
    g.poll(p);
    game::Input in = step(g);
    CHECK(in.jump);
    CHECK(in.interact);
    in = step(g); // the same frame's next step: still jumping, no second interact
    CHECK(in.jump);
    CHECK_FALSE(in.interact);
    g.poll(p); // held over the next frame: no new press
    CHECK_FALSE(step(g).interact);
    // A tap between two polls is not seen by polling, but a press and release across polls counts once.
    p.buttons = {};
    g.poll(p);
    CHECK_FALSE(step(g).jump);
    // Trigger: past half way fires once; held, nothing more; it must come back under 0.3 before the next.
    auto trigger = [&](float pulled) { // 0..1 → GLFW's -1..1
        p.axes[kPadRightTrigger] = pulled * 2.0f - 1.0f;
        g.poll(p);
    };
    trigger(0.4f);
    CHECK_FALSE(step(g).fire);
    trigger(0.8f);
    CHECK(step(g).fire);
    CHECK_FALSE(step(g).fire);
    trigger(1.0f);
    CHECK_FALSE(step(g).fire);
    trigger(0.4f); // eased off, not released: no new shot when pulled again
    trigger(0.9f);
    CHECK_FALSE(step(g).fire);
    trigger(0.1f);
    trigger(0.9f);
    CHECK(step(g).fire);
    // The left trigger does nothing.
    trigger(0.0f);
    p.axes[kPadLeftTrigger] = 1.0f;
    g.poll(p);
    CHECK_FALSE(step(g).fire);
}

TEST_CASE("gamepad: B and Start are edges for the menus; after a clear, held buttons wait for a release") {
    GamepadInput g;
    GamepadState p = pad();
    p.buttons[kPadStart] = true;
    g.poll(p);
    CHECK(g.take_press(kPadStart));
    CHECK_FALSE(g.take_press(kPadStart));
    g.poll(p);
    CHECK_FALSE(g.take_press(kPadStart)); // held: no new press
    p.buttons[kPadStart] = false;
    g.poll(p);
    p.buttons[kPadB] = true;
    g.poll(p);
    CHECK(g.take_press(kPadB));
    CHECK_FALSE(g.take_press(99));
    // The A that pressed Resume is still down when play starts: it must not jump until pressed again.
    p.buttons = {};
    p.buttons[kPadA] = true;
    p.axes[kPadRightTrigger] = 1.0f;
    g.poll(p);
    g.clear_latches();
    g.poll(p);
    game::Input in = step(g);
    CHECK_FALSE(in.jump);
    CHECK_FALSE(in.fire);
    CHECK_FALSE(g.held(kPadA));
    p.buttons[kPadA] = false;
    p.axes[kPadRightTrigger] = -1.0f;
    g.poll(p);
    p.buttons[kPadA] = true;
    p.axes[kPadRightTrigger] = 1.0f;
    g.poll(p);
    in = step(g);
    CHECK(in.jump);
    CHECK(in.fire);
}

TEST_CASE("player input: keys and pad together, as PlayerInput::gather adds them") {
    InputState keys;
    Options o;
    GamepadInput g;
    GamepadState p = pad();
    p.axes[kPadLeftX] = 1.0f;
    g.poll(p);
    keys.key('W', InputState::kPress);
    game::Input in = keyboard_mouse_input(keys, o, true);
    g.add_to(in, kPadStep, o);
    CHECK(in.move_forward == 1.0f);
    CHECK(in.move_right == doctest::Approx(1.0f));
}

TEST_CASE("input script: pad buttons and axes parse; bad pad lines are refused with a fix") {
    auto events = parse_input_script("10 pad a tap\n11 pad start down\n12 pad ddown up\n13 pad ly -1\n"
                                     "14 pad rt 0.5\n",
                                     "pad.txt");
    REQUIRE(events.ok());
    REQUIRE(events->size() == 5);
    CHECK((*events)[0].kind == ScriptEvent::Kind::PadButton);
    CHECK((*events)[0].code == kPadA);
    CHECK((*events)[0].action == 2);
    CHECK((*events)[1].code == kPadStart);
    CHECK((*events)[1].action == 1);
    CHECK((*events)[2].code == kPadDpadDown);
    CHECK((*events)[2].action == 0);
    CHECK((*events)[3].kind == ScriptEvent::Kind::PadAxis);
    CHECK((*events)[3].code == kPadLeftY);
    CHECK((*events)[3].x == -1.0);
    CHECK((*events)[4].code == kPadRightTrigger);
    for (const char* bad : {"1 pad z tap", "1 pad a hold", "1 pad ly", "1 pad ly 2", "1 pad rx nan",
                            "1 pad lx 0.5x", "1 pad a tap extra"}) {
        auto r = parse_input_script(bad, "pad.txt");
        CHECK_MESSAGE(!r.ok(), bad);
        if (!r.ok()) CHECK(r.error().str().find("pad.txt:1") != std::string::npos);
    }
}
