#pragma once
// Turns the keyboard, mouse and gamepad into the game's per-step Input. The keys are the player's bindings
// (key_bindings.h: GLFW key codes, which name physical positions, and mouse buttons); the gamepad is
// gamepad_input.h's. Reads InputState (input_events.h), fed by GLFW's
// callbacks: a key tapped or a button clicked between two steps still counts once, and the mouse motion is
// everything the cursor moved since the previous step — so a frame's motion goes into the first step that
// frame runs and the total turn does not depend on the frame rate.
#include "game/game_types.h"
#include "gamepad_input.h"
#include "input_events.h"
#include "runtime/model/options.h"

#include <cmath>

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

// Mouse motion (pixels) → the game's look input (radians; yaw positive turns left, pitch positive looks up).
inline void look_from_motion(double dx, double dy, const Options& options, float& look_yaw,
                             float& look_pitch) {
    const float k = Options::kRadiansPerPixel * options.mouse_sensitivity;
    look_yaw = -static_cast<float>(dx) * k;
    look_pitch = -static_cast<float>(dy) * k * (options.invert_y ? -1.0f : 1.0f);
}

// Is one of the action's keys (or buttons) held now or tapped since the last step? Reads every slot's latch.
inline bool action_held(InputState& state, const Bindings& b, Action a) {
    bool any = false;
    for (int code : b[a]) {
        if (code == kNoKey) continue;
        const bool down = is_mouse_code(code)
                              ? state.take_click(code - kMouseBase) || state.button_held(code - kMouseBase)
                              : state.down_or_tapped(code);
        any = any || down;
    }
    return any;
}
// Did one of the action's keys (or buttons) go down since the last call? Once per press.
inline bool action_pressed(InputState& state, const Bindings& b, Action a) {
    bool any = false;
    for (int code : b[a]) {
        if (code == kNoKey) continue;
        const bool pressed =
            is_mouse_code(code) ? state.take_click(code - kMouseBase) : state.take_press(code);
        any = any || pressed;
    }
    return any;
}

// The keyboard and mouse part of one step through the bindings; `captured`: the mouse is the game's (look and
// shots count only then).
inline game::Input keyboard_mouse_input(InputState& state, const Options& options, bool captured) {
    game::Input in;
    const Bindings& b = options.bindings;
    // A tap shorter than a step still moves the player for one step; every latch is read.
    auto axis = [&](Action plus, Action minus) {
        const float p = action_held(state, b, plus) ? 1.0f : 0.0f;
        const float m = action_held(state, b, minus) ? 1.0f : 0.0f;
        return p - m;
    };
    in.move_forward = axis(Action::Forward, Action::Back);
    in.move_right = axis(Action::Right, Action::Left);
    in.jump = action_held(state, b, Action::Jump); // held jump re-jumps on landing, as the reference
    in.interact = action_pressed(state, b, Action::Interact);
    in.fire = action_pressed(state, b, Action::Fire) && captured;
    double dx = 0.0, dy = 0.0;
    state.take_motion(dx, dy);
    if (captured && std::isfinite(dx) && std::isfinite(dy))
        look_from_motion(dx, dy, options, in.look_yaw, in.look_pitch);
    return in;
}

} // namespace ks::runtime
