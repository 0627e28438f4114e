#include "shell/key_taps.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <array>
#include <vector>

namespace ks::shell {
namespace {

struct HeldRelease {
    int key, scancode, mods;
};

// GLFW callbacks take no closure; one window per process, so one state.
GLFWwindow* g_window = nullptr;
GLFWkeyfun g_imgui_key = nullptr;               // the callback this one sits in front of (ImGui's backend)
std::array<bool, GLFW_KEY_LAST + 1> g_unseen{}; // pressed since the last frame began
std::vector<HeldRelease> g_held;                // releases of keys no frame has seen down yet

void on_key(GLFWwindow* window, int key, int scancode, int action, int mods) {
    const bool known = key >= 0 && key <= GLFW_KEY_LAST;
    if (known && action == GLFW_PRESS) {
        // Pressed again before the held release went out: it is down, and stays so.
        std::erase_if(g_held, [key](const HeldRelease& r) { return r.key == key; });
        g_unseen[static_cast<size_t>(key)] = true;
    } else if (known && action == GLFW_RELEASE && g_unseen[static_cast<size_t>(key)]) {
        g_held.push_back({key, scancode, mods});
        return;
    }
    if (g_imgui_key) g_imgui_key(window, key, scancode, action, mods);
}

} // namespace

void install_key_taps(GLFWwindow* window) {
    g_window = window;
    g_imgui_key = glfwSetKeyCallback(window, on_key);
    g_unseen.fill(false);
    g_held.clear();
}

void uninstall_key_taps(GLFWwindow* window) {
    if (g_window != window) return;
    glfwSetKeyCallback(window, g_imgui_key);
    g_window = nullptr;
    g_imgui_key = nullptr;
    g_held.clear();
}

void release_seen_taps() {
    g_unseen.fill(false);
    if (g_held.empty() || !g_window) return;
    const std::vector<HeldRelease> held = std::move(g_held);
    g_held.clear();
    for (const HeldRelease& r : held)
        if (g_imgui_key) g_imgui_key(g_window, r.key, r.scancode, GLFW_RELEASE, r.mods);
    glfwPostEmptyEvent(); // a frame soon, to see the key up: held down while idle, it would start repeating
}

} // namespace ks::shell
