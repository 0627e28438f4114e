#include "runtime/model/controls_state.h"

namespace ks::runtime {

bool finish_rebind(Options& options, ControlsState& state, int code) {
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

} // namespace ks::runtime
