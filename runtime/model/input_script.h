#pragma once
// `killswitch --input-script FILE`: keyboard, mouse and gamepad events stamped with the frame they happen
// in, fed through the same handlers as GLFW's callbacks (runtime/app/input_events.h, game_script.cpp), so
// PlayerInput and the ImGui menus see them exactly as real input. With --screenshot the frames are a fixed
// 1/60 s, so a script is deterministic whatever the machine's frame rate.
//
//   # comment
//   <frame> key <name> down|up|tap       keys: a-z, 0-9, space, escape, enter, tab, up, down, left, right
//   <frame> mouse left|right down|up|click
//   <frame> move <x> <y>                  the cursor to window pixel (x, y)
//   <frame> look <dx> <dy>                move the cursor by (dx, dy) pixels (mouse look while captured)
//   <frame> click <button label>          move onto the menu button with that label (drawn last frame), click
//   <frame> pad <button> down|up|tap      a gamepad button: a b x y lb rb back start dup ddown dleft dright
//                                         (tap: down this frame, up the next: the pad is polled once a frame)
//   <frame> pad <axis> <value>            a gamepad axis: lx ly rx ry (-1..1, up is -1) lt rt (-1..1)
//   <frame> quit                          end the program (exit 0)
//
// Frames count from 0 (the first frame the window draws) and must not decrease down the file.
#include "core/result.h"

#include <string>
#include <vector>

namespace ks::runtime {

struct ScriptEvent {
    enum class Kind { Key, Mouse, Move, Look, ClickButton, PadButton, PadAxis, Quit };
    long long frame = 0;
    Kind kind = Kind::Key;
    int code = 0;   // GLFW key or mouse button
    int action = 0; // 1 down, 0 up, 2 tap / click (down then up)
    double x = 0.0, y = 0.0;
    std::string label; // ClickButton
    int line = 0;      // for runtime errors ("input script line 7: no button 'Play' on this screen")
};

// GLFW key codes for the names above (checked against glfw3.h in runtime/app/input_events.cpp); -1 for
// unknown names.
int script_key_code(const std::string& name);

// GamepadButton / GamepadAxis (core/gamepad_state.h) for the script's pad names; -1 for unknown names.
int script_pad_button(const std::string& name);
int script_pad_axis(const std::string& name);

// The script's events, or the first bad line's error (the file, the line and a fix).
Result<std::vector<ScriptEvent>> parse_input_script(const std::string& text, const std::string& file);

} // namespace ks::runtime
