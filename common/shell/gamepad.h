#pragma once
// The first connected gamepad, read through GLFW's gamepad API (glfwGetGamepadState with the SDL controller
// mappings GLFW ships: button and axis numbers mean the same on every pad), and its menu navigation for
// Dear ImGui. GamepadState mirrors GLFWgamepadstate as a plain struct so the game's mapping and the tests
// need no window; poll_gamepad() and feed_imgui_nav() in gamepad.cpp are the GLFW and ImGui side.
#include <algorithm>
#include <array>
#include <cmath>

namespace ks::shell {

// GLFW_GAMEPAD_BUTTON_* / GLFW_GAMEPAD_AXIS_* (checked against glfw3.h in gamepad.cpp).
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

// What the pad asks of the menus this frame: A activates, B goes back, the d-pad or the left stick (past
// half way) moves the highlight, the bumpers switch focus.
struct GamepadNav {
    bool activate = false, cancel = false;
    bool up = false, down = false, left = false, right = false;
    bool focus_prev = false, focus_next = false;
    bool operator==(const GamepadNav&) const = default;
};
inline GamepadNav gamepad_nav(const GamepadState& s) {
    GamepadNav n;
    if (!s.connected) return n;
    constexpr float kStick = 0.5f;
    n.activate = s.button(kPadA);
    n.cancel = s.button(kPadB);
    n.up = s.button(kPadDpadUp) || s.axis(kPadLeftY) < -kStick;
    n.down = s.button(kPadDpadDown) || s.axis(kPadLeftY) > kStick;
    n.left = s.button(kPadDpadLeft) || s.axis(kPadLeftX) < -kStick;
    n.right = s.button(kPadDpadRight) || s.axis(kPadLeftX) > kStick;
    n.focus_prev = s.button(kPadLeftBumper);
    n.focus_next = s.button(kPadRightBumper);
    return n;
}

// Reads the first joystick GLFW knows as a gamepad into `out` (connected = false when there is none).
void poll_gamepad(GamepadState& out);
// Between ImGui_ImplGlfw_NewFrame() and ImGui::NewFrame(): when the app enabled ImGuiConfigFlags_NavEnable-
// Gamepad, replaces the backend's raw-joystick guesses in io.NavInputs with gamepad_nav(); when it enabled
// NavEnableKeyboard, Enter activates the highlighted item as Space does (ImGui 1.86 maps Enter to text
// input only).
void feed_imgui_nav(const GamepadState& pad);

} // namespace ks::shell
