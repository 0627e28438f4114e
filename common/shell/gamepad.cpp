#include "shell/gamepad.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

namespace ks::shell {

static_assert(kPadA == GLFW_GAMEPAD_BUTTON_A && kPadStart == GLFW_GAMEPAD_BUTTON_START);
static_assert(kPadDpadUp == GLFW_GAMEPAD_BUTTON_DPAD_UP && kPadDpadLeft == GLFW_GAMEPAD_BUTTON_DPAD_LEFT);
static_assert(kPadButtonCount == GLFW_GAMEPAD_BUTTON_LAST + 1 && kPadAxisCount == GLFW_GAMEPAD_AXIS_LAST + 1);
static_assert(kPadLeftY == GLFW_GAMEPAD_AXIS_LEFT_Y && kPadRightTrigger == GLFW_GAMEPAD_AXIS_RIGHT_TRIGGER);

void poll_gamepad(GamepadState& out) {
    out = GamepadState{};
    for (int j = GLFW_JOYSTICK_1; j <= GLFW_JOYSTICK_LAST; ++j) {
        GLFWgamepadstate raw;
        if (!glfwJoystickIsGamepad(j) || !glfwGetGamepadState(j, &raw)) continue;
        out.connected = true;
        for (int b = 0; b < kPadButtonCount; ++b)
            out.buttons[static_cast<std::size_t>(b)] = raw.buttons[b] == GLFW_PRESS;
        for (int a = 0; a < kPadAxisCount; ++a) out.axes[static_cast<std::size_t>(a)] = raw.axes[a];
        return;
    }
}

void feed_imgui_nav(const GamepadState& pad) {
    ImGuiIO& io = ImGui::GetIO();
    if (io.ConfigFlags & ImGuiConfigFlags_NavEnableGamepad) {
        const GamepadNav n = gamepad_nav(pad);
        for (float& v : io.NavInputs) v = 0.0f;
        auto set = [&](ImGuiNavInput input, bool on) { io.NavInputs[input] = on ? 1.0f : 0.0f; };
        set(ImGuiNavInput_Activate, n.activate);
        set(ImGuiNavInput_Cancel, n.cancel);
        set(ImGuiNavInput_DpadUp, n.up);
        set(ImGuiNavInput_DpadDown, n.down);
        set(ImGuiNavInput_DpadLeft, n.left);
        set(ImGuiNavInput_DpadRight, n.right);
        set(ImGuiNavInput_FocusPrev, n.focus_prev);
        set(ImGuiNavInput_FocusNext, n.focus_next);
        if (pad.connected)
            io.BackendFlags |= ImGuiBackendFlags_HasGamepad;
        else
            io.BackendFlags &= ~ImGuiBackendFlags_HasGamepad;
    }
    if ((io.ConfigFlags & ImGuiConfigFlags_NavEnableKeyboard) &&
        (io.KeysDown[GLFW_KEY_ENTER] || io.KeysDown[GLFW_KEY_KP_ENTER]))
        io.NavInputs[ImGuiNavInput_Activate] = 1.0f;
}

} // namespace ks::shell
