#pragma once
// A gamepad as the game's Input: left stick moves, right stick looks, A jumps, the right trigger shoots,
// X interacts, Start pauses; B is the menus' Back (as Esc). The pad is polled once a frame (shell/gamepad.h);
// presses are latched between polls and taken by the fixed steps, as InputState does for keys, so a tap
// counts once however many steps a frame runs. Sticks go through a radial dead zone rescaled so motion starts
// at zero past it; look uses the square of the deflection for fine aim near the centre and turns at
// kLookRate × the look sensitivity at full tilt. GL-free and header-only so the tests use it directly.
#include "game/game_types.h"
#include "runtime/model/options.h"
#include "shell/gamepad.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace ks::runtime {

struct Stick {
    float x = 0.0f, y = 0.0f;
};

// A stick's (x, y) through a radial dead zone: inside it nothing, past it the remaining travel rescaled to
// 0..1 in the same direction (so a diagonal keeps its angle); NaN reads as centred, the length is capped at
// 1, and an absurd dead zone is clamped to 0..0.9.
inline Stick apply_dead_zone(float x, float y, float dead_zone) {
    if (!std::isfinite(x) || !std::isfinite(y)) return {};
    const float dz = std::isfinite(dead_zone) ? std::clamp(dead_zone, 0.0f, 0.9f) : 0.0f;
    x = std::clamp(x, -1.0f, 1.0f);
    y = std::clamp(y, -1.0f, 1.0f);
    const float length = std::sqrt(x * x + y * y);
    if (length <= dz || length <= 0.0f) return {};
    const float scaled = (std::min(length, 1.0f) - dz) / (1.0f - dz);
    return {x / length * scaled, y / length * scaled};
}

class GamepadInput {
  public:
    static constexpr float kLookRate = 3.0f;       // radians per second at full tilt, sensitivity 1
    static constexpr float kTriggerPress = 0.5f;   // pulled past half way (0..1) fires
    static constexpr float kTriggerRelease = 0.3f; // and must come back under this before the next shot

    // Once a frame: the pad now. Buttons and the trigger that went down since the last poll are latched.
    void poll(const shell::GamepadState& pad) {
        pad_ = pad;
        for (int b = 0; b < shell::kPadButtonCount; ++b) {
            const auto i = static_cast<std::size_t>(b);
            const bool down = pad.button(b);
            if (!down) blocked_[i] = false;
            if (down && !held_[i] && !blocked_[i]) pressed_[i] = true;
            held_[i] = down;
        }
        const float trigger = (pad.axis(shell::kPadRightTrigger) + 1.0f) * 0.5f; // 0..1
        if (!trigger_down_ && trigger > kTriggerPress) {
            trigger_down_ = true;
            if (!trigger_blocked_) trigger_pressed_ = true;
        } else if (trigger_down_ && trigger < kTriggerRelease) {
            trigger_down_ = false;
            trigger_blocked_ = false;
        }
    }

    // True once per press since the last take (menus: B, Start).
    bool take_press(int button) {
        if (button < 0 || button >= shell::kPadButtonCount) return false;
        const auto i = static_cast<std::size_t>(button);
        const bool was = pressed_[i];
        pressed_[i] = false;
        return was;
    }
    // Held now (and not held over from before the last clear_latches()).
    bool held(int button) const {
        if (button < 0 || button >= shell::kPadButtonCount) return false;
        const auto i = static_cast<std::size_t>(button);
        return held_[i] && !blocked_[i];
    }

    // Forget presses, and ignore what is held until it is let go: the A that pressed Resume must not jump,
    // a trigger still pulled must not shoot.
    void clear_latches() {
        pressed_.fill(false);
        blocked_ = held_;
        trigger_pressed_ = false;
        trigger_blocked_ = trigger_down_;
    }

    // The pad's part of one fixed step of `dt` seconds, added to `in` (movement summed with the keys' and
    // kept in -1..1, look added, buttons or-ed).
    void add_to(game::Input& in, float dt, const Options& o) {
        if (!pad_.connected) return;
        const Stick move =
            apply_dead_zone(pad_.axis(shell::kPadLeftX), pad_.axis(shell::kPadLeftY), o.pad_dead_zone);
        in.move_forward = std::clamp(in.move_forward - move.y, -1.0f, 1.0f); // stick up is -y
        in.move_right = std::clamp(in.move_right + move.x, -1.0f, 1.0f);
        const Stick look =
            apply_dead_zone(pad_.axis(shell::kPadRightX), pad_.axis(shell::kPadRightY), o.pad_dead_zone);
        const float tilt = std::sqrt(look.x * look.x + look.y * look.y); // 0..1: the curve is tilt²
        const float rate =
            kLookRate * o.pad_look_sensitivity * tilt * (std::isfinite(dt) ? std::max(dt, 0.0f) : 0.0f);
        in.look_yaw += -look.x * rate;
        in.look_pitch += -look.y * rate * (o.invert_y ? -1.0f : 1.0f);
        const bool jump_tap = take_press(shell::kPadA);
        in.jump = in.jump || held(shell::kPadA) || jump_tap;
        in.interact = in.interact || take_press(shell::kPadX);
        in.fire = in.fire || trigger_pressed_;
        trigger_pressed_ = false;
    }

    const shell::GamepadState& state() const { return pad_; }

  private:
    shell::GamepadState pad_;
    std::array<bool, shell::kPadButtonCount> held_{}, pressed_{}, blocked_{};
    bool trigger_down_ = false, trigger_pressed_ = false, trigger_blocked_ = false;
};

} // namespace ks::runtime
