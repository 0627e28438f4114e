#include "campaign_screens.h"

#include "core/paths.h"
#include "menu_style.h"
#include "screens.h"

#include <imgui.h>

#include <algorithm>
#include <cfloat>

namespace ks::runtime {

namespace {

constexpr ImU32 kMuted = IM_COL32(95, 105, 115, 255); // secondary text on the light panel
constexpr ImU32 kError = IM_COL32(180, 35, 35, 255);

float scale() {
    return ui::display_scale();
}

// The panel's fonts are loaded for the window and scaled by begin_panel; draw-list text needs the size.
float font_px(float px_720) {
    return px_720 * scale();
}

ImVec2 text_size(ImFont* font, float px, const char* text, float wrap = 0.0f) {
    return font ? font->CalcTextSizeA(px, FLT_MAX, wrap, text) : ImVec2(px * 0.5f, px);
}

// One stat: a small accent label, the value large, a line of detail under it.
void tile(ImDrawList* d, ImVec2 at, ImVec2 size, const char* label, const std::string& value,
          const std::string& detail, const shell::Fonts& fonts) {
    const float s = scale();
    d->AddRectFilled(ImVec2(at.x + 2 * s, at.y + 4 * s), ImVec2(at.x + size.x + 2 * s, at.y + size.y + 4 * s),
                     IM_COL32(0, 0, 0, 35), 8.0f * s);
    d->AddRectFilled(at, ImVec2(at.x + size.x, at.y + size.y), IM_COL32(252, 253, 253, 255), 8.0f * s);
    d->AddRectFilled(at, ImVec2(at.x + size.x, at.y + 5.0f * s), ui::kAccent, 8.0f * s,
                     ImDrawFlags_RoundCornersTop);
    auto centred = [&](ImFont* font, float px, float y, ImU32 colour, const char* text) {
        const ImVec2 ts = text_size(font, px, text);
        d->AddText(font, px, ImVec2(at.x + (size.x - ts.x) * 0.5f, at.y + y), colour, text);
    };
    centred(fonts.hud, font_px(13), 14 * s, ui::kAccentActive, label);
    centred(fonts.title, font_px(34), 32 * s, ui::kInk, value.c_str());
    if (!detail.empty()) centred(fonts.body, font_px(14), 74 * s, kMuted, detail.c_str());
}

MenuAction from_row(int clicked, MenuAction first, MenuAction second) {
    return clicked == 0 ? first : clicked == 1 ? second : MenuAction::None;
}

// The table of the campaign-complete screen: a header, a row per level, the totals in bold.
void results_table(const CampaignProgress& progress, const shell::Fonts& fonts) {
    const float s = scale();
    const float width = ImGui::GetWindowWidth() - 80 * s, row_h = 30 * s;
    const float columns[4] = {0.02f, 0.52f, 0.67f, 0.82f};
    ImDrawList* d = ImGui::GetWindowDrawList();
    ImGui::SetCursorPosX(40 * s);
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    auto row = [&](float y, ImFont* font, ImU32 colour, const char* level, const std::string& time,
                   const std::string& robots, const std::string& accuracy) {
        const float px = font_px(font == fonts.hud ? 17 : 18);
        const float ty = origin.y + y + (row_h - px) * 0.5f;
        d->AddText(font, px, ImVec2(origin.x + width * columns[0], ty), colour, level);
        d->AddText(font, px, ImVec2(origin.x + width * columns[1], ty), colour, time.c_str());
        d->AddText(font, px, ImVec2(origin.x + width * columns[2], ty), colour, robots.c_str());
        d->AddText(font, px, ImVec2(origin.x + width * columns[3], ty), colour, accuracy.c_str());
    };
    row(0, fonts.hud, ui::kAccentActive, "LEVEL", "TIME", "ROBOTS", "ACCURACY");
    float y = row_h;
    std::size_t i = 0;
    for (const LevelResult& r : progress.results()) {
        if (i++ % 2 == 0)
            d->AddRectFilled(ImVec2(origin.x, origin.y + y), ImVec2(origin.x + width, origin.y + y + row_h),
                             IM_COL32(255, 255, 255, 150), 4.0f * s);
        row(y, fonts.body, ui::kInk, r.title.c_str(), format_time(r.seconds),
            std::to_string(r.robots_killed) + " / " + std::to_string(r.robots_total),
            accuracy_text(r.hits, r.shots));
        y += row_h;
    }
    d->AddLine(ImVec2(origin.x, origin.y + y + 3 * s), ImVec2(origin.x + width, origin.y + y + 3 * s),
               ui::kAccent, 2.0f * s);
    y += 6 * s;
    const LevelResult total = progress.totals();
    row(y, fonts.hud, ui::kInk, "Total", format_time(total.seconds),
        std::to_string(total.robots_killed) + " / " + std::to_string(total.robots_total),
        accuracy_text(total.hits, total.shots));
    ImGui::Dummy(ImVec2(width, y + row_h));
}

// A list row for a level that loads: a button with the level's name and its file name at the right.
bool level_row(const level::LevelFileEntry& entry, const shell::Fonts& fonts, float width) {
    const float s = scale(), row_h = 44 * s;
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImGui::PushID(entry.file.c_str());
    const bool clicked = ImGui::InvisibleButton("##level", ImVec2(width, row_h));
    ui::record_button(entry.name.c_str());
    const bool hovered = ImGui::IsItemHovered();
    ImGui::PopID();
    ImDrawList* d = ImGui::GetWindowDrawList();
    d->AddRectFilled(at, ImVec2(at.x + width, at.y + row_h),
                     hovered ? IM_COL32(41, 171, 226, 60) : IM_COL32(255, 255, 255, 170), 6.0f * s);
    d->AddRectFilled(at, ImVec2(at.x + 5 * s, at.y + row_h), hovered ? ui::kAccentActive : ui::kAccent,
                     6.0f * s, ImDrawFlags_RoundCornersLeft);
    const float name_px = font_px(19), file_px = font_px(14);
    d->AddText(fonts.hud, name_px, ImVec2(at.x + 18 * s, at.y + (row_h - name_px) * 0.5f), ui::kInk,
               entry.name.c_str());
    const std::string file = entry.file.filename().string();
    const ImVec2 fs = text_size(fonts.body, file_px, file.c_str());
    d->AddText(fonts.body, file_px, ImVec2(at.x + width - fs.x - 16 * s, at.y + (row_h - file_px) * 0.5f),
               kMuted, file.c_str());
    return clicked;
}

// A list row for a file that does not load: its name, "cannot be played", and the loader's first problem in
// at most two lines (the log has the whole report).
void broken_row(const level::LevelFileEntry& entry, const shell::Fonts& fonts, float width) {
    const float s = scale(), pad = 9 * s;
    const float name_px = font_px(18), error_px = font_px(14), wrap = width - 36 * s;
    std::string first = entry.error.substr(0, entry.error.find('\n'));
    if (const std::string full = entry.file.string(); first.rfind(full, 0) == 0) // the row says which folder
        first.replace(0, full.size(), entry.file.filename().string());
    const float error_h = std::min(text_size(fonts.body, error_px, first.c_str(), wrap).y, error_px * 2.4f);
    const float row_h = pad + name_px + 5 * s + error_h + pad;
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImDrawList* d = ImGui::GetWindowDrawList();
    d->AddRectFilled(at, ImVec2(at.x + width, at.y + row_h), IM_COL32(250, 232, 230, 220), 6.0f * s);
    d->AddRectFilled(at, ImVec2(at.x + 5 * s, at.y + row_h), kError, 6.0f * s, ImDrawFlags_RoundCornersLeft);
    const std::string title = entry.name + "  \u2014  cannot be played";
    d->AddText(fonts.hud, name_px, ImVec2(at.x + 18 * s, at.y + pad), kError, title.c_str());
    const ImVec2 error_at(at.x + 18 * s, at.y + pad + name_px + 5 * s);
    d->PushClipRect(error_at, ImVec2(error_at.x + wrap, error_at.y + error_h), true);
    d->AddText(fonts.body, error_px, error_at, IM_COL32(120, 40, 40, 255), first.c_str(), nullptr, wrap);
    d->PopClipRect();
    ImGui::Dummy(ImVec2(width, row_h));
}

// A folder's heading: its title, and where it is at the right.
void group_heading(const LevelGroup& group, const shell::Fonts& fonts, float width) {
    const float s = scale(), title_px = font_px(19), path_px = font_px(13);
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImDrawList* d = ImGui::GetWindowDrawList();
    d->AddText(fonts.hud, title_px, at, ui::kAccentActive, group.title.c_str());
    const std::string where = group.folder.folder.empty() ? "(no home folder)" : group.folder.folder.string();
    const ImVec2 ps = text_size(fonts.body, path_px, where.c_str());
    const float title_w = text_size(fonts.hud, title_px, group.title.c_str()).x;
    const float x = std::max(at.x + title_w + 16 * s, at.x + width - ps.x - 6 * s);
    d->PushClipRect(ImVec2(at.x, at.y), ImVec2(at.x + width, at.y + title_px + 4 * s), true);
    d->AddText(fonts.body, path_px, ImVec2(x, at.y + title_px - path_px - 1 * s), kMuted, where.c_str());
    d->PopClipRect();
    ImGui::Dummy(ImVec2(width, title_px + 2 * s));
}

void note(const std::string& text, const shell::Fonts& fonts, float width) {
    const float px = font_px(15);
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const ImVec2 ts = text_size(fonts.body, px, text.c_str(), width);
    ImGui::GetWindowDrawList()->AddText(fonts.body, px, ImVec2(at.x + 6 * scale(), at.y), kMuted,
                                        text.c_str(), nullptr, width);
    ImGui::Dummy(ImVec2(width, ts.y + 2 * scale()));
}

} // namespace

void result_tiles(const LevelResult& r, const shell::Fonts& fonts) {
    const float s = scale();
    const float total = ImGui::GetWindowWidth() - 80 * s, gap = 14 * s;
    const ImVec2 size((total - 2 * gap) / 3.0f, 100 * s);
    ImGui::SetCursorPosX(40 * s);
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImDrawList* d = ImGui::GetWindowDrawList();
    tile(d, at, size, "TIME", format_time(r.seconds),
         r.difficulty.empty() ? std::string("played") : "played on " + r.difficulty, fonts);
    tile(d, ImVec2(at.x + size.x + gap, at.y), size, "ROBOTS", std::to_string(r.robots_killed),
         "destroyed of " + std::to_string(r.robots_total), fonts);
    tile(d, ImVec2(at.x + 2 * (size.x + gap), at.y), size, "ACCURACY", accuracy_text(r.hits, r.shots),
         r.shots > 0 ? std::to_string(r.hits) + " of " + std::to_string(r.shots) + " shots hit"
                     : "no shots fired",
         fonts);
    ImGui::Dummy(ImVec2(total, size.y + 6 * s));
}

MenuAction summary_screen(const CampaignProgress& progress, const shell::Fonts& fonts, float w, float h) {
    ui::draw_backdrop(ImGui::GetBackgroundDrawList(), w, h, 0.85f);
    ui::begin_panel("##summary", "Level Complete", 640, 330, w, h, fonts);
    const LevelResult* result = progress.last_result();
    ui::centred_text(progress.campaign().name + "  \u00b7  level " + std::to_string(progress.index() + 1) +
                         " of " + std::to_string(progress.count()),
                     fonts.body, kMuted);
    ui::centred_text(result ? result->title : progress.current().title, fonts.hud, ui::kAccentActive);
    if (result) result_tiles(*result, fonts);
    const MenuAction action = from_row(ui::button_row({"Next Level", "Main Menu"}, fonts, 440, 1),
                                       MenuAction::NextLevel, MenuAction::MainMenu);
    ui::end_panel();
    return action;
}

MenuAction campaign_complete_screen(const CampaignProgress& progress, const shell::Fonts& fonts, float w,
                                    float h) {
    ui::draw_backdrop(ImGui::GetBackgroundDrawList(), w, h, 0.85f);
    const float rows = static_cast<float>(std::min<std::size_t>(progress.results().size(), 8));
    ui::begin_panel("##complete", "Campaign Complete", 760, 250 + 30 * rows, w, h, fonts);
    ui::centred_text(progress.campaign().name + ": every level won. The simulation is over.", fonts.body,
                     kMuted);
    results_table(progress, fonts);
    const MenuAction action = ui::big_button("Main Menu", fonts) ? MenuAction::MainMenu : MenuAction::None;
    ui::end_panel();
    return action;
}

MenuAction campaign_choice_screen(const CampaignSave& save, const shell::Fonts& fonts, float w, float h) {
    ui::draw_backdrop(ImGui::GetBackgroundDrawList(), w, h);
    ui::begin_panel("##campaign", "Campaign", 640, 400, w, h, fonts);
    const std::string name = save.name.empty() ? save.campaign.stem().string() : save.name;
    ui::centred_text(name + "  \u00b7  " + std::to_string(save.won.size()) + " of " +
                         std::to_string(save.level_count) + " levels won",
                     fonts.body, kMuted);
    LevelResult sum;
    for (const LevelResult& r : save.won) {
        sum.seconds += r.seconds;
        sum.robots_killed += r.robots_killed;
        sum.robots_total += r.robots_total;
        sum.shots += r.shots;
        sum.hits += r.hits;
    }
    result_tiles(sum, fonts);
    MenuAction action = MenuAction::None;
    const std::string next = "Continue: level " + std::to_string(save.won.size() + 1);
    if (ui::big_button(next.c_str(), fonts, 440)) action = MenuAction::Continue;
    switch (ui::button_row({"New campaign", "Back"}, fonts, 440, 1)) {
    case 0:
        action = MenuAction::NewCampaign;
        break;
    case 1:
        action = MenuAction::Back;
        break;
    }
    ui::end_panel();
    return action;
}

std::vector<LevelGroup> scan_custom_levels() {
    std::vector<LevelGroup> groups;
    groups.push_back({"Shipped levels", level::list_level_files(paths::data_root() / "levels",
                                                                {"dojo.json", "campaign.json"})});
    groups.push_back({"Your levels", level::list_level_files(paths::user_levels_dir())});
    return groups;
}

MenuAction custom_levels_screen(const std::vector<LevelGroup>& groups, const level::LevelFileEntry*& chosen,
                                const shell::Fonts& fonts, float w, float h) {
    ui::draw_backdrop(ImGui::GetBackgroundDrawList(), w, h);
    MenuAction action = MenuAction::None;
    // Taller where the window has room for more of the list (440 at 270p and 540p, 540 from 720p on).
    const float panel_h = std::clamp(h / ui::ui_scale(w, h) - 180.0f, 440.0f, 540.0f);
    ui::begin_panel("##custom", "Custom Level", 760, panel_h, w, h, fonts);
    const float s = scale();
    ui::centred_text("Play one level on its own. Your levels folder is listed below the shipped ones.",
                     fonts.body, kMuted);
    const float list_w = ImGui::GetWindowWidth() - 60 * s;
    ImGui::SetCursorPosX(30 * s);
    ImGui::PushStyleColor(ImGuiCol_ChildBg, IM_COL32(0, 0, 0, 0));
    ImGui::PushStyleColor(ImGuiCol_ScrollbarBg, IM_COL32(0, 0, 0, 20));
    ImGui::PushStyleColor(ImGuiCol_ScrollbarGrab, ui::kAccent);
    ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(8 * s, 6 * s));
    ImGui::BeginChild("##levels", ImVec2(list_w, (panel_h - 170.0f) * s), false);
    const float row_w = list_w - 18 * s; // room for the scroll bar
    for (const LevelGroup& group : groups) {
        group_heading(group, fonts, row_w);
        if (!group.folder.exists)
            note("No folder yet. Levels saved there from the editor will be listed here.", fonts, row_w);
        else if (group.folder.levels.empty())
            note("No levels here yet. Save a level from the editor into this folder to play it.", fonts,
                 row_w);
        for (const level::LevelFileEntry& entry : group.folder.levels) {
            if (!entry.ok()) {
                broken_row(entry, fonts, row_w);
                continue;
            }
            if (level_row(entry, fonts, row_w)) {
                chosen = &entry;
                action = MenuAction::PlayCustom;
            }
        }
        if (group.folder.left_out > 0)
            note("+" + std::to_string(group.folder.left_out) + " more files not listed", fonts, row_w);
        ImGui::Dummy(ImVec2(row_w, 4 * s));
    }
    ImGui::EndChild();
    ImGui::PopStyleVar();
    ImGui::PopStyleColor(3);
    if (ui::big_button("Back", fonts)) action = MenuAction::Back;
    ui::end_panel();
    return action;
}

} // namespace ks::runtime
