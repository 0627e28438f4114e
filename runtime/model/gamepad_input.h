#pragma once
// A gamepad as the game's Input: left stick moves, right stick looks, A jumps, the right trigger shoots,
// X interacts, Start pauses; B is the menus' Back (as Esc). The pad is polled once a frame (shell/gamepad.h);
// presses are latched between polls and taken by the fixed steps, as InputState does for keys, so a tap
// counts once however many steps a frame runs. Sticks go through a radial dead zone rescaled so motion starts
// at zero past it; look uses the square of the deflection for fine aim near the centre and turns at
// kLookRate × the look sensitivity at full tilt.
#include "core/gamepad_state.h"
#include "game/game_types.h"
#include "runtime/model/options.h"

#include <array>

namespace ks::runtime {

struct Stick {
    float x = 0.0f, y = 0.0f;
};

// A stick's (x, y) through a radial dead zone: inside it nothing, past it the remaining travel rescaled to
// 0..1 in the same direction (so a diagonal keeps its angle); NaN reads as centred, the length is capped at
// 1, and an absurd dead zone is clamped to 0..0.9.
Stick apply_dead_zone(float x, float y, float dead_zone);

class GamepadInput {
  public:
    static constexpr float kLookRate = 3.0f;       // radians per second at full tilt, sensitivity 1
    static constexpr float kTriggerPress = 0.5f;   // pulled past half way (0..1) fires
    static constexpr float kTriggerRelease = 0.3f; // and must come back under this before the next shot

    // Once a frame: the pad now. Buttons and the trigger that went down since the last poll are latched.
    void poll(const GamepadState& pad);

    // True once per press since the last take (menus: B, Start).
    bool take_press(int button);

    // Held now (and not held over from before the last clear_latches()).
    bool held(int button) const;

    // Forget presses, and ignore what is held until it is let go: the A that pressed Resume must not jump,
    // a trigger still pulled must not shoot.
    void clear_latches();

    // The pad's part of one fixed step of `dt` seconds, added to `in` (movement summed with the keys' and
    // kept in -1..1, look added, buttons or-ed).
    void add_to(game::Input& in, float dt, const Options& o);

    const GamepadState& state() const { return pad_; }

  private:
    GamepadState pad_;
    std::array<bool, kPadButtonCount> held_{}, pressed_{}, blocked_{};
    bool trigger_down_ = false, trigger_pressed_ = false, trigger_blocked_ = false;
};

} // namespace ks::runtime
