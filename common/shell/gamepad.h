#pragma once
// The first connected gamepad, read through GLFW's gamepad API (glfwGetGamepadState with the SDL controller
// mappings GLFW ships: button and axis numbers mean the same on every pad) into a GamepadState
// (core/gamepad_state.h), and its menu navigation for Dear ImGui; poll_gamepad() and feed_imgui_nav() in
// gamepad.cpp are the GLFW and ImGui side.
#include "core/gamepad_state.h"

namespace ks::shell {

// The pad's state is core's (core/gamepad_state.h), so the game's mapping needs no shell; shell:: names it
// too.
using ks::GamepadAxis;
using ks::GamepadButton;
using ks::GamepadState;
using enum ks::GamepadAxis;
using enum ks::GamepadButton;

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
