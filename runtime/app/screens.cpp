#include "screens.h"

#include "campaign_screens.h"
#include "menu_style.h"
#include "version_label.h"

#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

namespace ks::runtime {

namespace {
// The controls that are not bindings (How to Play lists the bindings first, from the options).
const char* const kFixedControls[][2] = {
    {"Mouse", "look around"},
    {"Esc", "pause and free the mouse; back in menus"},
    {"Gamepad", "left stick move, right stick look, A jump"},
    {"", "right trigger shoot, X interact, Start pause"},
    {"1 - 9, 0, Tab (Dojo)", "play robot clips, reset, pick from the list"},
};

void two_columns(const char* left, const char* right, float split) {
    ImGui::SetCursorPosX(ImGui::GetWindowWidth() * split - ImGui::CalcTextSize(left).x - 12.0f);
    ImGui::PushStyleColor(ImGuiCol_Text, ui::kAccentActive);
    ImGui::TextUnformatted(left);
    ImGui::PopStyleColor();
    ImGui::SameLine(ImGui::GetWindowWidth() * split + 12.0f);
    ImGui::TextUnformatted(right);
}

// Easy, Normal, Hard (game/difficulty.h) as a three-step slider (three radio buttons do not fit the
// column); `label` places the row's label and the control. True on a change.
template <class Label>
bool difficulty_row(Options& o, const Label& label, float width) {
    label("Difficulty");
    int d = static_cast<int>(o.difficulty);
    if (!ui::value_slider("Difficulty", "##difficulty", d, 0, 2,
                          game::difficulty_title(static_cast<game::Difficulty>(d)), width))
        return false;
    o.difficulty = static_cast<game::Difficulty>(d);
    return true;
}
} // namespace

void loading_screen(float fraction, const std::string& step, const shell::Fonts& fonts, float w, float h) {
    ui::draw_backdrop(ImGui::GetBackgroundDrawList(), w, h, 1.25f);
    ui::begin_panel("##loading", "Killswitch", 560, 200, w, h, fonts);
    ImGui::Dummy(ImVec2(1, 16 * ui::ui_scale(w, h)));
    ui::centred_text("Loading the simulation...", fonts.hud);
    ui::progress_bar(fraction, step, fonts, 440);
    ui::end_panel();
}

MenuAction main_menu(const std::string& error, const shell::Fonts& fonts, float w, float h) {
    ui::draw_backdrop(ImGui::GetBackgroundDrawList(), w, h);
    version_label(fonts, w, h);
    MenuAction action = MenuAction::None;
    ui::begin_panel("##main", "Killswitch", 640, error.empty() ? 380 : 460, w, h, fonts);
    ui::centred_text("A virtual disaster simulator. The robots went rogue.", fonts.body);
    // The campaign first; the less used choices share rows (Quit grey).
    if (ui::big_button("Campaign", fonts, 420)) action = MenuAction::Campaign;
    switch (ui::button_row({"Play", "Custom level\u2026"}, fonts, 420)) {
    case 0:
        action = MenuAction::Play;
        break;
    case 1:
        action = MenuAction::CustomLevels;
        break;
    }
    switch (ui::button_row({"Dojo", "How to Play"}, fonts, 420)) {
    case 0:
        action = MenuAction::Dojo;
        break;
    case 1:
        action = MenuAction::HowTo;
        break;
    }
    switch (ui::button_row({"Options", "Credits", "Quit"}, fonts, 420, 2)) {
    case 0:
        action = MenuAction::Options;
        break;
    case 1:
        action = MenuAction::Credits;
        break;
    case 2:
        action = MenuAction::Quit;
        break;
    }
    if (!error.empty()) {
        ImGui::PushTextWrapPos(ImGui::GetWindowWidth() - 30 * ui::ui_scale(w, h));
        ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(190, 30, 30, 255));
        ImGui::TextWrapped("%s", error.c_str());
        ImGui::PopStyleColor();
        ImGui::PopTextWrapPos();
    }
    ui::end_panel();
    return action;
}

MenuAction pause_menu(const shell::Fonts& fonts, float w, float h, bool back_to_editor) {
    ui::draw_backdrop(ImGui::GetBackgroundDrawList(), w, h, 0.8f);
    MenuAction action = MenuAction::None;
    ui::begin_panel("##pause", "Paused", 560, back_to_editor ? 510 : 440, w, h, fonts);
    ui::centred_text("Click outside this panel or press Resume to play on.", fonts.body);
    if (ui::big_button("Resume", fonts)) action = MenuAction::Resume;
    if (back_to_editor && ui::big_button("Back to editor", fonts)) action = MenuAction::BackToEditor;
    if (ui::big_button("How to Play", fonts)) action = MenuAction::HowTo;
    if (ui::big_button("Options", fonts)) action = MenuAction::Options;
    if (ui::big_button("Credits", fonts)) action = MenuAction::Credits;
    if (ui::big_button("Main Menu", fonts)) action = MenuAction::MainMenu;
    ui::end_panel();
    return action;
}

MenuAction death_menu(const shell::Fonts& fonts, float w, float h) {
    // The death screen tints red: the simulation "killed" the player.
    ImDrawList* bg = ImGui::GetBackgroundDrawList();
    ui::draw_backdrop(bg, w, h, 0.6f);
    bg->AddRectFilled(ImVec2(0, 0), ImVec2(w, h), IM_COL32(150, 0, 0, 120));
    MenuAction action = MenuAction::None;
    ui::begin_panel("##death", "You Died", 520, 240, w, h, fonts);
    ui::centred_text("The robots got you. The simulation restarts on your call.", fonts.body);
    if (ui::big_button("Retry", fonts)) action = MenuAction::Retry;
    if (ui::big_button("Main Menu", fonts)) action = MenuAction::MainMenu;
    ui::end_panel();
    return action;
}

MenuAction win_menu(const LevelResult& result, const shell::Fonts& fonts, float w, float h) {
    ui::draw_backdrop(ImGui::GetBackgroundDrawList(), w, h, 0.85f);
    MenuAction action = MenuAction::None;
    ui::begin_panel("##win", "You Won", 600, 380, w, h, fonts);
    ui::centred_text("Simulation ended", fonts.hud, ui::kAccentActive);
    result_tiles(result, fonts);
    if (ui::big_button("Play Again", fonts)) action = MenuAction::Retry;
    if (ui::big_button("Main Menu", fonts)) action = MenuAction::MainMenu;
    ui::end_panel();
    return action;
}

MenuAction how_to_play(const Options& options, const shell::Fonts& fonts, float w, float h) {
    ui::draw_backdrop(ImGui::GetBackgroundDrawList(), w, h);
    MenuAction action = MenuAction::None;
    // 500 at 720p; in a smaller window the controls list scrolls above Back.
    const float panel_h = std::clamp(h / ui::ui_scale(w, h) - 80.0f, 440.0f, 500.0f);
    ui::begin_panel("##howto", "How to Play", 900, panel_h, w, h, fonts);
    ImGui::PushTextWrapPos(ImGui::GetWindowWidth() - 30 * ui::ui_scale(w, h));
    ImGui::TextWrapped("Survive the rogue robots and reach the computer at the end of the level to end the "
                       "simulation. Shoot gas cylinders to blow up robots near them - keep your distance. "
                       "Pick up health (red), shield (blue) and ammo (yellow) on the way.");
    ImGui::PopTextWrapPos();
    if (fonts.body) ImGui::PushFont(fonts.body);
    ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(10 * ui::ui_scale(w, h), 5 * ui::ui_scale(w, h)));
    ImGui::PushStyleColor(ImGuiCol_ScrollbarBg, IM_COL32(0, 0, 0, 20));
    ImGui::PushStyleColor(ImGuiCol_ScrollbarGrab, ui::kAccent);
    ImGui::BeginChild("##howto_keys", ImVec2(0, ImGui::GetContentRegionAvail().y - 70 * ui::ui_scale(w, h)),
                      false, ImGuiWindowFlags_NoBackground | ImGuiWindowFlags_NavFlattened);
    const auto& b = options.bindings;
    const std::string move = keys_text(b, Action::Forward) + ", " + keys_text(b, Action::Left) + ", " +
                             keys_text(b, Action::Back) + ", " + keys_text(b, Action::Right);
    two_columns(move.c_str(), "move forward, left, back, right", 0.36f);
    for (Action a : {Action::Jump, Action::Fire, Action::Interact, Action::Pause, Action::Mute}) {
        std::string what = action_info(a).label; // "Jump" → "jump", as the other rows
        what[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(what[0])));
        two_columns(keys_text(b, a).c_str(), what.c_str(), 0.36f);
    }
    for (const auto& row : kFixedControls) two_columns(row[0], row[1], 0.36f);
    ImGui::EndChild();
    ImGui::PopStyleColor(2);
    ImGui::PopStyleVar();
    if (fonts.body) ImGui::PopFont();
    if (ui::big_button("Back", fonts)) action = MenuAction::Back;
    ui::end_panel();
    return action;
}

MenuAction credits(const shell::Fonts& fonts, float w, float h) {
    ui::draw_backdrop(ImGui::GetBackgroundDrawList(), w, h);
    MenuAction action = MenuAction::None;
    ui::begin_panel("##credits", "Credits", 760, 440, w, h, fonts);
    if (fonts.body) ImGui::PushFont(fonts.body);
    two_columns("Killswitch", "the Killswitch team: engine, physics, animation,", 0.3f);
    two_columns("", "renderer, game rules, runtime, level editor, assets", 0.3f);
    two_columns("Based on", "\"Interactive Graphics - Final Project\" (2021),", 0.3f);
    two_columns("", "a three.js first-person shooter and robot Dojo", 0.3f);
    two_columns("Fonts", "DejaVu Sans, Sans Bold and Sans Mono -", 0.3f);
    two_columns("", "Bitstream Vera licence (free to use, modify and", 0.3f);
    two_columns("", "redistribute); assets/fonts/LICENSE-DejaVu.txt", 0.3f);
    two_columns("Libraries", "GLFW, Dear ImGui, GLM, assimp, stb, nlohmann/json,", 0.3f);
    two_columns("", "libepoxy, doctest", 0.3f);
    if (fonts.body) ImGui::PopFont();
    if (ui::big_button("Back", fonts)) action = MenuAction::Back;
    ui::end_panel();
    return action;
}

MenuAction options_panel(Options& o, bool& changed, const shell::Fonts& fonts, float w, float h) {
    ui::draw_backdrop(ImGui::GetBackgroundDrawList(), w, h);
    MenuAction action = MenuAction::None;
    const float s = ui::ui_scale(w, h);
    // Two columns (controls and picture | sound) so every row fits a 270-pixel-high window too.
    ui::begin_panel("##options", "Options", 1000, 440, w, h, fonts);
    ImGui::PushStyleColor(ImGuiCol_FrameBg, IM_COL32(205, 214, 218, 255));
    ImGui::PushStyleColor(ImGuiCol_FrameBgHovered, IM_COL32(190, 205, 212, 255));
    ImGui::PushStyleColor(ImGuiCol_FrameBgActive, IM_COL32(180, 198, 206, 255));
    ImGui::PushStyleColor(ImGuiCol_SliderGrab, ui::kAccent);
    ImGui::PushStyleColor(ImGuiCol_SliderGrabActive, ui::kAccentActive);
    ImGui::PushStyleColor(ImGuiCol_CheckMark, ui::kAccent);
    ImGui::PushStyleVar(ImGuiStyleVar_FrameRounding, 5.0f * s);
    ImGui::PushStyleVar(ImGuiStyleVar_GrabMinSize, 18.0f * s);
    ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(10 * s, 9 * s));
    if (fonts.body) ImGui::PushFont(fonts.body);
    const float column_w = (ImGui::GetWindowWidth() - 100 * s) * 0.5f, label_w = 200 * s;
    const float top = ImGui::GetCursorPosY();
    float column_x = 40 * s;
    auto label = [&](const char* text) {
        ImGui::SetCursorPosX(column_x);
        ImGui::AlignTextToFramePadding();
        ImGui::TextUnformatted(text);
        ImGui::SameLine(column_x + label_w);
        ImGui::SetNextItemWidth(column_w - label_w);
    };
    const float slider_w = column_w - label_w;
    auto shown = [](const char* format, float value) {
        char text[32];
        std::snprintf(text, sizeof text, format, static_cast<double>(value));
        return std::string(text);
    };
    label("Mouse sensitivity");
    changed |=
        ui::value_slider("Mouse sensitivity", "##sens", o.mouse_sensitivity, Options::kMinSensitivity,
                         Options::kMaxSensitivity, 0.01f, shown("%.2f", o.mouse_sensitivity), slider_w);
    label("Field of view");
    changed |= ui::value_slider("Field of view", "##fov", o.fov_degrees, Options::kMinFov, Options::kMaxFov,
                                1.0f, shown("%.0f deg", o.fov_degrees), slider_w);
    label("Invert mouse Y");
    changed |= ImGui::Checkbox("##invert", &o.invert_y);
    ui::record_button("Invert mouse Y");
    // For slow machines: fewer pixels (the HUD and menus stay sharp) and cheaper shading.
    label("Render scale");
    {
        static const char* names[] = {"Auto", "25 %", "50 %", "75 %", "100 %"};
        int step =
            o.render_scale <= 0.0f ? 0 : std::clamp(static_cast<int>(o.render_scale * 4.0f + 0.5f), 1, 4);
        if (ui::value_slider("Render scale", "##scale", step, 0, 4, names[step], slider_w)) {
            o.render_scale = step == 0 ? 0.0f : static_cast<float>(step) * 0.25f;
            changed = true;
        }
    }
    label("Quality");
    {
        int q = static_cast<int>(o.quality);
        bool moved = ImGui::RadioButton("Auto", &q, 0);
        ui::record_button("Auto");
        ImGui::SameLine();
        moved |= ImGui::RadioButton("Full", &q, 1);
        ui::record_button("Full");
        ImGui::SameLine();
        moved |= ImGui::RadioButton("Fast", &q, 2);
        ui::record_button("Fast");
        if (moved) {
            o.quality = static_cast<QualityOption>(q);
            changed = true;
        }
    }
    const float bottom = ImGui::GetCursorPosY();
    // The sound column.
    column_x = 60 * s + column_w;
    ImGui::SetCursorPosY(top);
    auto volume = [&](const char* text, const char* id, float& value) {
        label(text);
        float percent = value * 100.0f;
        if (ui::value_slider(text, id, percent, 0.0f, 100.0f, 1.0f, shown("%.0f %%", percent), slider_w)) {
            value = percent / 100.0f;
            changed = true;
        }
    };
    volume("Master volume", "##master", o.master_volume);
    volume("Effects", "##effects", o.effects_volume);
    volume("Music & ambience", "##ambience", o.ambience_volume);
    label("Mute (M)");
    changed |= ImGui::Checkbox("##mute", &o.muted);
    ui::record_button("Mute (M)");
    changed |= difficulty_row(o, label, slider_w);
    label("Logic debugger (F3)");
    changed |= ImGui::Checkbox("##logic_debugger", &o.logic_debugger);
    ui::record_button("Logic debugger (F3)");
    ImGui::SetCursorPosY(std::max(bottom, ImGui::GetCursorPosY()));
    ImGui::SetCursorPosX(40 * s);
    ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(90, 100, 110, 255));
    ImGui::TextUnformatted(("Saved to " + options_path().string()).c_str());
    ImGui::PopStyleColor();
    if (fonts.body) ImGui::PopFont();
    ImGui::PopStyleVar(3);
    ImGui::PopStyleColor(6);
    switch (ui::button_row({"Controls\u2026", "Back"}, fonts, 560)) {
    case 0:
        action = MenuAction::Controls;
        break;
    case 1:
        action = MenuAction::Back;
        break;
    }
    ui::end_panel();
    return action;
}

} // namespace ks::runtime
