#include "player_input.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace ks::runtime {

// key_names.h mirrors GLFW's codes so that the tests need no GLFW.
static_assert(kKeyEscape == GLFW_KEY_ESCAPE && kLastKeyCode == GLFW_KEY_LAST && kKeySpace == GLFW_KEY_SPACE);
static_assert(kKeyUp == GLFW_KEY_UP && kKeyDown == GLFW_KEY_DOWN && kKeyLeft == GLFW_KEY_LEFT &&
              kKeyRight == GLFW_KEY_RIGHT);
static_assert(kMouseButtons == GLFW_MOUSE_BUTTON_LAST + 1);
static_assert(GLFW_KEY_F1 == 290 && GLFW_KEY_F25 == 314 && GLFW_KEY_KP_0 == 320 && GLFW_KEY_KP_EQUAL == 336);
static_assert(GLFW_KEY_LEFT_SHIFT == 340 && GLFW_KEY_MENU == 348 && GLFW_KEY_PAGE_UP == 266 &&
              GLFW_KEY_CAPS_LOCK == 280 && GLFW_KEY_PAUSE == 284 && GLFW_KEY_GRAVE_ACCENT == 96);

void PlayerInput::capture(GLFWwindow* window, InputState& state) {
    if (window) {
        glfwSetInputMode(window, GLFW_CURSOR, GLFW_CURSOR_DISABLED);
        if (glfwRawMouseMotionSupported()) glfwSetInputMode(window, GLFW_RAW_MOUSE_MOTION, GLFW_TRUE);
    }
    captured_ = true;
    // The click that resumed the game must not also fire; the jump to the locked cursor is no look.
    state.clear_latches();
    pad_.clear_latches();
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
    pad_.clear_latches();
}

game::Input PlayerInput::gather(InputState& state, const Options& options, float dt) {
    game::Input in = keyboard_mouse_input(state, options, captured_);
    pad_.add_to(in, dt, options);
    return in;
}

} // namespace ks::runtime
