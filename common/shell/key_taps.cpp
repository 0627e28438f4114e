#include "shell/key_taps.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <array>
#include <deque>

namespace ks::shell {
namespace {

struct KeyEvent {
    int key, scancode, action, mods;
};

// GLFW callbacks take no closure; one window per process, so one state.
GLFWwindow* g_window = nullptr;
GLFWkeyfun g_imgui_key = nullptr;                // the callback this one sits in front of (ImGui's backend)
std::array<bool, GLFW_KEY_LAST + 1> g_changed{}; // pressed or released since the last frame began
bool g_any_changed = false;                      // some key was
std::deque<KeyEvent> g_waiting;                  // in arrival order, for a later frame

bool known(int key) {
    return key >= 0 && key <= GLFW_KEY_LAST;
}

// Whether the next frame could not tell the event apart from what it already gets: a key changes once a
// frame (a tap's release waits for the frame that sees it pressed), and a release waits while any key
// changed this frame (a Ctrl let go in the frame D was pressed would make it see a plain D). Presses of
// different keys go together (a chord).
bool too_soon(const KeyEvent& e) {
    if (e.action == GLFW_RELEASE) return g_any_changed;
    return e.action == GLFW_PRESS && g_changed[static_cast<size_t>(e.key)];
}

void deliver(const KeyEvent& e) {
    if (e.action != GLFW_REPEAT) g_changed[static_cast<size_t>(e.key)] = g_any_changed = true;
    if (g_imgui_key && g_window) g_imgui_key(g_window, e.key, e.scancode, e.action, e.mods);
}

void on_key(GLFWwindow* window, int key, int scancode, int action, int mods) {
    const KeyEvent e{key, scancode, action, mods};
    // Behind a waiting event everything waits, so events keep their order.
    if (window == g_window && known(key) && (!g_waiting.empty() || too_soon(e))) {
        g_waiting.push_back(e);
        return;
    }
    if (window == g_window && known(key)) {
        deliver(e);
    } else if (g_imgui_key) {
        g_imgui_key(window, key, scancode, action, mods);
    }
}

} // namespace

void install_key_taps(GLFWwindow* window) {
    g_window = window;
    g_imgui_key = glfwSetKeyCallback(window, on_key);
    g_changed.fill(false);
    g_any_changed = false;
    g_waiting.clear();
}

void uninstall_key_taps(GLFWwindow* window) {
    if (g_window != window) return;
    glfwSetKeyCallback(window, g_imgui_key);
    g_window = nullptr;
    g_imgui_key = nullptr;
    g_waiting.clear();
}

void release_seen_taps() {
    g_changed.fill(false);
    g_any_changed = false;
    // In order, as many as the next frame can tell apart.
    while (!g_waiting.empty() && !too_soon(g_waiting.front())) {
        deliver(g_waiting.front());
        g_waiting.pop_front();
    }
    if (g_any_changed) glfwPostEmptyEvent(); // that frame soon: a key held down while idle would repeat
}

} // namespace ks::shell
