#include "player_input.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cmath>

namespace ks::runtime {

void PlayerInput::capture(GLFWwindow* window) {
    glfwSetInputMode(window, GLFW_CURSOR, GLFW_CURSOR_DISABLED);
    if (glfwRawMouseMotionSupported()) glfwSetInputMode(window, GLFW_RAW_MOUSE_MOTION, GLFW_TRUE);
    captured_ = true;
    have_cursor_ = false;
    // The click that resumed the game must not also fire.
    fire_was_down_ = interact_was_down_ = jump_was_down_ = true;
}

void PlayerInput::release(GLFWwindow* window) {
    if (glfwRawMouseMotionSupported()) glfwSetInputMode(window, GLFW_RAW_MOUSE_MOTION, GLFW_FALSE);
    glfwSetInputMode(window, GLFW_CURSOR, GLFW_CURSOR_NORMAL);
    captured_ = false;
}

game::Input PlayerInput::gather(GLFWwindow* window, const Options& options) {
    game::Input in;
    auto down = [&](int key) { return glfwGetKey(window, key) == GLFW_PRESS; };
    in.move_forward = (down(GLFW_KEY_W) || down(GLFW_KEY_UP) ? 1.0f : 0.0f) -
                      (down(GLFW_KEY_S) || down(GLFW_KEY_DOWN) ? 1.0f : 0.0f);
    in.move_right = (down(GLFW_KEY_D) || down(GLFW_KEY_RIGHT) ? 1.0f : 0.0f) -
                    (down(GLFW_KEY_A) || down(GLFW_KEY_LEFT) ? 1.0f : 0.0f);
    const bool jump = down(GLFW_KEY_SPACE);
    const bool interact = down(GLFW_KEY_E);
    const bool fire = captured_ && (glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS ||
                                    glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS);
    in.jump = jump; // held jump re-jumps on landing, as the reference
    in.interact = interact && !interact_was_down_;
    in.fire = fire && !fire_was_down_;
    jump_was_down_ = jump;
    interact_was_down_ = interact;
    fire_was_down_ = fire;

    if (captured_) {
        double x = 0.0, y = 0.0;
        glfwGetCursorPos(window, &x, &y);
        if (have_cursor_ && std::isfinite(x) && std::isfinite(y)) {
            const float k = Options::kRadiansPerPixel * options.mouse_sensitivity;
            in.look_yaw = -static_cast<float>(x - last_x_) * k;
            in.look_pitch = -static_cast<float>(y - last_y_) * k * (options.invert_y ? -1.0f : 1.0f);
        }
        last_x_ = x;
        last_y_ = y;
        have_cursor_ = true;
    }
    return in;
}

} // namespace ks::runtime
