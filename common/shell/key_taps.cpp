#include "shell/key_taps.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
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
std::deque<KeyEvent> g_waiting;                  // in arrival order: each waits for its key's next frame

bool known(int key) {
    return key >= 0 && key <= GLFW_KEY_LAST;
}

// Hands the event to ImGui; a press or release is the key's one change this frame.
void deliver(const KeyEvent& e) {
    if (known(e.key) && e.action != GLFW_REPEAT) g_changed[static_cast<size_t>(e.key)] = true;
    if (g_imgui_key && g_window) g_imgui_key(g_window, e.key, e.scancode, e.action, e.mods);
}

void on_key(GLFWwindow* window, int key, int scancode, int action, int mods) {
    const KeyEvent e{key, scancode, action, mods};
    // A second change of a key before a frame has seen the first waits; so does everything after a waiting
    // event, so that a Ctrl let go after a tapped D is let go after it.
    if (window == g_window && known(key) && (!g_waiting.empty() || g_changed[static_cast<size_t>(key)])) {
        g_waiting.push_back(e);
        return;
    }
    if (window == g_window) {
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
    // In order, each key's next change, up to the first key that already changed: the next frame sees them.
    while (!g_waiting.empty() && !g_changed[static_cast<size_t>(g_waiting.front().key)]) {
        deliver(g_waiting.front());
        g_waiting.pop_front();
    }
    if (!g_waiting.empty() || std::any_of(g_changed.begin(), g_changed.end(), [](bool c) { return c; }))
        glfwPostEmptyEvent(); // a frame soon: a key held down while idle would start repeating
}

} // namespace ks::shell
