#pragma once
// Keyboard and mouse as events rather than polls. At 4 frames per second a key tap or a click (xdotool's
// click sends press and release together) can start and end between two polls, and glfwGetKey would never
// see it. GLFW's callbacks — chained to ImGui's backend, so the menus still see everything — record each
// key's and button's held state, a latch "went down since the game last asked", and the cursor's motion
// since the game last asked. Scripted input (--input-script) enters through the same handlers.
// Header-only state (InputState) so tests use it without a window; input_events.cpp binds it to GLFW.
#include "runtime/model/key_names.h"

#include <array>

struct GLFWwindow;

namespace ks::runtime {

class InputState {
  public:
    static constexpr int kKeys = 349;  // GLFW_KEY_LAST + 1
    static constexpr int kButtons = 8; // GLFW_MOUSE_BUTTON_LAST + 1
    static constexpr int kPress = 1;   // GLFW_PRESS
    static constexpr int kRelease = 0; // GLFW_RELEASE

    void key(int key, int action) { record(slot(keys_, key), action); }
    void button(int button, int action) { record(slot(buttons_, button), action); }
    // The cursor's position (window pixels; virtual and unbounded while captured).
    void cursor(double x, double y) {
        if (have_cursor_) {
            dx_ += x - x_;
            dy_ += y - y_;
        }
        x_ = x;
        y_ = y;
        have_cursor_ = true;
    }

    bool held(int key) const { return key >= 0 && key < kKeys && keys_[static_cast<std::size_t>(key)].held; }
    bool button_held(int b) const {
        return b >= 0 && b < kButtons && buttons_[static_cast<std::size_t>(b)].held;
    }
    // True once for each time the key went down since the last call (a tap shorter than a frame counts).
    bool take_press(int key) { return take(slot(keys_, key)); }
    bool take_click(int b) { return take(slot(buttons_, b)); }
    // The first key, else mouse button (kMouseBase + button, key_names.h), that went down since the last
    // take; kNoKey when none did (the Controls screen waiting for the key to bind).
    int take_any_press() {
        for (int k = 0; k < kKeys; ++k)
            if (take_press(k)) return k;
        for (int b = 0; b < kButtons; ++b)
            if (take_click(b)) return kMouseBase + b;
        return kNoKey;
    }
    bool any_button_held() const {
        for (const auto& b : buttons_)
            if (b.held) return true;
        return false;
    }
    // Held now, or tapped since the last take: what a per-step "is it down" question should see.
    bool down_or_tapped(int key) { return take_press(key) || held(key); }
    // Cursor motion since the last call, in pixels.
    void take_motion(double& dx, double& dy) {
        dx = dx_;
        dy = dy_;
        dx_ = dy_ = 0.0;
    }
    // Forget latches and motion (on capture/release: the click that resumed must not also fire).
    void clear_latches() {
        for (auto& k : keys_) k.pressed = false;
        for (auto& b : buttons_) b.pressed = false;
        dx_ = dy_ = 0.0;
        have_cursor_ = false;
    }
    // Everything up (the window lost focus: releases will not arrive).
    void release_all() {
        keys_.fill({});
        buttons_.fill({});
        clear_latches();
    }

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
    static void record(Slot* s, int action) {
        if (!s) return;
        if (action == kRelease) {
            s->held = false;
        } else if (action == kPress) {
            if (!s->held) s->pressed = true;
            s->held = true;
        } // GLFW_REPEAT: still held, not a new press
    }
    static bool take(Slot* s) {
        if (!s) return false;
        const bool was = s->pressed;
        s->pressed = false;
        return was;
    }

    std::array<Slot, kKeys> keys_{};
    std::array<Slot, kButtons> buttons_{};
    double x_ = 0.0, y_ = 0.0, dx_ = 0.0, dy_ = 0.0;
    bool have_cursor_ = false;
};

// Binds one InputState to a window's GLFW callbacks, chaining to the callbacks installed before (ImGui's).
// One window per process (GLFW callbacks carry no user data here: ImGui's backend owns the user pointer).
class InputEvents {
  public:
    InputEvents() = default;
    InputEvents(const InputEvents&) = delete;
    InputEvents& operator=(const InputEvents&) = delete;
    ~InputEvents() { uninstall(); }

    void install(GLFWwindow* window);
    void uninstall();
    InputState& state() { return state_; }

    // Synthetic events through the same path as GLFW's (the previous callbacks — ImGui — see them too).
    void inject_key(int key, int action);
    void inject_button(int button, int action);
    // Moves the cursor: warps the real pointer when free (ImGui polls it), adds motion when captured.
    void inject_cursor(double x, double y);

  private:
    GLFWwindow* window_ = nullptr;
    InputState state_;
};

} // namespace ks::runtime
