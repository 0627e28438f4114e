#pragma once
// Turns the window's keyboard and mouse into the game's per-step Input. Keys are GLFW key codes, which name
// physical positions (W is the key left of E on any layout). Mouse motion is read as the cursor's movement
// since the previous step, so a frame's motion spreads over the fixed steps that frame runs.
#include "game/game_types.h"
#include "options.h"

struct GLFWwindow;

namespace ks::runtime {

class PlayerInput {
  public:
    // Hides and locks the cursor (raw motion where supported) / gives it back.
    void capture(GLFWwindow* window);
    void release(GLFWwindow* window);
    bool captured() const { return captured_; }

    // The input for one fixed step. Clicks and E fire once per press.
    game::Input gather(GLFWwindow* window, const Options& options);

  private:
    bool captured_ = false;
    bool have_cursor_ = false;
    double last_x_ = 0.0, last_y_ = 0.0;
    bool fire_was_down_ = true, interact_was_down_ = true, jump_was_down_ = true;
};

} // namespace ks::runtime
