#pragma once
// Readable names for the keys and mouse buttons a player can bind ("W", "Space", "Left Shift", "Mouse Left"),
// as options.json stores them and the Controls screen shows them. Codes are GLFW key codes (physical
// positions: "W" is the key left of E on any layout); mouse buttons are kMouseBase + GLFW button, so one int
// names either. The values are checked against glfw3.h in runtime/app/player_input.cpp (the model sees
// no GLFW).
#include <string>
#include <string_view>

namespace ks::runtime {

inline constexpr int kNoKey = -1;        // an empty binding slot
inline constexpr int kKeyEscape = 256;   // GLFW_KEY_ESCAPE: reserved (pause, back, cancel a rebind)
inline constexpr int kMouseBase = 1000;  // kMouseBase + GLFW_MOUSE_BUTTON_n
inline constexpr int kMouseButtons = 8;  // GLFW_MOUSE_BUTTON_LAST + 1
inline constexpr int kLastKeyCode = 348; // GLFW_KEY_LAST
inline constexpr int kKeyUp = 265, kKeyDown = 264, kKeyLeft = 263, kKeyRight = 262;
inline constexpr int kKeySpace = 32;

// kMouseBase + a GLFW mouse button (not a key).
bool is_mouse_code(int code);

// "W", "7", "F5", "Keypad 3", "Space", "Mouse Left"; "" for kNoKey and codes without a name.
std::string key_name(int code);
// The code for a name key_name() gives (case-insensitive); kNoKey for "" and for names it does not know.
int key_code(std::string_view name);

} // namespace ks::runtime
