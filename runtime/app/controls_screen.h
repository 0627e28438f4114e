#pragma once
// Options > Controls: every action with its two keys (click one, press the new key or mouse button; Esc or
// the pad's B cancels, Backspace clears the slot), keys shared by two actions in red, Reset to defaults, and
// the gamepad's layout with its look speed and dead zone. In the menus' style (menu_style.h).
#include "runtime/model/key_bindings.h"
#include "runtime/model/options.h"
#include "shell/app_shell.h"

#include <cstddef>
#include <string>

namespace ks::runtime {

enum class MenuAction;

// What the Controls screen remembers between frames.
struct ControlsState {
    int waiting_action = -1; // the action whose slot waits for a key, -1 when none
    std::size_t waiting_slot = 0;
    bool hold_mouse = false; // the click that bound a mouse button is still down: ImGui must not see it
    std::string message;     // the last rebind's outcome ("Space moved from Jump, ...")
    bool waiting() const { return waiting_action >= 0; }
    void cancel() {
        waiting_action = -1;
        message.clear();
    }
};

// Applies `code` (a key or kMouseBase + button pressed while waiting; kNoKey: nothing yet) to the waiting
// slot: Backspace clears it, anything else goes through rebind(). Returns true when the bindings changed.
inline bool finish_rebind(Options& options, ControlsState& state, int code) {
    constexpr int kBackspace = 259; // GLFW_KEY_BACKSPACE
    if (!state.waiting() || code == kNoKey) return false;
    const auto action = static_cast<Action>(state.waiting_action);
    state.waiting_action = -1;
    if (code == kBackspace) {
        options.bindings[action][state.waiting_slot] = kNoKey;
        state.message = std::string(action_info(action).label) + ": slot cleared.";
        return true;
    }
    const RebindResult r = rebind(options.bindings, action, state.waiting_slot, code);
    state.message = r.message;
    state.hold_mouse = is_mouse_code(code);
    return r.accepted;
}

// The screen; `changed` is set when an option moved this frame. Back returns MenuAction::Back.
MenuAction controls_screen(Options& options, ControlsState& state, bool& changed, const shell::Fonts& fonts,
                           float w, float h);

} // namespace ks::runtime
