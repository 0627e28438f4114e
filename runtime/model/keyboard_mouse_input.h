#pragma once
// The keyboard and mouse as the game's per-step Input, through the player's bindings (key_bindings.h: GLFW
// key codes, which name physical positions, and mouse buttons), read from an InputState (input_state.h): a
// key tapped or a button clicked between two steps still counts once, and the mouse motion is everything the
// cursor moved since the previous step — so a frame's motion goes into the first step that frame runs and
// the total turn does not depend on the frame rate. runtime/app/player_input.h adds the gamepad's part.
#include "game/game_types.h"
#include "runtime/model/input_state.h"
#include "runtime/model/options.h"

namespace ks::runtime {

// Mouse motion (pixels) → the game's look input (radians; yaw positive turns left, pitch positive looks up).
void look_from_motion(double dx, double dy, const Options& options, float& look_yaw, float& look_pitch);

// Is one of the action's keys (or buttons) held now or tapped since the last step? Reads every slot's latch.
bool action_held(InputState& state, const Bindings& b, Action a);
// Did one of the action's keys (or buttons) go down since the last call? Once per press.
bool action_pressed(InputState& state, const Bindings& b, Action a);

// The keyboard and mouse part of one step through the bindings; `captured`: the mouse is the game's (look and
// shots count only then). Shots and Interact fire once per press.
game::Input keyboard_mouse_input(InputState& state, const Options& options, bool captured);

} // namespace ks::runtime
