#include "runtime/model/key_names.h"

#include <array>

namespace ks::runtime {

namespace {
struct NamedKey {
    int code;
    const char* name;
};
// Every named non-printable key GLFW has, plus the punctuation keys by name ("Minus", not "-", which the
// menus use for an empty slot); letters, digits, F-keys and the keypad digits are generated in key_name().
constexpr std::array<NamedKey, 54> kNamedKeys{{
    {32, "Space"},
    {39, "Apostrophe"},
    {44, "Comma"},
    {45, "Minus"},
    {46, "Period"},
    {47, "Slash"},
    {59, "Semicolon"},
    {61, "Equals"},
    {91, "Left Bracket"},
    {92, "Backslash"},
    {93, "Right Bracket"},
    {96, "Backquote"},
    {256, "Esc"},
    {257, "Enter"},
    {258, "Tab"},
    {259, "Backspace"},
    {260, "Insert"},
    {261, "Delete"},
    {262, "Right"},
    {263, "Left"},
    {264, "Down"},
    {265, "Up"},
    {266, "Page Up"},
    {267, "Page Down"},
    {268, "Home"},
    {269, "End"},
    {280, "Caps Lock"},
    {281, "Scroll Lock"},
    {282, "Num Lock"},
    {283, "Print Screen"},
    {284, "Pause"},
    {330, "Keypad ."},
    {331, "Keypad /"},
    {332, "Keypad *"},
    {333, "Keypad -"},
    {334, "Keypad +"},
    {335, "Keypad Enter"},
    {336, "Keypad ="},
    {340, "Left Shift"},
    {341, "Left Ctrl"},
    {342, "Left Alt"},
    {343, "Left Super"},
    {344, "Right Shift"},
    {345, "Right Ctrl"},
    {346, "Right Alt"},
    {347, "Right Super"},
    {348, "Menu"},
    {kMouseBase + 0, "Mouse Left"},
    {kMouseBase + 1, "Mouse Right"},
    {kMouseBase + 2, "Mouse Middle"},
    {kMouseBase + 3, "Mouse 4"},
    {kMouseBase + 4, "Mouse 5"},
    {kMouseBase + 5, "Mouse 6"},
    {kMouseBase + 6, "Mouse 7"},
}};
} // namespace

bool is_mouse_code(int code) {
    return code >= kMouseBase && code < kMouseBase + kMouseButtons;
}

std::string key_name(int code) {
    if (code >= 'A' && code <= 'Z') return std::string(1, static_cast<char>(code));
    if (code >= '0' && code <= '9') return std::string(1, static_cast<char>(code));
    if (code >= 290 && code <= 314) return "F" + std::to_string(code - 290 + 1); // F1..F25
    if (code >= 320 && code <= 329) return "Keypad " + std::to_string(code - 320);
    if (code == kMouseBase + 7) return "Mouse 8";
    for (const auto& k : kNamedKeys)
        if (k.code == code) return k.name;
    return "";
}

int key_code(std::string_view name) {
    if (name.empty()) return kNoKey;
    auto lower = [](std::string_view s) {
        std::string out(s);
        for (char& c : out)
            if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
        return out;
    };
    const std::string wanted = lower(name);
    if (wanted.size() == 1 && wanted[0] >= 'a' && wanted[0] <= 'z') return 'A' + (wanted[0] - 'a');
    if (wanted.size() == 1 && wanted[0] >= '0' && wanted[0] <= '9') return wanted[0];
    for (int code = 290; code <= 329; ++code)
        if (!key_name(code).empty() && lower(key_name(code)) == wanted) return code;
    if (wanted == "mouse 8") return kMouseBase + 7;
    for (const auto& k : kNamedKeys)
        if (lower(k.name) == wanted) return k.code;
    return kNoKey;
}

} // namespace ks::runtime
