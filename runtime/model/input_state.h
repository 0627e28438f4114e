#pragma once
// Keyboard and mouse as events rather than polls. At 4 frames per second a key tap or a click (xdotool's
// click sends press and release together) can start and end between two polls, and glfwGetKey would never
// see it. InputState records each key's and button's held state, a latch "went down since the game last
// asked", and the cursor's motion since the game last asked; runtime/app/input_events.h feeds it from GLFW's
// callbacks, and scripted input (--input-script) enters through the same handlers.
#include "runtime/model/key_names.h"

#include <array>
#include <cstddef>

namespace ks::runtime {

class InputState {
  public:
    static constexpr int kKeys = 349;  // GLFW_KEY_LAST + 1
    static constexpr int kButtons = 8; // GLFW_MOUSE_BUTTON_LAST + 1
    static constexpr int kPress = 1;   // GLFW_PRESS
    static constexpr int kRelease = 0; // GLFW_RELEASE

    void key(int key, int action);
    void button(int button, int action);
    // The cursor's position (window pixels; virtual and unbounded while captured).
    void cursor(double x, double y);

    bool held(int key) const;
    bool button_held(int b) const;
    // True once for each time the key went down since the last call (a tap shorter than a frame counts).
    bool take_press(int key);
    bool take_click(int b);
    // The first key, else mouse button (kMouseBase + button, key_names.h), that went down since the last
    // take; kNoKey when none did (the Controls screen waiting for the key to bind).
    int take_any_press();
    bool any_button_held() const;
    // Held now, or tapped since the last take: what a per-step "is it down" question should see.
    bool down_or_tapped(int key) { return take_press(key) || held(key); }
    // Cursor motion since the last call, in pixels.
    void take_motion(double& dx, double& dy);
    // Forget latches and motion (on capture/release: the click that resumed must not also fire).
    void clear_latches();
    // Everything up (the window lost focus: releases will not arrive).
    void release_all();

  private:
    struct Slot {
        bool held = false;
        bool pressed = false; // went down since the last take
    };
    // nullptr for GLFW_KEY_UNKNOWN (-1) and anything absurd.
    template <std::size_t N>
    static Slot* slot(std::array<Slot, N>& slots, int code) {
        return code >= 0 && static_cast<std::size_t>(code) < N ? &slots[static_cast<std::size_t>(code)]
                                                               : nullptr;
    }
    static void record(Slot* s, int action);
    static bool take(Slot* s);

    std::array<Slot, kKeys> keys_{};
    std::array<Slot, kButtons> buttons_{};
    double x_ = 0.0, y_ = 0.0, dx_ = 0.0, dy_ = 0.0;
    bool have_cursor_ = false;
};

} // namespace ks::runtime
