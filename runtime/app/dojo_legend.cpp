#include "dojo_legend.h"

#include "menu_style.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace ks::runtime {

namespace {
constexpr ImU32 kRowText = IM_COL32(235, 240, 245, 255);
constexpr ImU32 kListOnlyText = IM_COL32(185, 198, 210, 255); // clips without a key
constexpr ImU32 kPlayingText = IM_COL32(255, 220, 120, 255);
constexpr ImU32 kHintText = IM_COL32(150, 200, 230, 255);

// "playing: shooting  0.42 s  (blending)", into `out` (no allocation per frame).
void playing_line(const anim::DojoController& dojo, char* out, std::size_t size) {
    const int playing = dojo.playing_entry();
    if (playing < 0) {
        std::snprintf(out, size, "playing: (rest pose)");
        return;
    }
    std::snprintf(out, size, "playing: %s  %.2f s%s",
                  dojo.entries()[static_cast<std::size_t>(playing)].clip.c_str(), dojo.player().clip_time(),
                  dojo.player().blending() ? "  (blending)" : "");
}

// The rows, scrolling when there are more than fit; returns the entry clicked while picking.
int clip_rows(const anim::DojoController& dojo, bool picking, float row, float list_h) {
    int clicked = -1;
    ImGui::PushStyleColor(ImGuiCol_ChildBg, IM_COL32(0, 0, 0, 0));
    ImGui::PushStyleColor(ImGuiCol_Header, IM_COL32(41, 171, 226, 90));
    ImGui::PushStyleColor(ImGuiCol_HeaderHovered, IM_COL32(41, 171, 226, 170));
    ImGui::PushStyleColor(ImGuiCol_HeaderActive, ui::kAccentActive);
    ImGui::BeginChild("##dojo_clips", ImVec2(0, list_h), false, ImGuiWindowFlags_NoNav);
    const int playing = dojo.playing_entry();
    const auto& entries = dojo.entries();
    ImDrawList* d = ImGui::GetWindowDrawList();
    ImFont* font = ImGui::GetFont();
    const float size = ImGui::GetFontSize(), name_x = size * 1.6f;
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const anim::DojoKey& e = entries[i];
        const bool is_playing = static_cast<int>(i) == playing;
        char id[32];
        std::snprintf(id, sizeof id, "##clip%zu", i);
        if (ImGui::Selectable(id, is_playing, 0, ImVec2(0, row)) && picking) clicked = static_cast<int>(i);
        if (picking) ui::record_button(e.clip.c_str()); // --input-script's "click <clip>"
        // The key and the name in two columns (a proportional font would not line them up).
        const ImVec2 at = ImGui::GetItemRectMin();
        const float y = at.y + (row - size) * 0.5f;
        const ImU32 colour = is_playing ? kPlayingText : e.key == 0 ? kListOnlyText : kRowText;
        const char key[2] = {e.key, '\0'};
        if (e.key != 0) d->AddText(font, size, ImVec2(at.x + 2.0f, y), colour, key);
        d->AddText(font, size, ImVec2(at.x + name_x, y), colour, e.clip.c_str());
    }
    ImGui::EndChild();
    ImGui::PopStyleColor(4);
    return clicked;
}
} // namespace

int dojo_legend(const anim::DojoController& dojo, bool picking, const shell::Fonts& fonts, float w, float h) {
    const float s = ui::ui_scale(w, h);
    ImFont* font = fonts.body ? fonts.body : ImGui::GetFont();
    const float px = 20.0f * s, row = px * 1.3f, pad = 14.0f * s, title_h = 34.0f * s;
    const float box_w = 340.0f * s;
    // Title, rows, the playing line and the picking hint; the rows scroll past 60 % of the window's height.
    const float rows_h = row * static_cast<float>(dojo.entries().size());
    const float list_h = std::min(rows_h, h * 0.6f);
    const ImVec2 p(w - box_w - 16 * s, 16 * s);

    ImGui::SetNextWindowPos(p);
    ImGui::SetNextWindowSizeConstraints(ImVec2(box_w, 0), ImVec2(box_w, h)); // as tall as its content
    ImGui::PushStyleColor(ImGuiCol_WindowBg, IM_COL32(10, 16, 24, 190));
    ImGui::PushStyleColor(ImGuiCol_Border, ui::kAccent);
    ImGui::PushStyleVar(ImGuiStyleVar_WindowRounding, 8 * s);
    ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 2 * s);
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(pad, pad * 0.6f));
    ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(0, 0));
    ImGui::Begin("##dojo_legend", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav |
                     ImGuiWindowFlags_AlwaysAutoResize);
    ImGui::PushFont(font);
    ImGui::SetWindowFontScale(px / std::max(font->FontSize, 1.0f));
    ImDrawList* d = ImGui::GetWindowDrawList();
    d->AddText(fonts.hud ? fonts.hud : font, 22 * s, ImVec2(p.x + pad, p.y + 8 * s), ui::kAccent,
               "Dojo - robot clips");
    ImGui::SetCursorPosY(title_h);
    const int clicked = clip_rows(dojo, picking, row, list_h);
    ImGui::Dummy(ImVec2(0, 6 * s));

    char line[192];
    playing_line(dojo, line, sizeof line);
    ImGui::PushStyleColor(ImGuiCol_Text, kPlayingText);
    ImGui::TextUnformatted(line);
    ImGui::PopStyleColor();
    ImGui::PushStyleColor(ImGuiCol_Text, kHintText);
    ImGui::TextUnformatted(picking ? "click a clip to play it  -  Tab: look"
                                   : "Tab: pick a clip with the mouse");
    ImGui::PopStyleColor();
    ImGui::Dummy(ImVec2(0, 4 * s));
    ImGui::PopFont();
    ImGui::End();
    ImGui::PopStyleVar(4);
    ImGui::PopStyleColor(2);

    const char* hint =
        "WASD move  -  mouse look  -  1-9, 0 play clips  -  Tab pick from the list  -  Esc pause";
    const ImVec2 hs = font->CalcTextSizeA(px, 10000.0f, 0.0f, hint);
    ImGui::GetForegroundDrawList()->AddText(font, px, ImVec2((w - hs.x) * 0.5f, h - hs.y - 60 * s),
                                            IM_COL32(235, 240, 245, 220), hint);
    return clicked;
}

} // namespace ks::runtime
