#include "logic_hud.h"

#include "menu_style.h"
#include "shell/app_shell.h"

#include <imgui.h>

#include <cfloat>
#include <cstdio>
#include <utility>

namespace ks::runtime {

namespace {

ImU32 rgba(int r, int g, int b, float alpha) {
    return IM_COL32(r, g, b, static_cast<int>(std::clamp(alpha, 0.0f, 1.0f) * 255.0f));
}

// A check mark inside the square at `at` of side `size`.
void tick(ImDrawList* d, ImVec2 at, float size, ImU32 colour, float thickness) {
    const ImVec2 points[3] = {ImVec2(at.x + size * 0.22f, at.y + size * 0.52f),
                              ImVec2(at.x + size * 0.42f, at.y + size * 0.72f),
                              ImVec2(at.x + size * 0.78f, at.y + size * 0.28f)};
    d->AddPolyline(points, 3, colour, ImDrawFlags_None, thickness);
}

void text_with_shadow(ImDrawList* d, ImFont* font, float size, ImVec2 at, ImU32 colour, const char* begin,
                      const char* end = nullptr, float wrap = 0.0f) {
    const ImU32 shadow = IM_COL32(0, 0, 0, (colour >> IM_COL32_A_SHIFT & 0xFF) * 3 / 4);
    d->AddText(font, size, ImVec2(at.x + 1.0f, at.y + 1.0f), shadow, begin, end, wrap);
    d->AddText(font, size, at, colour, begin, end, wrap);
}

float text_width(ImFont* font, float size, const std::string& text) {
    return font ? font->CalcTextSizeA(size, FLT_MAX, 0.0f, text.c_str()).x : size * 0.5f * text.size();
}

// Top right: a dark panel like the HUD's bars, a header with the count done, then one row per objective.
// Returns the panel's box (empty without objectives) for the message line to keep clear of.
HudBox draw_objectives(ImDrawList* d, const game::Game& game, const shell::Fonts& fonts, float w, float s) {
    const auto objectives = game.logic().objectives();
    if (objectives.empty()) return {};
    const int count = static_cast<int>(objectives.size());
    const int current = game.logic().current_objective();
    const ObjectiveRows rows = objective_rows(count, current);
    const float row_h = 30.0f * s, header_h = 30.0f * s, pad = 12.0f * s, box = 16.0f * s;
    const float text_size = 19.0f * s;
    float widest = text_width(fonts.hud, 15.0f * s, "OBJECTIVES") + 60.0f * s;
    for (int i = rows.first; i < rows.end; ++i)
        widest = std::max(widest, text_width(i == current ? fonts.hud : fonts.body, text_size,
                                             objectives[static_cast<std::size_t>(i)].text));
    const int more_rows = (rows.hidden_before > 0) + (rows.hidden_after > 0);
    const HudBox panel = objective_panel_box(w, s, widest, rows.end - rows.first + more_rows);
    const ImVec2 p0(panel.x0, panel.y0), p1(panel.x1, panel.y1);
    d->AddRectFilled(p0, p1, IM_COL32(15, 18, 24, 170), 8.0f * s);
    d->AddRect(p0, p1, IM_COL32(230, 235, 240, 90), 8.0f * s, 0, 1.5f * s);
    d->PushClipRect(p0, p1, true);

    int done = 0;
    for (const game::ObjectiveState& o : objectives) done += o.completed ? 1 : 0;
    text_with_shadow(d, fonts.hud, 15.0f * s, ImVec2(p0.x + pad, p0.y + 9.0f * s), ui::kAccentHover,
                     "OBJECTIVES");
    char tally[32];
    std::snprintf(tally, sizeof(tally), "%d / %d", done, count);
    const float tally_w = fonts.hud ? fonts.hud->CalcTextSizeA(15.0f * s, FLT_MAX, 0.0f, tally).x : 0.0f;
    text_with_shadow(d, fonts.hud, 15.0f * s, ImVec2(p1.x - pad - tally_w, p0.y + 9.0f * s),
                     IM_COL32(200, 208, 215, 220), tally);

    float y = p0.y + header_h;
    auto more_line = [&](int hidden, const char* where) {
        char text[48];
        std::snprintf(text, sizeof(text), "+%d %s", hidden, where);
        text_with_shadow(d, fonts.body, 15.0f * s, ImVec2(p0.x + pad + box + pad, y + 6.0f * s),
                         IM_COL32(170, 180, 190, 200), text);
        y += row_h;
    };
    if (rows.hidden_before > 0) more_line(rows.hidden_before, "done");
    for (int i = rows.first; i < rows.end; ++i) {
        const game::ObjectiveState& o = objectives[static_cast<std::size_t>(i)];
        const bool is_current = i == current;
        const ImVec2 b0(p0.x + pad, y + (row_h - box) * 0.5f), b1(b0.x + box, b0.y + box);
        if (is_current) {
            d->AddRectFilled(ImVec2(p0.x + 2.0f * s, y), ImVec2(p1.x - 2.0f * s, y + row_h),
                             IM_COL32(41, 171, 226, 55), 5.0f * s);
            d->AddRectFilled(ImVec2(p0.x + 2.0f * s, y + 4.0f * s),
                             ImVec2(p0.x + 6.0f * s, y + row_h - 4.0f * s), ui::kAccent, 2.0f * s);
        }
        ImU32 text_colour = IM_COL32(190, 198, 205, 190);
        if (o.completed) {
            d->AddRectFilled(b0, b1, IM_COL32(40, 170, 70, 235), 3.0f * s);
            tick(d, b0, box, IM_COL32(255, 255, 255, 255), 2.4f * s);
            text_colour = IM_COL32(185, 200, 190, 150);
        } else if (is_current) {
            d->AddRect(b0, b1, ui::kAccentHover, 3.0f * s, 0, 2.4f * s);
            text_colour = IM_COL32(255, 255, 255, 255);
        } else {
            d->AddRect(b0, b1, IM_COL32(150, 160, 170, 170), 3.0f * s, 0, 1.5f * s);
        }
        ImFont* font = is_current ? fonts.hud : fonts.body;
        const ImVec2 at(b1.x + pad, y + (row_h - text_size) * 0.5f);
        text_with_shadow(d, font, text_size, at, text_colour, o.text.c_str());
        if (o.completed) // struck through, lightly: done, still readable
            d->AddLine(ImVec2(at.x, at.y + text_size * 0.55f),
                       ImVec2(at.x + text_width(font, text_size, o.text), at.y + text_size * 0.55f),
                       IM_COL32(185, 200, 190, 120), 1.2f * s);
        y += row_h;
    }
    if (rows.hidden_after > 0) more_line(rows.hidden_after, "more");
    d->PopClipRect();
    return panel;
}

// Upper middle, clear of the bars and the objective panel (message_layout): the message in a dark pill with
// an accent edge.
void draw_message(ImDrawList* d, const game::ShownMessage& message, const shell::Fonts& fonts, float w,
                  float h, float s, const HudBox& panel) {
    const float alpha = message_alpha(message);
    if (!(alpha > 0.0f) || message.text.empty()) return;
    const char* begin = message.text.data();
    const char* end = begin + message.text.size();
    const float size = 24.0f * s;
    const MessageLayout l = message_layout(w, h, s, panel, [&](float wrap) {
        const ImVec2 ts =
            fonts.hud ? fonts.hud->CalcTextSizeA(size, FLT_MAX, wrap, begin, end) : ImVec2(wrap, size);
        return std::pair(ts.x, ts.y);
    });
    const ImVec2 at(l.text_x, l.text_y), p0(l.box.x0, l.box.y0), p1(l.box.x1, l.box.y1);
    d->AddRectFilled(p0, p1, rgba(10, 14, 22, 0.75f * alpha), 10.0f * s);
    d->AddRectFilled(p0, ImVec2(p0.x + 6.0f * s, p1.y), rgba(41, 171, 226, alpha), 10.0f * s,
                     ImDrawFlags_RoundCornersLeft);
    text_with_shadow(d, fonts.hud, size, at, rgba(255, 255, 255, alpha), begin, end, l.wrap);
}

// Above the crosshair: "OBJECTIVE COMPLETE" with a tick and the objective's text, on a band that fades at
// its ends; it pops in slightly larger and fades out.
void draw_flash(ImDrawList* d, const ObjectiveFlash& flash, const shell::Fonts& fonts, float w, float h,
                float s) {
    if (!flash.visible()) return;
    const float a = flash.strength();
    const float entrance = std::clamp(flash.age() / 0.1f, 0.0f, 1.0f);
    const float pop = 1.0f + 0.2f * (1.0f - entrance) * (1.0f - entrance);
    const float title_size = 32.0f * s * pop, text_size = 20.0f * s;
    const char* title = "OBJECTIVE COMPLETE";
    const float title_w = fonts.hud ? fonts.hud->CalcTextSizeA(title_size, FLT_MAX, 0.0f, title).x : 0.0f;
    const float icon = title_size * 0.9f, gap = 12.0f * s;
    const float cy = h * 0.32f;
    const float band_top = cy - title_size * 0.5f - 14.0f * s,
                band_bottom = cy + title_size * 0.5f + text_size + 22.0f * s;
    const ImU32 dark = rgba(8, 20, 14, 0.7f * a), clear = rgba(8, 20, 14, 0.0f);
    d->AddRectFilledMultiColor(ImVec2(w * 0.15f, band_top), ImVec2(w * 0.5f, band_bottom), clear, dark, dark,
                               clear);
    d->AddRectFilledMultiColor(ImVec2(w * 0.5f, band_top), ImVec2(w * 0.85f, band_bottom), dark, clear, clear,
                               dark);
    const float x0 = (w - (icon + gap + title_w)) * 0.5f;
    const ImVec2 icon_at(x0, cy - icon * 0.5f);
    d->AddRectFilled(icon_at, ImVec2(icon_at.x + icon, icon_at.y + icon), rgba(40, 170, 70, a), 5.0f * s);
    tick(d, icon_at, icon, rgba(255, 255, 255, a), 3.5f * s);
    text_with_shadow(d, fonts.hud, title_size, ImVec2(x0 + icon + gap, cy - title_size * 0.5f),
                     rgba(120, 235, 150, a), title);
    if (flash.text().empty()) return;
    const float text_w = text_width(fonts.body, text_size, flash.text());
    text_with_shadow(d, fonts.body, text_size, ImVec2((w - text_w) * 0.5f, cy + title_size * 0.5f + 8.0f * s),
                     rgba(235, 245, 238, a), flash.text().c_str());
}

} // namespace

void draw_logic_hud(ImDrawList* d, const game::Game& game, const ObjectiveFlash& flash,
                    const shell::Fonts& fonts, float width, float height) {
    const float s = hud_scale(height);
    const HudBox panel = draw_objectives(d, game, fonts, width, s);
    draw_message(d, game.logic().message(), fonts, width, height, s, panel);
    draw_flash(d, flash, fonts, width, height, s);
}

} // namespace ks::runtime
