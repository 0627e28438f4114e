// GameApp's --input-script player: feeds each frame's scripted events through InputEvents.
#include "game_app_internal.h"

#include "core/log.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>

namespace ks::runtime {

void GameApp::run_script(long long frame) {
    if (click_next_frame_) {
        click_next_frame_ = false;
        events_.inject_button(GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS);
        events_.inject_button(GLFW_MOUSE_BUTTON_LEFT, GLFW_RELEASE);
    }
    if (pad_release_next_ != 0) { // the pad buttons tapped last frame come up now
        shell::GamepadState pad = shell_.gamepad();
        for (int b = 0; b < shell::kPadButtonCount; ++b)
            if (pad_release_next_ & (1u << b)) pad.buttons[static_cast<std::size_t>(b)] = false;
        pad_release_next_ = 0;
        shell_.inject_gamepad(pad);
    }
    while (script_next_ < script_.size() && script_[script_next_].frame <= frame) {
        const ScriptEvent& e = script_[script_next_++];
        switch (e.kind) {
        case ScriptEvent::Kind::Key:
            if (e.action != 0) events_.inject_key(e.code, GLFW_PRESS);
            if (e.action != 1) events_.inject_key(e.code, GLFW_RELEASE);
            break;
        case ScriptEvent::Kind::Mouse:
            if (e.action != 0) events_.inject_button(e.code, GLFW_PRESS);
            if (e.action != 1) events_.inject_button(e.code, GLFW_RELEASE);
            break;
        case ScriptEvent::Kind::Move:
            events_.inject_cursor(e.x, e.y);
            break;
        case ScriptEvent::Kind::Look: {
            double x = 0.0, y = 0.0;
            glfwGetCursorPos(shell_.window(), &x, &y);
            events_.inject_cursor(x, y); // where it is (an origin if none was seen yet), then the motion
            events_.inject_cursor(x + e.x, y + e.y);
            break;
        }
        case ScriptEvent::Kind::ClickButton: {
            const auto& buttons = ui::buttons_drawn();
            const auto it = std::find_if(buttons.begin(), buttons.end(),
                                         [&](const ui::ButtonRect& b) { return b.label == e.label; });
            if (it == buttons.end()) {
                log::error("input script line ", e.line, " (frame ", frame, "): no button '", e.label,
                           "' on the ", status_name(screen_), " screen; wait more frames before clicking");
                exit_code_ = 1;
                quit_ = true;
                return;
            }
            // Onto the button now, the click next frame: ImGui takes the pointer's place at the start of a
            // frame, and a pointer that only just entered the window may not count yet (as with a hand).
            events_.inject_cursor((it->x0 + it->x1) * 0.5, (it->y0 + it->y1) * 0.5);
            click_next_frame_ = true;
            break;
        }
        case ScriptEvent::Kind::PadButton: {
            shell::GamepadState pad = shell_.gamepad();
            pad.connected = true;
            pad.buttons[static_cast<std::size_t>(e.code)] = e.action != 0;
            if (e.action == 2) pad_release_next_ |= 1u << e.code;
            shell_.inject_gamepad(pad);
            break;
        }
        case ScriptEvent::Kind::PadAxis: {
            shell::GamepadState pad = shell_.gamepad();
            pad.connected = true;
            pad.axes[static_cast<std::size_t>(e.code)] = static_cast<float>(e.x);
            shell_.inject_gamepad(pad);
            break;
        }
        case ScriptEvent::Kind::Quit:
            quit_ = true;
            break;
        }
    }
}

} // namespace ks::runtime
