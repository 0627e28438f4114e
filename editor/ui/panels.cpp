// The left column, arranged: the entity palette (place_palette.h) over the Outliner and Layers tabs
// (outliner.h) and the Prefabs tab (prefab_palette.h); a click in the palette or the Prefabs tab arms the
// viewport's place tool. And the viewport's tool bar.
#include "ui/editor_app.h"
#include "ui/panel_style.h"

#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>

namespace ks::editor::ui {

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
    const PanelContext ctx = context();
    if (!dojo_tab_) {
        // The palette takes at most 40 % of the column and scrolls past that, so the tab bar under it stays
        // on screen in a small window; it is measured each frame for the next.
        const float most =
            std::max(ImGui::GetFrameHeightWithSpacing() * 2.0f, ImGui::GetContentRegionAvail().y * 0.4f);
        ImGui::BeginChild("palette", ImVec2(0, std::min(palette_height_, most)));
        const auto type = palette_.draw(placing_.type);
        palette_height_ = ImGui::GetCursorPosY();
        ImGui::EndChild();
        if (type) {
            logic_.end_pick(); // placing takes the viewport's clicks
            placing_.reset();
            placing_.type = *type;
        }
        ImGui::Separator();
    }
    outliner_.refresh(editor_); // cheap unless the level changed: the tree, issue badges, layer counts
    if (!ImGui::BeginTabBar("left_tabs")) {
        ImGui::End();
        return;
    }
    const bool outliner = ImGui::BeginTabItem("Outliner");
    spots_.here("tab.outliner");
    if (outliner) {
        shown_left_tab_ = LeftTab::Outliner;
        outliner_.outliner_tab(ctx);
        ImGui::EndTabItem();
    }
    const bool layers = ImGui::BeginTabItem(
        "Layers", nullptr, start_tab_ == LeftTab::Layers ? ImGuiTabItemFlags_SetSelected : 0);
    spots_.here("tab.layers");
    if (layers) {
        shown_left_tab_ = LeftTab::Layers;
        outliner_.layers_tab(ctx);
        ImGui::EndTabItem();
    }
    const bool prefabs = ImGui::BeginTabItem(
        "Prefabs", nullptr, start_tab_ == LeftTab::Prefabs ? ImGuiTabItemFlags_SetSelected : 0);
    spots_.here("tab.prefabs");
    if (prefabs) {
        shown_left_tab_ = LeftTab::Prefabs;
        if (const auto name = prefabs_.draw(ctx, placing_.prefab)) {
            logic_.end_pick(); // placing takes the viewport's clicks
            placing_.reset();
            placing_.prefab = *name;
        }
        ImGui::EndTabItem();
    }
    start_tab_ = LeftTab::Outliner;
    ImGui::EndTabBar();
    ImGui::End();
}

} // namespace ks::editor::ui
