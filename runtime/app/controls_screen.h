#pragma once
// Options > Controls: every action with its two keys (click one, press the new key or mouse button; Esc or
// the pad's B cancels, Backspace clears the slot), keys shared by two actions in red, Reset to defaults, and
// the gamepad's layout with its look speed and dead zone. In the menus' style (menu_style.h).
#include "runtime/model/controls_state.h"
#include "shell/app_shell.h"

namespace ks::runtime {

enum class MenuAction;

// The screen; `changed` is set when an option moved this frame. Back returns MenuAction::Back.
MenuAction controls_screen(Options& options, ControlsState& state, bool& changed, const shell::Fonts& fonts,
                           float w, float h);

} // namespace ks::runtime
