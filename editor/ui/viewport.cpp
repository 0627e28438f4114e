// The level viewport's panel (level_viewport.h), the ImGui pass: the tool bar, the single view's picture,
// and over every view the axis views' grid, the level logic, the play-test report, the gizmo, the box being
// dragged, the axis indicator, the status line and the hints.
#include "model/edit_groups.h"
#include "ui/gizmo_draw.h"
#include "ui/level_viewport.h"
#include "ui/structure_actions.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ks::editor::ui {

namespace {
// The world's axes as the view turns them, in the view's top-right corner.
void axis_indicator(ImDrawList* draw, const ViewCamera& view, Vec2 corner) {
    const Mat4 view_matrix = view.camera.view();
    const char* names[3] = {"X", "Y", "Z"};
    const ImU32 colours[3] = {IM_COL32(235, 70, 70, 255), IM_COL32(110, 215, 80, 255),
                              IM_COL32(70, 130, 240, 255)};
    for (int i = 0; i < 3; ++i) {
        Vec3 axis(0.0f);
        axis[i] = 1.0f;
        const Vec3 v = Mat3(view_matrix) * axis;
        const ImVec2 tip(corner.x + v.x * 24.0f, corner.y - v.y * 24.0f);
        draw->AddLine(ImVec2(corner.x, corner.y), tip, colours[i], 2.0f);
        draw->AddText(ImVec2(tip.x - 3, tip.y - 7), colours[i], names[i]);
    }
}

void axis_grid(ImDrawList* draw, const ViewCamera& view, float grid_step, Vec2 origin) {
    // The view plane's grid on screen, over the picture: lines at least 10 pixels apart (the grid step
    // doubled until they are), majors every 16 units (a wall), the world axes through 0.
    const GridPlan plan = plan_axis_grid(view, grid_step, 10.0f);
    const Vec2 size = view.viewport();
    const ImU32 axis_colours[3] = {IM_COL32(235, 80, 70, 170), IM_COL32(110, 215, 80, 170),
                                   IM_COL32(80, 130, 255, 170)};
    auto colour = [&](float coordinate, int other_axis) {
        if (std::abs(coordinate) < plan.step * 0.01f) return axis_colours[other_axis];
        const float major = std::max(16.0f, plan.step * 4.0f);
        return std::abs(std::remainder(coordinate, major)) < plan.step * 0.01f ? IM_COL32(190, 205, 230, 80)
                                                                               : IM_COL32(170, 180, 200, 34);
    };
    const Vec3 at = view.camera.position + view.forward();
    // Lines of constant u are vertical on screen, lines of constant v horizontal.
    auto lines = [&](int axis, float first, int count, int other_axis, bool vertical) {
        for (int i = 0; i < count; ++i) {
            const float c = first + static_cast<float>(i) * plan.step;
            Vec3 p = at;
            p[axis] = c;
            Vec2 s;
            if (!view.project(p, s)) continue;
            const ImVec2 from =
                vertical ? ImVec2(origin.x + s.x, origin.y) : ImVec2(origin.x, origin.y + s.y);
            const ImVec2 to = vertical ? ImVec2(origin.x + s.x, origin.y + size.y)
                                       : ImVec2(origin.x + size.x, origin.y + s.y);
            draw->AddLine(from, to, colour(c, other_axis));
        }
    };
    lines(plan.u_axis, plan.u_first, plan.u_count, plan.v_axis, true);
    lines(plan.v_axis, plan.v_first, plan.v_count, plan.u_axis, false);
    char text[48];
    std::snprintf(text, sizeof(text), "grid %g", plan.step);
    draw->AddText(ImVec2(origin.x + 10, origin.y + 26), IM_COL32(200, 210, 230, 200), text);
}
} // namespace

void LevelViewport::panel(const Rect& rect, const OverPicture& over_picture) {
    ImGui::SetNextWindowPos(ImVec2(rect.x, rect.y));
    ImGui::SetNextWindowSize(ImVec2(rect.w, rect.h));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    ImGui::Begin("Viewport", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoScrollWithMouse);
    ImGui::PopStyleVar();
    // Tool bar: palette, gizmo mode, view.
    ImGui::SetCursorPos(ImVec2(6, 4));
    toolbar();
    ImGui::SetCursorPos(ImVec2(0, kViewportBar));
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const Vec2 origin(at.x, at.y);
    // The same size the render pass gave the views (EditorApp::render_views).
    const Vec2 area(static_cast<float>(static_cast<int>(rect.w)),
                    static_cast<float>(std::max(1, static_cast<int>(rect.h - kViewportBar))));
    area_ = {origin, area};
    place_.end_drop_preview(); // a thumbnail still dragged over a view shows it again below
    if (quad_.on)
        quad_view(origin, area);
    else
        single_view(origin);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    status_line(draw, area);
    over_picture(origin, area); // the selection's, not a pane's: across the bottom
    ctx_.logic.pick_hint(draw, origin_);
    if (!quad_.on) open_group_hint(draw, origin_, size_, false);
    for (const ViewportTool* tool : tools())
        if (tool->armed())
            draw->AddText(ImVec2(origin_.x + 12, origin_.y + 8), IM_COL32(140, 255, 160, 255),
                          tool->hint().c_str());
    ImGui::End();
    geometry_.bar(ctx_.editor, ctx_.log, area_.origin, area_.size, ctx_.spots);
}

// Along the bottom of the view (in the 4-up view, of the active pane): view, camera speed, grid, what a drag
// does.
void LevelViewport::status_line(ImDrawList* draw, Vec2 area) const {
    const Vec2 under = quad_.on ? origin_ : area_.origin;
    const Vec2 span = quad_.on ? size_ : area;
    const Editor& editor = ctx_.editor;
    char text[256];
    char speed[48] = "";
    if (!quad_.on) std::snprintf(speed, sizeof(speed), "  |  fly speed %.1f u/s (wheel)", view_.speed);
    std::snprintf(text, sizeof(text), "%s%s%s  |  grid %.2f %s  |  %s%s%s%s", quad_.on ? "4-up: " : "",
                  view_mode_name(view_.mode), speed, editor.doc().grid.step,
                  editor.doc().grid.snap ? "snap" : "free", gizmo_label(gizmo_).c_str(),
                  gizmo_.readout().empty() && !face_drag_.dragging() ? "" : "  ",
                  face_drag_.dragging() ? face_drag_.describe().c_str() : gizmo_.readout().c_str(),
                  scene_.bake_label().c_str());
    draw->PushClipRect(ImVec2(under.x, under.y), ImVec2(under.x + span.x, under.y + span.y), true);
    draw->AddRectFilled(ImVec2(under.x + 6, under.y + span.y - 26),
                        ImVec2(under.x + span.x - 6, under.y + span.y - 4), IM_COL32(15, 17, 22, 170), 4.0f);
    draw->AddText(ImVec2(under.x + 12, under.y + span.y - 23), IM_COL32(225, 230, 240, 255), text);
    draw->PopClipRect();
}

// The single view: the picture, the mouse and the overlays.
void LevelViewport::single_view(Vec2 origin) {
    const RenderTarget& target = scene_.single_target();
    const Vec2 size(static_cast<float>(target.width()), static_cast<float>(target.height()));
    ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(target.texture())),
                 ImVec2(size.x, size.y), ImVec2(0, 1), ImVec2(1, 0));
    origin_ = origin;
    size_ = size;
    view_.set_viewport(size);
    // A screenshot does not depend on where the X pointer happens to rest (no hot gizmo handle).
    const bool hovered = ImGui::IsItemHovered() && !ctx_.shell.screenshot_mode();
    model_drop(origin_); // the picture is the last item
    input(origin_, hovered);
    pane_overlays(ImGui::GetWindowDrawList(), origin_, true);
}

// Over one view (the single view, or a pane of the 4-up view with its camera in view_): the axis views'
// grid, the level logic, the play-test report, the gizmo, the box being dragged (`active`: the view the
// mouse works in) and the axis indicator in the corner.
void LevelViewport::pane_overlays(ImDrawList* draw, Vec2 origin, bool active) {
    const Vec2 size = view_.viewport();
    draw->PushClipRect(ImVec2(origin.x, origin.y), ImVec2(origin.x + size.x, origin.y + size.y), true);
    if (overlays_.grid && view_.orthographic()) axis_grid(draw, view_, ctx_.editor.doc().grid.step, origin);
    logic_overlay_.draw(draw, origin, view_, ctx_.editor, overlays_.links, overlays_.ceilings, shown_fn());
    ctx_.analysis.draw(draw, view_, origin);
    geometry_.draw(draw, origin, view_, ctx_.editor.doc());
    if (!ctx_.editor.doc().selection.empty() && !tool_armed() && geometry_.active() == GeometryTool::none)
        draw_gizmo(draw, gizmo_, view_, origin, gizmo_frame(), active ? hovered_handle_ : Handle::None);
    if (active && box_selecting_) {
        const ImVec2 m = ImGui::GetIO().MousePos;
        draw->AddRectFilled(ImVec2(box_start_.x, box_start_.y), m, IM_COL32(90, 160, 255, 40));
        draw->AddRect(ImVec2(box_start_.x, box_start_.y), m, IM_COL32(90, 160, 255, 200));
    }
    axis_indicator(draw, view_, Vec2(origin.x + size.x - 40, origin.y + 40));
    draw->PopClipRect();
}

// Over a view's top-left corner (under a 4-up pane's name and grid label), clipped to the view: the entered
// group, so the designer sees they are inside it.
void LevelViewport::open_group_hint(ImDrawList* draw, Vec2 origin, Vec2 size, bool pane) const {
    const int open = ctx_.editor.open_group();
    if (open == 0) return;
    const level::Group* group = ctx_.editor.level().editor.find_group(open);
    if (!group) return;
    // A 4-up pane is narrow: the group's name alone.
    const std::string text = pane ? "In " + group->name + " (Esc leaves)"
                                  : "Inside group " + group_label(*group) + "  -  Esc to leave";
    const float top = pane ? 46.0f : (tool_armed() || ctx_.logic.picking() ? 28.0f : 8.0f);
    const ImVec2 at(origin.x + 12, origin.y + top);
    const ImVec2 extent = ImGui::CalcTextSize(text.c_str());
    draw->PushClipRect(ImVec2(origin.x, origin.y), ImVec2(origin.x + size.x, origin.y + size.y), true);
    draw->AddRectFilled(ImVec2(at.x - 5, at.y - 3), ImVec2(at.x + extent.x + 5, at.y + extent.y + 3),
                        IM_COL32(20, 35, 60, 210), 3.0f);
    draw->AddText(at, IM_COL32(150, 195, 255, 255), text.c_str());
    draw->PopClipRect();
}

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
void LevelViewport::toolbar() {
    for (GizmoMode m : {GizmoMode::Move, GizmoMode::Rotate, GizmoMode::Scale}) {
        if (toggle_button(gizmo_mode_name(m), gizmo_.mode == m)) gizmo_.mode = m;
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Gizmo mode (W / E / R)");
        ImGui::SameLine();
    }
    if (gizmo_.mode == GizmoMode::Rotate) { // the space only matters to the rings
        if (ImGui::SmallButton(gizmo_.space == RotationSpace::World ? "World" : "Local"))
            gizmo_.space = gizmo_.space == RotationSpace::World ? RotationSpace::Local : RotationSpace::World;
        ctx_.spots.here("gizmo_space");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("The rotate rings turn about the world's axes or the entity's own (X toggles)");
        ImGui::SameLine();
    }
    // Snap and the grid steps before the view buttons: in a narrow window the view buttons (also on the
    // numpad) run off the bar's end, never the Snap control.
    GridSettings& grid = ctx_.editor.grid();
    ImGui::Checkbox("Snap", &grid.snap);
    ctx_.spots.here("toolbar.snap");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(48);
    ImGui::DragFloat("##grid", &grid.step, 0.05f, 0.05f, 16.0f, "%g u");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Grid step (origin snapping, nudge distance)");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(44);
    ImGui::DragFloat("##rot", &grid.rotation_step, 0.5f, 1.0f, 90.0f, "%.0f\xc2\xb0");
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
    ctx_.spots.here("view_4up");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Top, front, side and perspective at once, each with its own camera (Numpad 0)");
}

} // namespace ks::editor::ui
