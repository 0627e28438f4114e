#pragma once
// The 2D layer drawn with ImGui draw lists over the scene: health/shield/ammo bars with labels, the
// crosshair, a caption at the bottom, the red damage flash and a dimmed menu background. Sizes follow the
// window height so it reads the same at 720p and 1080p.
#include <string>

struct ImDrawList;
struct ImFont;

namespace ks::shell {

struct HudState {
    float health = 100, health_max = 100;
    float shield = 0, shield_max = 100;
    float ammo = 30, ammo_max = 30;
    std::string caption;    // e.g. "Press E to open the door"; empty hides it
    float damage_flash = 0; // 0..1, fades the screen edge red
    bool crosshair = true;
    bool menu_background = false;
};

struct HudFonts {
    ImFont* label = nullptr; // bar labels and caption
};

void draw_hud(ImDrawList* draw, const HudState& state, const HudFonts& fonts, float width, float height);

// Fraction of a bar to fill: value/max clamped to 0..1; NaN or max <= 0 gives 0.
float bar_fraction(float value, float max);

} // namespace ks::shell
