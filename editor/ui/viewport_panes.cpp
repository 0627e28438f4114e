// The level viewport's views (level_viewport.h): the render pass of the single view or of the 4-up view's
// four panes (each its own camera and target, the level emitted once), the 4-up view's panes in the ImGui
// pass, and framing. view_ is the camera being drawn: each pane's camera is swapped into it while that pane
// is laid out and given the mouse, so every overlay, pick and gizmo drag works unchanged in every pane;
// between frames it holds the active pane's camera, where the menus, keys and the status file find it.
#include "model/bounds.h"
#include "model/edit_selection.h"
#include "ui/face_inspector.h"
#include "ui/level_viewport.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace ks::editor::ui {

namespace {
constexpr float kPaneGap = 2.0f;

// Every entity's bounds (±20 around 0 for an empty level): what the view presets frame.
void level_box(const Editor& editor, Vec3& lo, Vec3& hi) {
    lo = Vec3(-20.0f), hi = Vec3(20.0f);
    if (editor.level().entities.empty()) return;
    const geometry::Aabb box = selection_bounds(editor.level().entities);
    lo = box.min, hi = box.max;
}
} // namespace

void LevelViewport::sync_active_pane() {
    if (quad_.on) quad_.cameras[static_cast<size_t>(quad_.active)] = view_;
}

void LevelViewport::rebuild_scene() {
    section_ = overlays_.section ? section_cut(ctx_.editor, view_) : std::nullopt;
    scene_.rebuild_if_changed(ctx_.editor,
                              section_key(section_) ^ (static_cast<std::uint64_t>(overlays_.ceilings) << 63) ^
                                  (models_revision_ * 0x9e3779b97f4a7c15ull),
                              shown_fn());
}

// A view's lines in the render pass: the overlays', the tools' (where a click would place) and the entered
// group's box over them.
void LevelViewport::draw_lines(render::DebugDraw& debug, const ViewCamera& view) {
    lines_.draw(debug, view, ctx_.editor, overlays_, logic_overlay_, ctx_.shell.screenshot_mode());
    model_collision_.draw(debug, ctx_.editor);
    const ShownFn shown = shown_fn();
    const ToolView tool_view{ctx_.editor, view, place_ray_, shown};
    for (const ViewportTool* tool : tools()) tool->draw_lines(debug, tool_view);
    lines_.open_group_box(debug, ctx_.editor);
    draw_selected_faces(debug, ctx_.editor.doc()); // face_inspector.h
}

void LevelViewport::render(int width, int height) {
    const auto lines = [this](render::DebugDraw& debug, const ViewCamera& view) { draw_lines(debug, view); };
    if (!quad_.on) {
        view_.set_viewport(Vec2(static_cast<float>(width), static_cast<float>(std::max(1, height))));
        scene_.render_single(view_, width, height, lines);
        return;
    }
    sync_active_pane();
    const auto panes =
        quad_panes(Vec2(0.0f), Vec2(static_cast<float>(width), static_cast<float>(height)), kPaneGap);
    for (size_t i = 0; i < panes.size(); ++i) {
        quad_.cameras[i].set_viewport(panes[i].size);
        scene_.render_pane(i, quad_.cameras[i], panes[i].size, lines);
    }
    view_ = quad_.cameras[static_cast<size_t>(quad_.active)];
}

void LevelViewport::quad_view(Vec2 origin, Vec2 size) {
    sync_active_pane();
    pane_rects_ = quad_panes(origin, size, kPaneGap);
    const ImGuiIO& io = ImGui::GetIO();
    // The pane under the mouse becomes the active one, unless a drag, a fly or a box select started in
    // another is still going on (it keeps the pane it started in until the button is released).
    bool busy =
        gizmo_.dragging() || patrol_drag_.dragging() || face_drag_.dragging() || box_selecting_ || flying_;
    for (int button = 0; button < 3; ++button)
        if (io.MouseDown[button] && !ImGui::IsMouseClicked(button)) busy = true;
    const int under =
        ImGui::IsWindowHovered() ? pane_at(pane_rects_, Vec2(io.MousePos.x, io.MousePos.y)) : -1;
    if (!busy && under >= 0) quad_.active = under;

    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(ImVec2(origin.x, origin.y), ImVec2(origin.x + size.x, origin.y + size.y),
                        IM_COL32(30, 33, 40, 255));
    for (size_t i = 0; i < pane_rects_.size(); ++i) {
        const PaneRect& pane = pane_rects_[i];
        const bool active = static_cast<int>(i) == quad_.active;
        view_ = quad_.cameras[i];
        view_.set_viewport(pane.size);
        ImGui::SetCursorScreenPos(ImVec2(pane.origin.x, pane.origin.y));
        ImGui::PushID(static_cast<int>(i));
        ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(scene_.pane_target(i).texture())),
                     ImVec2(pane.size.x, pane.size.y), ImVec2(0, 1), ImVec2(1, 0));
        ImGui::PopID();
        const bool hovered = ImGui::IsItemHovered() && !ctx_.shell.screenshot_mode();
        model_drop(pane.origin); // before input(): a pane's picture is the last item
        if (active) {
            origin_ = pane.origin;
            size_ = pane.size;
            input(pane.origin, hovered);
        }
        pane_overlays(draw, pane.origin, active);
        const char* name = view_mode_name(view_.mode);
        const ImVec2 label(pane.origin.x + 8, pane.origin.y + 6), extent = ImGui::CalcTextSize(name);
        draw->AddRectFilled(ImVec2(label.x - 4, label.y - 2),
                            ImVec2(label.x + extent.x + 4, label.y + extent.y + 2), IM_COL32(15, 17, 22, 190),
                            3.0f);
        draw->AddText(label, active ? IM_COL32(255, 200, 90, 255) : IM_COL32(210, 215, 225, 255), name);
        open_group_hint(draw, pane.origin, pane.size, true);
        if (active) // the pane the keys and the mouse work in
            draw->AddRect(ImVec2(pane.origin.x, pane.origin.y),
                          ImVec2(pane.origin.x + pane.size.x, pane.origin.y + pane.size.y),
                          IM_COL32(255, 190, 70, 200), 0.0f, 0, 2.0f);
        quad_.cameras[i] = view_;
    }
    const PaneRect& active = pane_rects_[static_cast<size_t>(quad_.active)];
    view_ = quad_.cameras[static_cast<size_t>(quad_.active)];
    origin_ = active.origin;
    size_ = active.size;
}

void LevelViewport::toggle_quad() {
    if (quad_.on) {
        sync_active_pane();
        view_ = quad_.leave();
        ctx_.log.line("single view: " + std::string(view_mode_name(view_.mode)));
        return;
    }
    Vec3 lo, hi;
    level_box(ctx_.editor, lo, hi);
    // The panes' size now (before the first frame too): from the window, as the layout computes it.
    int width = 0, height = 0;
    glfwGetFramebufferSize(ctx_.shell.window(), &width, &height);
    const Layout layout =
        compute_layout(static_cast<float>(width), static_cast<float>(height), ImGui::GetFrameHeight());
    const Vec2 area(std::floor(layout.centre.w), std::max(1.0f, std::floor(layout.centre.h - kViewportBar)));
    quad_.enter(view_, lo, hi, quad_panes(Vec2(0.0f), area, kPaneGap)[0].size);
    view_ = quad_.cameras[static_cast<size_t>(quad_.active)];
    ctx_.log.line("4-up view: top, front, side and perspective (Numpad 0 toggles)");
}

void LevelViewport::focus_selection() {
    const Editor& editor = ctx_.editor;
    const auto selected = selected_entities(editor);
    geometry::Aabb box{Vec3(-10.0f), Vec3(10.0f)}; // an empty level
    if (editor.doc().player_start_selected())
        box = player_obb(editor.level().player_start).aabb();
    else if (!selected.empty())
        box = selection_bounds(selected);
    else if (!editor.level().entities.empty())
        box = selection_bounds(editor.level().entities);
    const Vec3 lo = box.min, hi = box.max;
    if (!quad_.on) {
        view_.focus(lo, hi);
        return;
    }
    sync_active_pane(); // F in the 4-up view focuses every pane
    for (ViewCamera& pane : quad_.cameras) pane.focus(lo, hi);
    view_ = quad_.cameras[static_cast<size_t>(quad_.active)];
}

void LevelViewport::set_view(ViewMode mode) { // in the 4-up view: the active pane's
    Vec3 lo, hi;
    level_box(ctx_.editor, lo, hi);
    frame_box(view_, mode, lo, hi);
}

} // namespace ks::editor::ui
