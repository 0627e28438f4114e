#include "input_events.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace ks::runtime {

static_assert(InputState::kKeys == GLFW_KEY_LAST + 1);
static_assert(InputState::kButtons == GLFW_MOUSE_BUTTON_LAST + 1);
static_assert(InputState::kPress == GLFW_PRESS && InputState::kRelease == GLFW_RELEASE);

namespace {
// GLFW callbacks take no closure; one window per process, so one bound state.
InputState* g_state = nullptr;
GLFWwindow* g_window = nullptr;
GLFWkeyfun g_prev_key = nullptr;
GLFWmousebuttonfun g_prev_button = nullptr;
GLFWcursorposfun g_prev_cursor = nullptr;
GLFWwindowfocusfun g_prev_focus = nullptr;

void on_key(GLFWwindow* w, int key, int scancode, int action, int mods) {
    if (g_state && w == g_window) g_state->key(key, action);
    if (g_prev_key) g_prev_key(w, key, scancode, action, mods);
}
void on_button(GLFWwindow* w, int button, int action, int mods) {
    if (g_state && w == g_window) g_state->button(button, action);
    if (g_prev_button) g_prev_button(w, button, action, mods);
}
void on_cursor(GLFWwindow* w, double x, double y) {
    if (g_state && w == g_window) g_state->cursor(x, y);
    if (g_prev_cursor) g_prev_cursor(w, x, y);
}
void on_focus(GLFWwindow* w, int focused) {
    // Releases that happen while another window has the focus never arrive: forget what was held.
    if (g_state && w == g_window && !focused) g_state->release_all();
    if (g_prev_focus) g_prev_focus(w, focused);
}
} // namespace

void InputEvents::install(GLFWwindow* window) {
    uninstall();
    window_ = window;
    g_state = &state_;
    g_window = window;
    g_prev_key = glfwSetKeyCallback(window, on_key);
    g_prev_button = glfwSetMouseButtonCallback(window, on_button);
    g_prev_cursor = glfwSetCursorPosCallback(window, on_cursor);
    g_prev_focus = glfwSetWindowFocusCallback(window, on_focus);
}

void InputEvents::uninstall() {
    if (!window_) return;
    // Give the window back the callbacks it had (ImGui's backend restores its own on shutdown).
    if (g_window == window_) {
        glfwSetKeyCallback(window_, g_prev_key);
        glfwSetMouseButtonCallback(window_, g_prev_button);
        glfwSetCursorPosCallback(window_, g_prev_cursor);
        glfwSetWindowFocusCallback(window_, g_prev_focus);
        g_state = nullptr;
        g_window = nullptr;
        g_prev_key = nullptr;
        g_prev_button = nullptr;
        g_prev_cursor = nullptr;
        g_prev_focus = nullptr;
    }
    window_ = nullptr;
}

void InputEvents::inject_key(int key, int action) {
    if (window_) on_key(window_, key, 0, action, 0);
}

void InputEvents::inject_button(int button, int action) {
    if (window_) on_button(window_, button, action, 0);
}

void InputEvents::inject_cursor(double x, double y) {
    if (!window_) return;
    if (glfwGetInputMode(window_, GLFW_CURSOR) == GLFW_CURSOR_DISABLED) {
        on_cursor(window_, x, y); // a virtual position: GLFW reports motion, nothing to warp
    } else {
        glfwSetCursorPos(window_, x, y); // ImGui polls the pointer, so it must really move
        on_cursor(window_, x, y);
    }
}

} // namespace ks::runtime
