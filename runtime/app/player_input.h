#pragma once
// Turns the keyboard and mouse into the game's per-step Input. Keys are GLFW key codes, which name physical
// positions (W is the key left of E on any layout). Reads InputState (input_events.h), fed by GLFW's
// callbacks: a key tapped or a button clicked between two steps still counts once, and the mouse motion is
// everything the cursor moved since the previous step — so a frame's motion goes into the first step that
// frame runs and the total turn does not depend on the frame rate.
#include "game/game_types.h"
#include "input_events.h"
#include "options.h"

struct GLFWwindow;

namespace ks::runtime {

class PlayerInput {
  public:
    // Hides and locks the cursor (raw motion where supported) / gives it back.
    void capture(GLFWwindow* window, InputState& state);
    void release(GLFWwindow* window, InputState& state);
    bool captured() const { return captured_; }

    // The input for one fixed step. Clicks and E fire once per press.
    game::Input gather(InputState& state, const Options& options);

  private:
    bool captured_ = false;
};

// Mouse motion (pixels) → the game's look input (radians; yaw positive turns left, pitch positive looks up).
inline void look_from_motion(double dx, double dy, const Options& options, float& look_yaw,
                             float& look_pitch) {
    const float k = Options::kRadiansPerPixel * options.mouse_sensitivity;
    look_yaw = -static_cast<float>(dx) * k;
    look_pitch = -static_cast<float>(dy) * k * (options.invert_y ? -1.0f : 1.0f);
}

} // namespace ks::runtime
