#include "shell/hud.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace ks::shell {

float bar_fraction(float value, float max) {
    if (!std::isfinite(value) || !std::isfinite(max) || max <= 0.0f) return 0.0f;
    return std::clamp(value / max, 0.0f, 1.0f);
}

namespace {
void bar(ImDrawList* d, ImFont* font, ImVec2 pos, ImVec2 size, float fraction, ImU32 fill, const char* label,
         float value, float max, float scale) {
    const float r = 6.0f * scale;
    d->AddRectFilled(pos, ImVec2(pos.x + size.x, pos.y + size.y), IM_COL32(15, 18, 24, 170), r);
    if (fraction > 0.0f)
        d->AddRectFilled(pos, ImVec2(pos.x + size.x * fraction, pos.y + size.y), fill, r,
                         fraction > 0.98f ? ImDrawFlags_RoundCornersAll : ImDrawFlags_RoundCornersLeft);
    d->AddRect(pos, ImVec2(pos.x + size.x, pos.y + size.y), IM_COL32(230, 235, 240, 140), r, 0, 1.5f * scale);
    char text[64];
    std::snprintf(text, sizeof(text), "%s", label);
    float font_size = size.y * 0.62f;
    ImVec2 ts = font ? font->CalcTextSizeA(font_size, 1e9f, 0, text) : ImVec2(0, font_size);
    ImVec2 tp(pos.x + 10.0f * scale, pos.y + (size.y - ts.y) * 0.5f);
    d->AddText(font, font_size, ImVec2(tp.x + 1, tp.y + 1), IM_COL32(0, 0, 0, 200), text);
    d->AddText(font, font_size, tp, IM_COL32(255, 255, 255, 255), text);
    std::snprintf(text, sizeof(text), "%d / %d", static_cast<int>(std::round(value)),
                  static_cast<int>(std::round(max)));
    ts = font ? font->CalcTextSizeA(font_size, 1e9f, 0, text) : ImVec2(0, font_size);
    ImVec2 vp(pos.x + size.x - ts.x - 10.0f * scale, tp.y);
    d->AddText(font, font_size, ImVec2(vp.x + 1, vp.y + 1), IM_COL32(0, 0, 0, 200), text);
    d->AddText(font, font_size, vp, IM_COL32(255, 255, 255, 230), text);
}
} // namespace

void draw_hud(ImDrawList* d, const HudState& s, const HudFonts& fonts, float width, float height) {
    const float scale = std::max(0.5f, height / 720.0f);
    if (s.menu_background) {
        d->AddRectFilledMultiColor(ImVec2(0, 0), ImVec2(width, height), IM_COL32(5, 8, 14, 210),
                                   IM_COL32(5, 8, 14, 210), IM_COL32(20, 10, 10, 235),
                                   IM_COL32(20, 10, 10, 235));
        return;
    }
    if (s.damage_flash > 0.0f) {
        auto a = static_cast<int>(std::clamp(s.damage_flash, 0.0f, 1.0f) * 150.0f);
        ImU32 edge = IM_COL32(200, 0, 0, a), clear = IM_COL32(200, 0, 0, 0);
        float band = height * 0.25f;
        d->AddRectFilledMultiColor(ImVec2(0, 0), ImVec2(width, band), edge, edge, clear, clear);
        d->AddRectFilledMultiColor(ImVec2(0, height - band), ImVec2(width, height), clear, clear, edge, edge);
        d->AddRectFilledMultiColor(ImVec2(0, 0), ImVec2(band, height), edge, clear, clear, edge);
        d->AddRectFilledMultiColor(ImVec2(width - band, 0), ImVec2(width, height), clear, edge, edge, clear);
    }
    const ImVec2 size(360.0f * scale, 28.0f * scale);
    const float x = 14.0f * scale, gap = 10.0f * scale;
    float y = 14.0f * scale;
    bar(d, fonts.label, ImVec2(x, y), size, bar_fraction(s.health, s.health_max), IM_COL32(40, 190, 70, 235),
        "HEALTH", s.health, s.health_max, scale);
    y += size.y + gap;
    bar(d, fonts.label, ImVec2(x, y), size, bar_fraction(s.shield, s.shield_max), IM_COL32(50, 130, 240, 235),
        "SHIELD", s.shield, s.shield_max, scale);
    y += size.y + gap;
    bar(d, fonts.label, ImVec2(x, y), size, bar_fraction(s.ammo, s.ammo_max), IM_COL32(235, 160, 30, 235),
        "AMMO", s.ammo, s.ammo_max, scale);
    if (s.crosshair) {
        ImVec2 c(width * 0.5f, height * 0.5f);
        float a = 9.0f * scale, g = 4.0f * scale, t = 2.0f * scale;
        for (int pass = 0; pass < 2; ++pass) {
            ImU32 col = pass == 0 ? IM_COL32(0, 0, 0, 160) : IM_COL32(255, 255, 255, 230);
            float w = pass == 0 ? t + 2.0f : t;
            d->AddLine(ImVec2(c.x - a - g, c.y), ImVec2(c.x - g, c.y), col, w);
            d->AddLine(ImVec2(c.x + g, c.y), ImVec2(c.x + a + g, c.y), col, w);
            d->AddLine(ImVec2(c.x, c.y - a - g), ImVec2(c.x, c.y - g), col, w);
            d->AddLine(ImVec2(c.x, c.y + g), ImVec2(c.x, c.y + a + g), col, w);
        }
    }
    if (!s.caption.empty()) {
        float font_size = 26.0f * scale;
        ImVec2 ts = fonts.label ? fonts.label->CalcTextSizeA(font_size, 1e9f, 0, s.caption.c_str())
                                : ImVec2(0, font_size);
        ImVec2 p((width - ts.x) * 0.5f, height - 70.0f * scale);
        d->AddRectFilled(ImVec2(p.x - 16 * scale, p.y - 8 * scale),
                         ImVec2(p.x + ts.x + 16 * scale, p.y + ts.y + 8 * scale), IM_COL32(0, 0, 0, 150),
                         8.0f * scale);
        d->AddText(fonts.label, font_size, p, IM_COL32(255, 255, 255, 255), s.caption.c_str());
    }
}

} // namespace ks::shell
