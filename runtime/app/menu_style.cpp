#include "menu_style.h"

#include <imgui_internal.h>

#include <algorithm>
#include <cmath>

namespace ks::runtime::ui {

float ui_scale(float width, float height) {
    return std::clamp(std::min(height / 720.0f, width / 1280.0f), 0.6f, 3.0f);
}

float display_scale() {
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    return size.x > 0.0f && size.y > 0.0f ? ui_scale(size.x, size.y) : 1.0f;
}

void draw_backdrop(ImDrawList* d, float w, float h, float strength) {
    const auto a = [&](float v) { return static_cast<int>(std::clamp(v * strength, 0.0f, 255.0f)); };
    d->AddRectFilledMultiColor(ImVec2(0, 0), ImVec2(w, h), IM_COL32(30, 28, 60, a(200)),
                               IM_COL32(14, 40, 70, a(190)), IM_COL32(10, 50, 80, a(205)),
                               IM_COL32(40, 20, 50, a(215)));
    // Vignette: darker bands along each edge read as depth of field around the panel.
    const float band = std::min(w, h) * 0.22f;
    const ImU32 dark = IM_COL32(0, 0, 0, a(150)), clear = IM_COL32(0, 0, 0, 0);
    d->AddRectFilledMultiColor(ImVec2(0, 0), ImVec2(w, band), dark, dark, clear, clear);
    d->AddRectFilledMultiColor(ImVec2(0, h - band), ImVec2(w, h), clear, clear, dark, dark);
    d->AddRectFilledMultiColor(ImVec2(0, 0), ImVec2(band, h), dark, clear, clear, dark);
    d->AddRectFilledMultiColor(ImVec2(w - band, 0), ImVec2(w, h), clear, dark, dark, clear);
}

void begin_panel(const char* id, const std::string& title, float panel_w, float panel_h, float w, float h,
                 const shell::Fonts& fonts) {
    const float s = ui_scale(w, h);
    const ImVec2 size(panel_w * s, panel_h * s);
    const ImVec2 pos((w - size.x) * 0.5f, (h - size.y) * 0.5f + 20.0f * s);
    ImDrawList* bg = ImGui::GetBackgroundDrawList();
    // Shadow, border and body of the panel, then the title tab that overlaps its top edge.
    const float r = 6.0f * s, border = 5.0f * s;
    bg->AddRectFilled(ImVec2(pos.x + 6 * s, pos.y + 8 * s),
                      ImVec2(pos.x + size.x + 6 * s, pos.y + size.y + 8 * s), IM_COL32(0, 0, 0, 90), r);
    bg->AddRectFilled(pos, ImVec2(pos.x + size.x, pos.y + size.y), kAccent, r);
    bg->AddRectFilled(ImVec2(pos.x + border, pos.y + border),
                      ImVec2(pos.x + size.x - border, pos.y + size.y - border), kPanel, r);
    ImFont* title_font = fonts.title ? fonts.title : ImGui::GetFont();
    const float title_px = 52.0f * s;
    const ImVec2 tsize = title_font->CalcTextSizeA(title_px, 10000.0f, 0.0f, title.c_str());
    const ImVec2 tab_min(pos.x + (size.x - tsize.x) * 0.5f - 20 * s, pos.y - 42 * s);
    const ImVec2 tab_max(pos.x + (size.x + tsize.x) * 0.5f + 20 * s, pos.y + 30 * s);
    bg->AddRectFilled(tab_min, tab_max, kAccent, 16.0f * s, ImDrawFlags_RoundCornersTop);
    bg->AddRectFilled(ImVec2(tab_min.x + border, tab_min.y + border),
                      ImVec2(tab_max.x - border, tab_max.y + border), kPanel, 12.0f * s,
                      ImDrawFlags_RoundCornersTop);
    bg->AddText(title_font, title_px, ImVec2(pos.x + (size.x - tsize.x) * 0.5f, tab_min.y + 8 * s), kAccent,
                title.c_str());

    ImGui::SetNextWindowPos(ImVec2(pos.x, pos.y + 40 * s));
    ImGui::SetNextWindowSize(ImVec2(size.x, size.y - 40 * s));
    ImGui::PushStyleColor(ImGuiCol_WindowBg, IM_COL32(0, 0, 0, 0));
    ImGui::PushStyleColor(ImGuiCol_Border, IM_COL32(0, 0, 0, 0));
    ImGui::PushStyleColor(ImGuiCol_Text, kInk);
    ImGui::PushStyleColor(ImGuiCol_NavHighlight, kNavRing);
    ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(10 * s, 14 * s));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(30 * s, 14 * s));
    ImGui::Begin(id, nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoBringToFrontOnFocus);
    // The shell already sizes its fonts for the window it opened; scale only the rest of the way.
    const float loaded = fonts.body ? fonts.body->FontSize / 18.0f : 1.0f;
    ImGui::SetWindowFontScale(s / std::max(loaded, 0.1f));
}

void end_panel() {
    ImGui::End();
    ImGui::PopStyleVar(2);
    ImGui::PopStyleColor(4);
}

namespace {
std::vector<ButtonRect>& drawn() {
    static std::vector<ButtonRect> rects;
    return rects;
}
std::vector<TextRect>& texts() {
    static std::vector<TextRect> rects;
    return rects;
}

// Draws `shown` right-aligned in the column after the last item and records it as text `label`.
void value_text(const char* label, const std::string& shown, float column_w, float gap) {
    ImGui::SameLine(0.0f, gap);
    const float x = ImGui::GetCursorPosX();
    ImGui::SetCursorPosX(x + std::max(0.0f, column_w - ImGui::CalcTextSize(shown.c_str()).x));
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted(shown.c_str());
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    texts().push_back({label, a.x, a.y, b.x, b.y});
}

float value_column(float width, float& slider_w) {
    const float s = display_scale();
    const float column = std::min(84.0f * s, width * 0.4f);
    slider_w = std::max(1.0f, width - column - 8.0f * s);
    return column;
}
} // namespace

void begin_frame() {
    drawn().clear();
    texts().clear();
}

const std::vector<TextRect>& texts_drawn() {
    return texts();
}

bool value_slider(const char* label, const char* id, float& value, float lo, float hi, float step,
                  const std::string& shown, float width) {
    float slider_w = 0.0f;
    const float column = value_column(width, slider_w);
    ImGui::SetNextItemWidth(slider_w);
    float v = value;
    // No text on the slider ("" also keeps ImGui from rounding to a format); typing is off, the step rounds.
    const bool moved =
        ImGui::SliderFloat(id, &v, lo, hi, "", ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_NoInput);
    record_button(label);
    nav_focus_ring();
    if (moved) v = std::clamp(step > 0.0f ? std::round(v / step) * step : v, lo, hi);
    value_text(label, shown, column, width - slider_w - column);
    const bool changed = moved && v != value;
    if (moved) value = v;
    return changed;
}

bool value_slider(const char* label, const char* id, int& value, int lo, int hi, const std::string& shown,
                  float width) {
    float slider_w = 0.0f;
    const float column = value_column(width, slider_w);
    ImGui::SetNextItemWidth(slider_w);
    const bool moved =
        ImGui::SliderInt(id, &value, lo, hi, "", ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_NoInput);
    record_button(label);
    nav_focus_ring();
    value_text(label, shown, column, width - slider_w - column);
    return moved;
}

const std::vector<ButtonRect>& buttons_drawn() {
    return drawn();
}

void record_button(const char* label) {
    // Only the part that can be clicked: a row scrolled half out of a list is cut to what shows.
    const ImVec2 clip_min = ImGui::GetWindowDrawList()->GetClipRectMin();
    const ImVec2 clip_max = ImGui::GetWindowDrawList()->GetClipRectMax();
    const ImVec2 a(std::max(ImGui::GetItemRectMin().x, clip_min.x),
                   std::max(ImGui::GetItemRectMin().y, clip_min.y));
    const ImVec2 b(std::min(ImGui::GetItemRectMax().x, clip_max.x),
                   std::min(ImGui::GetItemRectMax().y, clip_max.y));
    if (a.x >= b.x || a.y >= b.y) return; // scrolled out of sight
    drawn().push_back({label, a.x, a.y, b.x, b.y, ImGui::IsItemHovered(), ImGui::IsItemClicked()});
}

void nav_focus_ring() {
    const ImGuiContext* g = ImGui::GetCurrentContext();
    if (!g || g->NavDisableHighlight || !ImGui::IsItemFocused()) return;
    if (!drawn().empty() && drawn().back().x0 >= ImGui::GetItemRectMin().x - 1.0f &&
        drawn().back().x1 <= ImGui::GetItemRectMax().x + 1.0f)
        drawn().back().focused = true; // the button record_button() just recorded
    const float s = display_scale();
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    ImGui::GetWindowDrawList()->AddRect(ImVec2(a.x - 4 * s, a.y - 4 * s), ImVec2(b.x + 4 * s, b.y + 4 * s),
                                        kNavRing, 8.0f * s, 0, 4.0f * s);
}

bool big_button(const char* label, const shell::Fonts& fonts, float width_720) {
    const float s = display_scale();
    const ImVec2 size(width_720 * s, 52.0f * s);
    ImGui::SetCursorPosX((ImGui::GetWindowWidth() - size.x) * 0.5f);
    const ImVec2 p = ImGui::GetCursorScreenPos();
    ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(p.x + 2 * s, p.y + 5 * s),
                                              ImVec2(p.x + size.x + 2 * s, p.y + size.y + 5 * s),
                                              IM_COL32(0, 0, 0, 60), 6.0f * s);
    ImGui::PushStyleColor(ImGuiCol_Button, kAccent);
    ImGui::PushStyleColor(ImGuiCol_ButtonHovered, kAccentHover);
    ImGui::PushStyleColor(ImGuiCol_ButtonActive, kAccentActive);
    ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(255, 255, 255, 255));
    ImGui::PushStyleVar(ImGuiStyleVar_FrameRounding, 6.0f * s);
    if (fonts.hud) ImGui::PushFont(fonts.hud);
    const bool clicked = ImGui::Button(label, size);
    record_button(label);
    nav_focus_ring();
    if (fonts.hud) ImGui::PopFont();
    ImGui::PopStyleVar();
    ImGui::PopStyleColor(4);
    return clicked;
}

int button_row(std::initializer_list<const char*> labels, const shell::Fonts& fonts, float width_720,
               std::size_t quiet_from) {
    const float s = display_scale();
    const float gap = 10.0f * s, total = width_720 * s;
    const float each =
        (total - gap * static_cast<float>(labels.size() - 1)) / static_cast<float>(labels.size());
    const float x0 = (ImGui::GetWindowWidth() - total) * 0.5f;
    int clicked = -1;
    ImGui::PushStyleColor(ImGuiCol_Button, kAccent);
    ImGui::PushStyleColor(ImGuiCol_ButtonHovered, kAccentHover);
    ImGui::PushStyleColor(ImGuiCol_ButtonActive, kAccentActive);
    ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(255, 255, 255, 255));
    ImGui::PushStyleVar(ImGuiStyleVar_FrameRounding, 6.0f * s);
    if (fonts.hud) ImGui::PushFont(fonts.hud);
    const float y = ImGui::GetCursorPosY();
    std::size_t i = 0;
    for (const char* label : labels) {
        const float x = x0 + static_cast<float>(i) * (each + gap);
        ImGui::SetCursorPos(ImVec2(x, y));
        const ImVec2 p = ImGui::GetCursorScreenPos();
        ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(p.x + 2 * s, p.y + 5 * s),
                                                  ImVec2(p.x + each + 2 * s, p.y + 52 * s + 5 * s),
                                                  IM_COL32(0, 0, 0, 60), 6.0f * s);
        const bool quiet = i >= quiet_from;
        if (quiet) {
            ImGui::PushStyleColor(ImGuiCol_Button, IM_COL32(120, 130, 140, 255));
            ImGui::PushStyleColor(ImGuiCol_ButtonHovered, IM_COL32(140, 150, 160, 255));
        }
        if (ImGui::Button(label, ImVec2(each, 52 * s))) clicked = static_cast<int>(i);
        record_button(label);
        nav_focus_ring();
        if (quiet) ImGui::PopStyleColor(2);
        ++i;
    }
    if (fonts.hud) ImGui::PopFont();
    ImGui::PopStyleVar();
    ImGui::PopStyleColor(4);
    return clicked;
}

void centred_text(const std::string& text, ImFont* font, ImU32 colour) {
    if (font) ImGui::PushFont(font);
    const float tw = ImGui::CalcTextSize(text.c_str()).x;
    ImGui::SetCursorPosX(std::max(0.0f, (ImGui::GetWindowWidth() - tw) * 0.5f));
    ImGui::PushStyleColor(ImGuiCol_Text, colour);
    ImGui::TextUnformatted(text.c_str());
    ImGui::PopStyleColor();
    if (font) ImGui::PopFont();
}

void progress_bar(float fraction, const std::string& label, const shell::Fonts& fonts, float width_720) {
    const float s = display_scale();
    const ImVec2 size(width_720 * s, 26.0f * s);
    ImGui::SetCursorPosX((ImGui::GetWindowWidth() - size.x) * 0.5f);
    const ImVec2 p = ImGui::GetCursorScreenPos();
    ImDrawList* d = ImGui::GetWindowDrawList();
    const float f = std::clamp(fraction, 0.0f, 1.0f);
    d->AddRectFilled(p, ImVec2(p.x + size.x, p.y + size.y), IM_COL32(200, 208, 212, 255), 6.0f * s);
    if (f > 0.0f) d->AddRectFilled(p, ImVec2(p.x + size.x * f, p.y + size.y), kAccent, 6.0f * s);
    ImGui::Dummy(size);
    centred_text(label, fonts.body);
}

} // namespace ks::runtime::ui
