#pragma once
// Turns the keyboard, mouse and gamepad into the game's per-step Input: the keys and mouse through the
// bindings (runtime/model/keyboard_mouse_input.h), the pad through runtime/model/gamepad_input.h, and the
// cursor captured while playing.
#include "game/game_types.h"
#include "input_events.h"
#include "runtime/model/gamepad_input.h"
#include "runtime/model/keyboard_mouse_input.h"
#include "runtime/model/options.h"

struct GLFWwindow;

namespace ks::runtime {

class PlayerInput {
  public:
    // Hides and locks the cursor (raw motion where supported) / gives it back.
    void capture(GLFWwindow* window, InputState& state);
    void release(GLFWwindow* window, InputState& state);
    bool captured() const { return captured_; }

    // The input for one fixed step of `dt` seconds, keys and mouse plus the pad. Shots and Interact fire once
    // per press.
    game::Input gather(InputState& state, const Options& options, float dt);

    // The gamepad (polled once a frame by the app; its latches are cleared with the keys' on capture and
    // release).
    GamepadInput& pad() { return pad_; }

  private:
    bool captured_ = false;
    GamepadInput pad_;
};

} // namespace ks::runtime
