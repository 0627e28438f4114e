// The menus' navigation the shell feeds to ImGui from a pad (shell/gamepad.h's gamepad_nav), from synthetic
// GamepadState: the d-pad, the left stick past half way, A, B and the bumpers.
#include "shell/gamepad.h"

#include <doctest/doctest.h>

#include <limits>

using namespace ks;

namespace {
shell::GamepadState pad() {
    shell::GamepadState s;
    s.connected = true;
    return s;
}
} // namespace

TEST_CASE("gamepad: the menus' navigation from the d-pad, the left stick, A, B and the bumpers") {
    GamepadState p = pad();
    CHECK(shell::gamepad_nav(p) == shell::GamepadNav{});
    p.buttons[shell::kPadDpadDown] = true;
    p.buttons[shell::kPadA] = true;
    shell::GamepadNav n = shell::gamepad_nav(p);
    CHECK(n.down);
    CHECK(n.activate);
    CHECK_FALSE(n.up);
    p.buttons = {};
    p.axes[shell::kPadLeftY] = -0.8f; // stick up
    p.axes[shell::kPadLeftX] = 0.3f;  // a little right: under the threshold
    n = shell::gamepad_nav(p);
    CHECK(n.up);
    CHECK_FALSE(n.right);
    p.axes[shell::kPadLeftY] = std::numeric_limits<float>::quiet_NaN();
    p.buttons[shell::kPadB] = true;
    p.buttons[shell::kPadRightBumper] = true;
    n = shell::gamepad_nav(p);
    CHECK_FALSE(n.up);
    CHECK_FALSE(n.down);
    CHECK(n.cancel);
    CHECK(n.focus_next);
    p.connected = false;
    CHECK(shell::gamepad_nav(p) == shell::GamepadNav{});
}
