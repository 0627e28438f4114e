#pragma once
// A gamepad's state as a plain struct, mirroring GLFWgamepadstate (the SDL controller mappings GLFW ships:
// button and axis numbers mean the same on every pad), so the game's mapping (runtime/model/gamepad_input.h)
// and the tests need no window. The shell reads it from GLFW (shell/gamepad.h: poll_gamepad, checked against
// glfw3.h there) and drives the menus with it.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace ks {

// GLFW_GAMEPAD_BUTTON_* / GLFW_GAMEPAD_AXIS_*.
enum GamepadButton : int {
    kPadA,
    kPadB,
    kPadX,
    kPadY,
    kPadLeftBumper,
    kPadRightBumper,
    kPadBack,
    kPadStart,
    kPadGuide,
    kPadLeftThumb,
    kPadRightThumb,
    kPadDpadUp,
    kPadDpadRight,
    kPadDpadDown,
    kPadDpadLeft,
    kPadButtonCount
};
enum GamepadAxis : int {
    kPadLeftX,
    kPadLeftY,
    kPadRightX,
    kPadRightY,
    kPadLeftTrigger,
    kPadRightTrigger,
    kPadAxisCount
};

struct GamepadState {
    bool connected = false;
    std::array<bool, kPadButtonCount> buttons{};
    // Sticks -1..1 (y down is +1, as GLFW reports), triggers -1 (released)..1 (pulled).
    std::array<float, kPadAxisCount> axes{0.0f, 0.0f, 0.0f, 0.0f, -1.0f, -1.0f};
    bool operator==(const GamepadState&) const = default;

    bool button(int b) const { return b >= 0 && b < kPadButtonCount && buttons[static_cast<std::size_t>(b)]; }
    // An axis made safe: NaN and infinities read as rest, everything clamped to -1..1.
    float axis(int a) const {
        if (a < 0 || a >= kPadAxisCount) return 0.0f;
        const float v = axes[static_cast<std::size_t>(a)];
        const float rest = a >= kPadLeftTrigger ? -1.0f : 0.0f;
        return std::isfinite(v) ? std::clamp(v, -1.0f, 1.0f) : rest;
    }
};

} // namespace ks
