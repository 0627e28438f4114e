#pragma once
// What the Controls screen (runtime/app/controls_screen.h) remembers between frames, and what the key pressed
// while a slot waits does to the bindings: Backspace clears the slot, anything else goes through rebind().
#include "runtime/model/options.h"

#include <cstddef>
#include <string>

namespace ks::runtime {

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
// slot. Returns true when the bindings changed.
bool finish_rebind(Options& options, ControlsState& state, int code);

} // namespace ks::runtime
