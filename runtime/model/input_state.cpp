#include "runtime/model/input_state.h"

namespace ks::runtime {

void InputState::key(int key, int action) {
    record(slot(keys_, key), action);
}

void InputState::button(int button, int action) {
    record(slot(buttons_, button), action);
}

void InputState::cursor(double x, double y) {
    if (have_cursor_) {
        dx_ += x - x_;
        dy_ += y - y_;
    }
    x_ = x;
    y_ = y;
    have_cursor_ = true;
}

bool InputState::held(int key) const {
    return key >= 0 && key < kKeys && keys_[static_cast<std::size_t>(key)].held;
}

bool InputState::button_held(int b) const {
    return b >= 0 && b < kButtons && buttons_[static_cast<std::size_t>(b)].held;
}

bool InputState::take_press(int key) {
    return take(slot(keys_, key));
}

bool InputState::take_click(int b) {
    return take(slot(buttons_, b));
}

int InputState::take_any_press() {
    for (int k = 0; k < kKeys; ++k)
        if (take_press(k)) return k;
    for (int b = 0; b < kButtons; ++b)
        if (take_click(b)) return kMouseBase + b;
    return kNoKey;
}

bool InputState::any_button_held() const {
    for (const auto& b : buttons_)
        if (b.held) return true;
    return false;
}

void InputState::take_motion(double& dx, double& dy) {
    dx = dx_;
    dy = dy_;
    dx_ = dy_ = 0.0;
}

void InputState::clear_latches() {
    for (auto& k : keys_) k.pressed = false;
    for (auto& b : buttons_) b.pressed = false;
    dx_ = dy_ = 0.0;
    have_cursor_ = false;
}

void InputState::release_all() {
    keys_.fill({});
    buttons_.fill({});
    clear_latches();
}

void InputState::record(Slot* s, int action) {
    if (!s) return;
    if (action == kRelease) {
        s->held = false;
    } else if (action == kPress) {
        if (!s->held) s->pressed = true;
        s->held = true;
    } // GLFW_REPEAT: still held, not a new press
}

bool InputState::take(Slot* s) {
    if (!s) return false;
    const bool was = s->pressed;
    s->pressed = false;
    return was;
}

} // namespace ks::runtime
