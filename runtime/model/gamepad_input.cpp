#include "runtime/model/gamepad_input.h"

#include <algorithm>
#include <cmath>

namespace ks::runtime {

Stick apply_dead_zone(float x, float y, float dead_zone) {
    if (!std::isfinite(x) || !std::isfinite(y)) return {};
    const float dz = std::isfinite(dead_zone) ? std::clamp(dead_zone, 0.0f, 0.9f) : 0.0f;
    x = std::clamp(x, -1.0f, 1.0f);
    y = std::clamp(y, -1.0f, 1.0f);
    const float length = std::sqrt(x * x + y * y);
    if (length <= dz || length <= 0.0f) return {};
    const float scaled = (std::min(length, 1.0f) - dz) / (1.0f - dz);
    return {x / length * scaled, y / length * scaled};
}

void GamepadInput::poll(const GamepadState& pad) {
    pad_ = pad;
    for (int b = 0; b < kPadButtonCount; ++b) {
        const auto i = static_cast<std::size_t>(b);
        const bool down = pad.button(b);
        if (!down) blocked_[i] = false;
        if (down && !held_[i] && !blocked_[i]) pressed_[i] = true;
        held_[i] = down;
    }
    const float trigger = (pad.axis(kPadRightTrigger) + 1.0f) * 0.5f; // 0..1
    if (!trigger_down_ && trigger > kTriggerPress) {
        trigger_down_ = true;
        if (!trigger_blocked_) trigger_pressed_ = true;
    } else if (trigger_down_ && trigger < kTriggerRelease) {
        trigger_down_ = false;
        trigger_blocked_ = false;
    }
}

bool GamepadInput::take_press(int button) {
    if (button < 0 || button >= kPadButtonCount) return false;
    const auto i = static_cast<std::size_t>(button);
    const bool was = pressed_[i];
    pressed_[i] = false;
    return was;
}

bool GamepadInput::held(int button) const {
    if (button < 0 || button >= kPadButtonCount) return false;
    const auto i = static_cast<std::size_t>(button);
    return held_[i] && !blocked_[i];
}

void GamepadInput::clear_latches() {
    pressed_.fill(false);
    blocked_ = held_;
    trigger_pressed_ = false;
    trigger_blocked_ = trigger_down_;
}

void GamepadInput::add_to(game::Input& in, float dt, const Options& o) {
    if (!pad_.connected) return;
    const Stick move = apply_dead_zone(pad_.axis(kPadLeftX), pad_.axis(kPadLeftY), o.pad_dead_zone);
    in.move_forward = std::clamp(in.move_forward - move.y, -1.0f, 1.0f); // stick up is -y
    in.move_right = std::clamp(in.move_right + move.x, -1.0f, 1.0f);
    const Stick look = apply_dead_zone(pad_.axis(kPadRightX), pad_.axis(kPadRightY), o.pad_dead_zone);
    const float tilt = std::sqrt(look.x * look.x + look.y * look.y); // 0..1: the curve is tilt²
    const float rate =
        kLookRate * o.pad_look_sensitivity * tilt * (std::isfinite(dt) ? std::max(dt, 0.0f) : 0.0f);
    in.look_yaw += -look.x * rate;
    in.look_pitch += -look.y * rate * (o.invert_y ? -1.0f : 1.0f);
    const bool jump_tap = take_press(kPadA);
    in.jump = in.jump || held(kPadA) || jump_tap;
    in.interact = in.interact || take_press(kPadX);
    in.fire = in.fire || trigger_pressed_;
    trigger_pressed_ = false;
}

} // namespace ks::runtime
