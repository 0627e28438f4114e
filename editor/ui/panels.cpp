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

namespace {
// A small button that shows whether it is on (the highlight of the view buttons); true when clicked.
bool toggle_button(const char* label, bool on) {
    if (on) ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.26f, 0.45f, 0.75f, 1));
    const bool clicked = ImGui::SmallButton(label);
    if (on) ImGui::PopStyleColor();
    return clicked;
}
} // namespace

// One row that fits the viewport's width at 1280 x 720 in every gizmo mode: the modes and views are small
// buttons, and where even that is too wide "Perspective" shortens to "Persp"; Snap comes before the views.
void EditorApp::viewport_toolbar() {
    for (GizmoMode m : {GizmoMode::Move, GizmoMode::Rotate, GizmoMode::Scale}) {
        if (toggle_button(gizmo_mode_name(m), gizmo_.mode == m)) gizmo_.mode = m;
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
    // Snap and the grid steps before the view buttons: in a narrow window the view buttons (also on the
    // numpad) run off the bar's end, never the Snap control.
    ImGui::Checkbox("Snap", &editor_.grid().snap);
    spots_.here("toolbar.snap");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(48);
    ImGui::DragFloat("##grid", &editor_.grid().step, 0.05f, 0.05f, 16.0f, "%g u");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Grid step (origin snapping, nudge distance)");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(44);
    ImGui::DragFloat("##rot", &editor_.grid().rotation_step, 0.5f, 1.0f, 90.0f, "%.0f\xc2\xb0");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Rotation snapping step");
    constexpr ViewMode kViews[] = {ViewMode::Perspective, ViewMode::Top, ViewMode::Front, ViewMode::Side};
    const ImGuiStyle& style = ImGui::GetStyle();
    const float gap = style.ItemInnerSpacing.x; // between the view buttons: they read as one group
    ImGui::SameLine(0, style.ItemSpacing.x * 2);
    float full = ImGui::CalcTextSize("4-up").x + style.FramePadding.x * 2 + gap * 4;
    for (ViewMode v : kViews) full += ImGui::CalcTextSize(view_mode_name(v)).x + style.FramePadding.x * 2;
    const bool narrow = ImGui::GetContentRegionAvail().x < full;
    for (ViewMode v : kViews) {
        if (v != kViews[0]) ImGui::SameLine(0, gap);
        const bool shorten = narrow && v == ViewMode::Perspective;
        if (toggle_button(shorten ? "Persp" : view_mode_name(v), view_.mode == v)) set_view(v);
        if (shorten && ImGui::IsItemHovered()) ImGui::SetTooltip("Perspective (Numpad 5)");
    }
    ImGui::SameLine(0, gap);
    if (toggle_button("4-up", quad_.on)) toggle_quad();
    spots_.here("view_4up");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Top, front, side and perspective at once, each with its own camera (Numpad 0)");
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
