#include "runtime/model/keyboard_mouse_input.h"

#include <cmath>

namespace ks::runtime {

void look_from_motion(double dx, double dy, const Options& options, float& look_yaw, float& look_pitch) {
    const float k = Options::kRadiansPerPixel * options.mouse_sensitivity;
    look_yaw = -static_cast<float>(dx) * k;
    look_pitch = -static_cast<float>(dy) * k * (options.invert_y ? -1.0f : 1.0f);
}

bool action_held(InputState& state, const Bindings& b, Action a) {
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

bool action_pressed(InputState& state, const Bindings& b, Action a) {
    bool any = false;
    for (int code : b[a]) {
        if (code == kNoKey) continue;
        const bool pressed =
            is_mouse_code(code) ? state.take_click(code - kMouseBase) : state.take_press(code);
        any = any || pressed;
    }
    return any;
}

game::Input keyboard_mouse_input(InputState& state, const Options& options, bool captured) {
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
