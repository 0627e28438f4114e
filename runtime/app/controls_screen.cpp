#include "controls_screen.h"

#include "menu_style.h"
#include "screens.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace ks::runtime {

namespace {
constexpr ImU32 kConflict = IM_COL32(200, 30, 30, 255);
constexpr ImU32 kQuiet = IM_COL32(90, 100, 110, 255);

// The gamepad's fixed layout (GLFW's standard mapping: Xbox names, the same buttons on any pad).
const char* const kPadRows[][2] = {
    {"Left stick", "move"},         {"Right stick", "look"}, {"A", "jump"},
    {"Right trigger", "shoot"},     {"X", "interact"},       {"Start", "pause / resume"},
    {"D-pad, A, B", "menus, back"},
};

void text_at(float x, const char* text, ImU32 colour) {
    ImGui::SetCursorPosX(x);
    ImGui::AlignTextToFramePadding();
    ImGui::PushStyleColor(ImGuiCol_Text, colour);
    ImGui::TextUnformatted(text);
    ImGui::PopStyleColor();
}

// One key slot's button: the key's name, "-" when empty, "Press a key..." while it waits.
bool key_button(Action a, std::size_t slot, const Options& o, const ControlsState& st, bool clash,
                float width) {
    const bool waiting = st.waiting_action == static_cast<int>(a) && st.waiting_slot == slot;
    const int code = o.bindings[a][slot];
    std::string text = waiting ? "Press a key\u2026" : code == kNoKey ? "-" : key_name(code);
    char id[64];
    std::snprintf(id, sizeof(id), "%s##%s%zu", text.c_str(), action_info(a).id, slot);
    const ImU32 face = waiting                   ? ui::kAccent
                       : clash && code != kNoKey ? IM_COL32(245, 205, 205, 255)
                                                 : IM_COL32(205, 214, 218, 255);
    ImGui::PushStyleColor(ImGuiCol_Button, face);
    ImGui::PushStyleColor(ImGuiCol_ButtonHovered, waiting ? ui::kAccentHover : IM_COL32(190, 205, 212, 255));
    ImGui::PushStyleColor(ImGuiCol_ButtonActive, ui::kAccentActive);
    ImGui::PushStyleColor(ImGuiCol_Text, waiting ? IM_COL32(255, 255, 255, 255)
                                         : clash ? kConflict
                                                 : ui::kInk);
    const bool clicked = ImGui::Button(id, ImVec2(width, 0));
    ImGui::PopStyleColor(4);
    char label[64];
    std::snprintf(label, sizeof(label), "bind %s %zu", action_info(a).id, slot + 1);
    ui::record_button(label);
    ui::nav_focus_ring();
    return clicked;
}

void bindings_table(Options& o, ControlsState& st, float x, float width) {
    const float s = ui::display_scale();
    const float key_w = 130 * s, gap = 10 * s;
    const float key_x = x + width - 2 * key_w - gap;
    const auto clash = conflicts(o.bindings);
    const float top = ImGui::GetCursorPosY();
    text_at(x, "Action", kQuiet);
    for (std::size_t slot = 0; slot < kSlots; ++slot) {
        const char* head = slot == 0 ? "Key" : "Alternative";
        const float cx = key_x + static_cast<float>(slot) * (key_w + gap) + key_w * 0.5f;
        ImGui::SameLine(cx - ImGui::CalcTextSize(head).x * 0.5f);
        ImGui::PushStyleColor(ImGuiCol_Text, kQuiet);
        ImGui::TextUnformatted(head);
        ImGui::PopStyleColor();
    }
    ImGui::SetCursorPosY(top + ImGui::GetFrameHeight() + 2 * s);
    for (std::size_t i = 0; i < kActionCount; ++i) {
        const auto a = static_cast<Action>(i);
        text_at(x, kActionInfo[i].label, clash[i] ? kConflict : ui::kInk);
        for (std::size_t slot = 0; slot < kSlots; ++slot) {
            ImGui::SameLine(key_x + static_cast<float>(slot) * (key_w + gap));
            if (key_button(a, slot, o, st, clash[i], key_w)) {
                st.waiting_action = static_cast<int>(i);
                st.waiting_slot = slot;
                st.message = "Press the new key or mouse button for " + std::string(kActionInfo[i].label) +
                             " (Esc cancels, Backspace clears).";
            }
        }
    }
}

void gamepad_column(Options& o, bool& changed, float x, float width) {
    const float s = ui::display_scale();
    text_at(x, "Gamepad", kQuiet);
    for (const auto& row : kPadRows) {
        text_at(x, row[0], ui::kAccentActive);
        ImGui::SameLine(x + 170 * s);
        ImGui::TextUnformatted(row[1]);
    }
    auto slider = [&](const char* label, const char* id, float& value, float lo, float hi, const char* format,
                      float shown_scale, float step) {
        text_at(x, label, ui::kInk);
        ImGui::SameLine(x + 170 * s);
        float shown = value * shown_scale;
        char text[32];
        std::snprintf(text, sizeof text, format, static_cast<double>(shown));
        if (ui::value_slider(label, id, shown, lo * shown_scale, hi * shown_scale, step, text,
                             width - 170 * s)) {
            value = shown / shown_scale;
            changed = true;
        }
    };
    slider("Look speed", "##padlook", o.pad_look_sensitivity, Options::kMinSensitivity,
           Options::kMaxSensitivity, "%.2f", 1.0f, 0.01f);
    slider("Dead zone", "##paddead", o.pad_dead_zone, Options::kMinDeadZone, Options::kMaxDeadZone, "%.0f %%",
           100.0f, 1.0f);
}
} // namespace

MenuAction controls_screen(Options& o, ControlsState& st, bool& changed, const shell::Fonts& fonts, float w,
                           float h) {
    ui::draw_backdrop(ImGui::GetBackgroundDrawList(), w, h);
    MenuAction action = MenuAction::None;
    const float s = ui::ui_scale(w, h);
    // As tall as the window allows (520 at 720p); in a small window the table and the pad column scroll
    // (keyboard and pad navigation scroll to the highlighted key) and the note and buttons stay.
    const float panel_h = std::clamp(h / s - 80.0f, 420.0f, 510.0f);
    ui::begin_panel("##controls", "Controls", 1060, panel_h, w, h, fonts);
    ImGui::PushStyleColor(ImGuiCol_FrameBg, IM_COL32(205, 214, 218, 255));
    ImGui::PushStyleColor(ImGuiCol_FrameBgHovered, IM_COL32(190, 205, 212, 255));
    ImGui::PushStyleColor(ImGuiCol_FrameBgActive, IM_COL32(180, 198, 206, 255));
    ImGui::PushStyleColor(ImGuiCol_SliderGrab, ui::kAccent);
    ImGui::PushStyleColor(ImGuiCol_SliderGrabActive, ui::kAccentActive);
    ImGui::PushStyleColor(ImGuiCol_ScrollbarBg, IM_COL32(0, 0, 0, 20));
    ImGui::PushStyleColor(ImGuiCol_ScrollbarGrab, ui::kAccent);
    ImGui::PushStyleVar(ImGuiStyleVar_FrameRounding, 5.0f * s);
    ImGui::PushStyleVar(ImGuiStyleVar_GrabMinSize, 18.0f * s);
    ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(8 * s, 4 * s));
    ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(10 * s, 7 * s));
    if (fonts.body) ImGui::PushFont(fonts.body);
    ImGui::BeginChild("##controls_body", ImVec2(0, (panel_h - 168.0f) * s), false,
                      ImGuiWindowFlags_NoBackground | ImGuiWindowFlags_NavFlattened);
    const float top = ImGui::GetCursorPosY();
    const float left_w = 580 * s, right_x = 10 * s + left_w + 50 * s;
    bindings_table(o, st, 10 * s, left_w);
    const float bottom = ImGui::GetCursorPosY();
    ImGui::SetCursorPosY(top);
    gamepad_column(o, changed, right_x, ImGui::GetWindowWidth() - right_x - 20 * s);
    ImGui::SetCursorPosY(std::max(bottom, ImGui::GetCursorPosY()));
    ImGui::EndChild();
    ImGui::Dummy(ImVec2(1, 2 * s));
    const auto clash = conflicts(o.bindings);
    const bool any_clash = std::find(clash.begin(), clash.end(), true) != clash.end();
    std::string note = st.message;
    if (note.empty())
        note = any_clash ? "Keys in red do two things: click one and press another key."
                         : "Click a key to change it. A key already used swaps with this one.";
    ImGui::SetCursorPosX(40 * s);
    ImGui::PushStyleColor(ImGuiCol_Text, any_clash && st.message.empty() ? kConflict : ui::kAccentActive);
    ImGui::TextUnformatted(note.c_str());
    ImGui::PopStyleColor();
    if (fonts.body) ImGui::PopFont();
    ImGui::PopStyleVar(4);
    ImGui::PopStyleColor(7);
    switch (ui::button_row({"Reset to defaults", "Back"}, fonts, 560)) {
    case 0:
        o.bindings = Bindings::defaults();
        o.pad_look_sensitivity = Options{}.pad_look_sensitivity;
        o.pad_dead_zone = Options{}.pad_dead_zone;
        st.cancel();
        st.message = "Every key and the gamepad settings are back to their defaults.";
        changed = true;
        break;
    case 1:
        st.cancel();
        action = MenuAction::Back;
        break;
    }
    ui::end_panel();
    return action;
}

} // namespace ks::runtime
