// The side and bottom panels: outliner, palette, viewport tool bar, validation, history, log. The inspector
// is in inspector.cpp.
#include "ui/editor_app.h"
#include "ui/panel_style.h"

#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>

namespace ks::editor::ui {

void EditorApp::palette_bar() {
    ImGui::TextDisabled("Place:");
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    bool first = true;
    for (auto type : level::all_types()) {
        const float w = ImGui::CalcTextSize(type_label(type)).x + ImGui::GetStyle().FramePadding.x * 2;
        if (!first) {
            ImGui::SameLine();
            if (ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + w > right) ImGui::NewLine();
        }
        first = false;
        const bool active = placing_.type == type;
        if (active) ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.25f, 0.55f, 0.3f, 1));
        ImGui::PushStyleColor(ImGuiCol_Text, type_colour(type));
        if (ImGui::SmallButton(type_label(type))) {
            if (pick_) end_pick(); // placing takes the viewport's clicks
            placing_.reset();
            placing_.type = type;
        }
        ImGui::PopStyleColor(active ? 2 : 1);
        palette_rects_[static_cast<size_t>(type)] = {
            Vec2(ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y),
            Vec2(ImGui::GetItemRectMax().x, ImGui::GetItemRectMax().y)};
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "Click, then click in the viewport to place a %s on the surface under the cursor "
                "(snapped to the grid). Shift+click places several.",
                type_label(type));
    }
}

void EditorApp::viewport_toolbar() {
    for (GizmoMode m : {GizmoMode::Move, GizmoMode::Rotate, GizmoMode::Scale}) {
        if (ImGui::RadioButton(gizmo_mode_name(m), gizmo_.mode == m)) gizmo_.mode = m;
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Gizmo mode (W / E / R)");
        ImGui::SameLine();
    }
    if (gizmo_.mode == GizmoMode::Rotate) { // the space only matters to the rings
        if (ImGui::SmallButton(gizmo_.space == RotationSpace::World ? "World" : "Local"))
            gizmo_.space = gizmo_.space == RotationSpace::World ? RotationSpace::Local : RotationSpace::World;
        spots_.here("gizmo_space");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("The rotate rings turn about the world's axes or the entity's own (X toggles)");
        ImGui::SameLine();
    }
    ImGui::TextDisabled("|");
    for (ViewMode v : {ViewMode::Perspective, ViewMode::Top, ViewMode::Front, ViewMode::Side}) {
        ImGui::SameLine();
        const bool active = view_.mode == v;
        if (active) ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.26f, 0.45f, 0.75f, 1));
        if (ImGui::SmallButton(view_mode_name(v))) set_view(v);
        if (active) ImGui::PopStyleColor();
    }
    ImGui::SameLine();
    if (quad_.on) ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.26f, 0.45f, 0.75f, 1));
    if (ImGui::SmallButton("4-up")) toggle_quad();
    if (quad_.on) ImGui::PopStyleColor();
    spots_.here("view_4up");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Top, front, side and perspective at once, each with its own camera (Numpad 0)");
    ImGui::SameLine();
    ImGui::TextDisabled("|");
    ImGui::SameLine();
    ImGui::Checkbox("Snap", &editor_.grid().snap);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(70);
    ImGui::DragFloat("##grid", &editor_.grid().step, 0.05f, 0.05f, 16.0f, "%.2f u");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Grid step (origin snapping, nudge distance)");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(70);
    ImGui::DragFloat("##rot", &editor_.grid().rotation_step, 0.5f, 1.0f, 90.0f, "%.0f deg");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Rotation snapping step");
}

void EditorApp::outliner_panel(float x, float y, float w, float h) {
    place_panel(x, y, w, h);
    ImGui::Begin("Outliner", nullptr, kPanelFlags);
    if (!dojo_tab_) {
        // The palette takes at most 40 % of the column and scrolls past that, so the tab bar under it stays
        // on screen in a small window; it is measured each frame for the next.
        const float most =
            std::max(ImGui::GetFrameHeightWithSpacing() * 2.0f, ImGui::GetContentRegionAvail().y * 0.4f);
        ImGui::BeginChild("palette", ImVec2(0, std::min(palette_height_, most)));
        palette_bar();
        palette_height_ = ImGui::GetCursorPosY();
        ImGui::EndChild();
        ImGui::Separator();
    }
    refresh_outliner_tree(); // cheap unless the level changed: the tree, issue badges, layer counts
    if (!ImGui::BeginTabBar("left_tabs")) {
        ImGui::End();
        return;
    }
    const bool outliner = ImGui::BeginTabItem("Outliner");
    spots_.here("tab.outliner");
    if (outliner) {
        shown_left_tab_ = LeftTab::Outliner;
        outliner_list();
        ImGui::EndTabItem();
    }
    const bool layers = ImGui::BeginTabItem(
        "Layers", nullptr, start_tab_ == LeftTab::Layers ? ImGuiTabItemFlags_SetSelected : 0);
    spots_.here("tab.layers");
    if (layers) {
        shown_left_tab_ = LeftTab::Layers;
        layers_section();
        ImGui::EndTabItem();
    }
    const bool prefabs = ImGui::BeginTabItem(
        "Prefabs", nullptr, start_tab_ == LeftTab::Prefabs ? ImGuiTabItemFlags_SetSelected : 0);
    spots_.here("tab.prefabs");
    if (prefabs) {
        shown_left_tab_ = LeftTab::Prefabs;
        prefab_palette();
        ImGui::EndTabItem();
    }
    start_tab_ = LeftTab::Outliner;
    ImGui::EndTabBar();
    ImGui::End();
}

// The Outliner tab: type filter, search and the entity tree (outliner_tree.cpp).
void EditorApp::outliner_list() {
    ImGui::SetNextItemWidth(-1);
    const char* preview =
        type_filter_ < 0 ? "All types" : type_label(static_cast<level::EntityType>(type_filter_));
    if (ImGui::BeginCombo("##type", preview)) {
        if (ImGui::Selectable("All types", type_filter_ < 0)) type_filter_ = -1;
        for (auto t : level::all_types())
            if (ImGui::Selectable(type_label(t), type_filter_ == static_cast<int>(t)))
                type_filter_ = static_cast<int>(t);
        ImGui::EndCombo();
    }
    ImGui::SetNextItemWidth(-1);
    ImGui::InputTextWithHint("##search", "Search names...", search_, sizeof(search_));
    if (type_filter_ >= 0 && ImGui::Button("Select all of this type", ImVec2(-1, 0)))
        editor_.select_all_of_type(static_cast<level::EntityType>(type_filter_));
    ImGui::BeginChild("entities", ImVec2(0, 0), false);
    outliner_tree();
    ImGui::EndChild();
}

void EditorApp::validation_panel(float x, float y, float w, float h) {
    place_panel(x, y, w, h);
    const auto& issues = editor_.issues();
    const int errors = count_errors(issues);
    char title[96];
    std::snprintf(title, sizeof(title), "Validation: %d errors, %d warnings###Validation", errors,
                  static_cast<int>(issues.size()) - errors);
    ImGui::Begin(title, nullptr, kPanelFlags);
    if (issues.empty())
        ImGui::TextColored(ImVec4(0.4f, 1.0f, 0.5f, 1), "No problems: the level is ready to play.");
    for (size_t i = 0; i < issues.size(); ++i) {
        const Issue issue = issues[i]; // a copy: a fix changes the list
        ImGui::PushID(static_cast<int>(i));
        const bool error = issue.severity == IssueSeverity::Error;
        ImGui::TextColored(error ? ImVec4(1, 0.35f, 0.3f, 1) : ImVec4(1, 0.8f, 0.3f, 1), "%s",
                           error ? "ERR " : "WARN");
        ImGui::SameLine();
        // The message wraps in the narrow column (a logic finding names entity, link and target); the quick
        // fix goes under it, where its label has the width it needs.
        ImGui::TextWrapped("[%s] %s", rule_name(issue.rule), issue.message.c_str());
        if (ImGui::IsItemHovered()) {
            ImGui::GetWindowDrawList()->AddRectFilled(ImGui::GetItemRectMin(), ImGui::GetItemRectMax(),
                                                      IM_COL32(90, 120, 180, 50));
            ImGui::SetTooltip("Click to select what this is about");
        }
        if (ImGui::IsItemClicked()) report(editor_.select_issue(issue), "select");
        if (issue.fix.available()) {
            ImGui::Indent(40.0f);
            const bool fix = ImGui::SmallButton(issue.fix.label.c_str());
            ImGui::Unindent(40.0f);
            if (fix) {
                report(editor_.apply_quick_fix(issue), "quick fix");
                ImGui::PopID();
                break;
            }
        }
        ImGui::PopID();
    }
    ImGui::End();
}

void EditorApp::history_panel(float x, float y, float w, float h) {
    place_panel(x, y, w, h);
    ImGui::Begin("History", nullptr, kPanelFlags);
    const auto& history = editor_.history();
    const auto names = history.step_names();
    const int done = static_cast<int>(history.undo_count());
    int target = -1;
    if (ImGui::Selectable("(opened)", done == 0)) target = 0;
    for (int i = 0; i < static_cast<int>(names.size()); ++i) {
        ImGui::PushID(i);
        ImGui::PushStyleColor(ImGuiCol_Text,
                              i < done ? ImVec4(0.9f, 0.92f, 1, 1) : ImVec4(0.5f, 0.5f, 0.55f, 1));
        char label[160];
        std::snprintf(label, sizeof(label), "%3d  %s", i + 1, names[static_cast<size_t>(i)].c_str());
        if (ImGui::Selectable(label, i + 1 == done)) target = i + 1;
        ImGui::PopStyleColor();
        ImGui::PopID();
    }
    if (target >= 0) { // jump: undo or redo until `target` steps are done
        while (static_cast<int>(editor_.history().undo_count()) > target && editor_.undo()) {
        }
        while (static_cast<int>(editor_.history().undo_count()) < target && editor_.redo()) {
        }
    }
    ImGui::End();
}

void EditorApp::log_panel(float x, float y, float w, float h) {
    place_panel(x, y, w, h);
    ImGui::Begin("Log", nullptr, kPanelFlags);
    if (ImGui::SmallButton("Clear")) log_.clear();
    ImGui::SameLine();
    ImGui::TextDisabled("editor messages, and the play-test's output");
    ImGui::BeginChild("lines");
    for (const auto& [line, error] : log_) {
        if (error)
            ImGui::TextColored(ImVec4(1, 0.45f, 0.4f, 1), "%s", line.c_str());
        else
            ImGui::TextUnformatted(line.c_str());
    }
    if (scroll_log_) ImGui::SetScrollHereY(1.0f), scroll_log_ = false;
    ImGui::EndChild();
    ImGui::End();
}

} // namespace ks::editor::ui
