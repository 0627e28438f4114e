#pragma once
// The look of the game's screens, drawn with ImGui: a darkened, vignetted backdrop over the level, a
// centred light panel with a title tab (the reference menu's shape and colours), and big accent buttons.
// Everything is sized from the window height so 720p and 1080p read the same.
#include "shell/app_shell.h"

#include <imgui.h>

#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

namespace ks::runtime::ui {

// The reference menu's palette.
inline constexpr ImU32 kAccent = IM_COL32(41, 171, 226, 255); // buttons, title, panel border
inline constexpr ImU32 kAccentHover = IM_COL32(70, 190, 240, 255);
inline constexpr ImU32 kAccentActive = IM_COL32(25, 140, 195, 255);
inline constexpr ImU32 kPanel = IM_COL32(232, 238, 238, 242); // panel body
inline constexpr ImU32 kInk = IM_COL32(40, 48, 58, 255);      // body text on the panel

// Scale from the 1280x720 layout to a `width` x `height` window: the height's ratio, or the width's when
// the window is narrower than 16:9 (a 4:3 window cut the Controls panel off at both sides), within
// [0.6, 3]. display_scale(): the same for ImGui's display size (1 before it has one).
float ui_scale(float width, float height);
float display_scale();

// Darkens the frame behind a menu: a vertical navy→plum gradient at ~80 % plus a vignette at the edges.
void draw_backdrop(ImDrawList* draw, float width, float height, float strength = 1.0f);

// Begins a centred panel window `panel_w` x `panel_h` (720p pixels) with `title` in a tab on top. Always
// pair with end_panel().
void begin_panel(const char* id, const std::string& title, float panel_w, float panel_h, float width,
                 float height, const shell::Fonts& fonts);
void end_panel();

// A big accent button centred in the panel; returns true when clicked.
bool big_button(const char* label, const shell::Fonts& fonts, float width_720 = 320.0f);
// A row of buttons sharing `width_720` (gaps included), centred; those from `quiet_from` on are grey (less
// used: Quit). Returns the index of the one clicked, or -1.
int button_row(std::initializer_list<const char*> labels, const shell::Fonts& fonts, float width_720 = 320.0f,
               std::size_t quiet_from = SIZE_MAX);
// Where this frame's buttons are (window pixels), for --status-file and --input-script's "click LABEL":
// tests click menu buttons where the player sees them. Cleared by begin_frame().
struct ButtonRect {
    std::string label;
    float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool hovered = false; // under the mouse this frame (the menu's hover sound)
    bool clicked = false; // pressed this frame (its click sound)
    bool focused = false; // highlighted by keyboard or gamepad navigation (nav_focus_ring)
};
void begin_frame();
const std::vector<ButtonRect>& buttons_drawn();
// Records the last ImGui item as a button named `label` (for buttons not drawn by big_button): the part of
// it not clipped away, nothing when it is out of sight.
void record_button(const char* label);

// Non-clickable text a layout check wants to see (a slider's value beside it): --status-file's `text`
// lines. Cleared by begin_frame().
struct TextRect {
    std::string label;
    float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};
const std::vector<TextRect>& texts_drawn();

// A slider of `width` (pixels) whose value `shown` is printed beside it, right-aligned in a column of its
// own, never under the grab (the grab covered "75 deg" in the middle of its range). Dragging rounds the
// value to `step`. Records the slider as button `label` and its value as text `label`; returns true when
// the value changed.
bool value_slider(const char* label, const char* id, float& value, float lo, float hi, float step,
                  const std::string& shown, float width);
bool value_slider(const char* label, const char* id, int& value, int lo, int hi, const std::string& shown,
                  float width);

// The keyboard/gamepad highlight: a thick warm ring round the last item when it has the navigation focus and
// the player is navigating with keys or a pad (ImGui hides it while the mouse is used).
inline constexpr ImU32 kNavRing = IM_COL32(255, 160, 30, 255);
void nav_focus_ring();

// Centred body text lines.
void centred_text(const std::string& text, ImFont* font, ImU32 colour = kInk);

// A bar with a label (the loading screen's progress).
void progress_bar(float fraction, const std::string& label, const shell::Fonts& fonts, float width_720);

} // namespace ks::runtime::ui
