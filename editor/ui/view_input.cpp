#include "ui/view_input.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace ks::editor::ui {

ViewInput read_view_input(GLFWwindow* window, bool hovered, Vec2 mouse_in_viewport, float wheel) {
    auto key = [&](int k) { return glfwGetKey(window, k) == GLFW_PRESS; };
    ViewInput in;
    in.hovered = hovered;
    in.mouse = mouse_in_viewport;
    in.left = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    in.right = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
    in.middle = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
    in.alt = key(GLFW_KEY_LEFT_ALT) || key(GLFW_KEY_RIGHT_ALT);
    in.wheel = wheel;
    // GLFW key codes name positions on a US layout, whatever the user's layout is (AZERTY's Z is W here).
    in.forward = key(GLFW_KEY_W);
    in.back = key(GLFW_KEY_S);
    in.strafe_right = key(GLFW_KEY_D);
    in.strafe_left = key(GLFW_KEY_A);
    in.up = key(GLFW_KEY_E);
    in.down = key(GLFW_KEY_Q);
    in.boost = key(GLFW_KEY_LEFT_SHIFT);
    return in;
}

} // namespace ks::editor::ui
