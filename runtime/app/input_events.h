#pragma once
// GLFW's keyboard, mouse and focus callbacks into an InputState (runtime/model/input_state.h: why events
// rather than polls), chained to ImGui's backend so the menus still see everything. Scripted input
// (--input-script) enters through the same handlers.
#include "runtime/model/input_state.h"

struct GLFWwindow;

namespace ks::runtime {

// Binds one InputState to a window's GLFW callbacks, chaining to the callbacks installed before (ImGui's).
// One window per process (GLFW callbacks carry no user data here: ImGui's backend owns the user pointer).
class InputEvents {
  public:
    InputEvents() = default;
    InputEvents(const InputEvents&) = delete;
    InputEvents& operator=(const InputEvents&) = delete;
    ~InputEvents() { uninstall(); }

    void install(GLFWwindow* window);
    void uninstall();
    InputState& state() { return state_; }

    // Synthetic events through the same path as GLFW's (the previous callbacks — ImGui — see them too).
    void inject_key(int key, int action);
    void inject_button(int button, int action);
    // Moves the cursor: warps the real pointer when free (ImGui polls it), adds motion when captured.
    void inject_cursor(double x, double y);

  private:
    GLFWwindow* window_ = nullptr;
    InputState state_;
};

} // namespace ks::runtime
