#include "player_input.h"

#define GLFW_INCLUDE_NONE
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cmath>

namespace ks::runtime {

void PlayerInput::capture(GLFWwindow* window, InputState& state) {
    if (window) {
        glfwSetInputMode(window, GLFW_CURSOR, GLFW_CURSOR_DISABLED);
        if (glfwRawMouseMotionSupported()) glfwSetInputMode(window, GLFW_RAW_MOUSE_MOTION, GLFW_TRUE);
    }
    captured_ = true;
    // The click that resumed the game must not also fire; the jump to the locked cursor is no look.
    state.clear_latches();
    if (window) {
        // The origin for the motion that follows, so that the very first movement already turns.
        double x = 0.0, y = 0.0;
        glfwGetCursorPos(window, &x, &y);
        state.cursor(x, y);
    }
}

void PlayerInput::release(GLFWwindow* window, InputState& state) {
    if (window) {
        if (glfwRawMouseMotionSupported()) glfwSetInputMode(window, GLFW_RAW_MOUSE_MOTION, GLFW_FALSE);
        glfwSetInputMode(window, GLFW_CURSOR, GLFW_CURSOR_NORMAL);
    }
    captured_ = false;
    state.clear_latches();
}

game::Input PlayerInput::gather(InputState& state, const Options& options) {
    game::Input in;
    // A tap shorter than a step still moves the player for one step.
    auto axis = [&](int a, int b) {
        const bool first = state.down_or_tapped(a), second = state.down_or_tapped(b); // both latches read
        return first || second ? 1.0f : 0.0f;
    };
    in.move_forward = axis(GLFW_KEY_W, GLFW_KEY_UP) - axis(GLFW_KEY_S, GLFW_KEY_DOWN);
    in.move_right = axis(GLFW_KEY_D, GLFW_KEY_RIGHT) - axis(GLFW_KEY_A, GLFW_KEY_LEFT);
    in.jump = state.down_or_tapped(GLFW_KEY_SPACE); // held jump re-jumps on landing, as the reference
    in.interact = state.take_press(GLFW_KEY_E);
    const bool left = state.take_click(GLFW_MOUSE_BUTTON_LEFT);
    const bool right = state.take_click(GLFW_MOUSE_BUTTON_RIGHT);
    in.fire = captured_ && (left || right);

    double dx = 0.0, dy = 0.0;
    state.take_motion(dx, dy);
    if (captured_ && std::isfinite(dx) && std::isfinite(dy))
        look_from_motion(dx, dy, options, in.look_yaw, in.look_pitch);
    return in;
}

} // namespace ks::runtime
