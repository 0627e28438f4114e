#pragma once
// The level viewport (the centre panel while the Level tab is shown): its tool bar, the single view or the
// 4-up view's panes (view/quad_view.h), the camera of each, the overlays over the picture (axis grid, level
// logic, play-test report, gizmo, box select, axis indicator, hints), the mouse (camera, picking, box
// select, the gizmo, patrol points) and its tools (viewport_tool.h). The level's picture is drawn by
// ViewportScene (viewport_scene.h), the lines in it by ViewportLines (viewport_lines.h). Files:
// viewport.cpp (the panel, the ImGui pass), viewport_input.cpp (the mouse and the keys), viewport_panes.cpp
// (the 4-up view, the render pass, framing) and viewport_status.cpp (--status-file).
#include "model/editor.h"
#include "model/face_drag.h"
#include "shell/app_shell.h"
#include "ui/analysis_view.h"
#include "ui/editor_log.h"
#include "ui/geometry_tools_ui.h"
#include "ui/layout.h"
#include "ui/logic_overlay.h"
#include "ui/logic_panels.h"
#include "ui/model_overlay.h"
#include "ui/place_tool.h"
#include "ui/ui_spots.h"
#include "ui/viewport_lines.h"
#include "ui/viewport_scene.h"
#include "view/gizmo.h"
#include "view/patrol_drag.h"
#include "view/quad_view.h"
#include "view/section_view.h"
#include "view/view_camera.h"

#include <nlohmann/json_fwd.hpp>

#include <array>
#include <functional>
#include <optional>

struct ImDrawList;

namespace ks::editor::ui {

// What the viewport works through: the document, the log and the status file's spots (as every panel,
// panel_context.h), plus the window's pieces tied to its picture and clicks.
struct ViewportContext {
    Editor& editor;
    EditorLog& log;
    UiSpots& spots;
    LogicPanels& logic;           // pick mode takes the viewport's left clicks; its hint over the picture
    const AnalysisView& analysis; // the play-test report over every view
    shell::AppShell& shell;       // the window (camera keys, its size) and screenshot mode
};

class LevelViewport {
  public:
    // Draws the window's own widgets over the picture (origin, size in window pixels): the clip preview.
    using OverPicture = std::function<void(Vec2 origin, Vec2 size)>;

    LevelViewport(const ViewportContext& ctx, ViewportScene& scene) : ctx_(ctx), scene_(scene) {}
    LevelViewport(const LevelViewport&) = delete;
    LevelViewport& operator=(const LevelViewport&) = delete;

    // ImGui pass: the tool bar and the views in `rect`.
    void panel(const Rect& rect, const OverPicture& over_picture);
    // Render pass: the level scene brought up to date, then (after the clip preview posed it) the views.
    void rebuild_scene();
    void render(int width, int height);

    void view_menu(); // the View menu's views, framing and overlays
    void shortcuts(); // F, W / E / R / X and the numpad's views (no Ctrl, not flying)
    bool escape();    // Esc: ends a gizmo drag or disarms the armed tool; false: neither was going on
    // The geometry tools' keys (B, C, M; with one active Esc, Enter, Tab, ...): true when one was used.
    bool geometry_tool_keys(bool ctrl) { return geometry_.keys(ctx_.editor, ctx_.log, ctrl); }
    void disarm_tools(); // the inspector's pick mode, or another tool, takes the viewport's clicks
    Result<void> set_gizmo_option(const std::string& option); // --gizmo MODE[,local]
    void set_view(ViewMode mode); // frames the level; in the 4-up view, the active pane's
    void toggle_quad();
    void focus_selection(); // F: frames the selection (every pane of the 4-up view)

    const ViewCamera& camera() const { return view_; } // the active view's
    ViewCamera& camera() { return view_; }
    Overlays& overlays() { return overlays_; }
    PlaceTool& place_tool() { return place_; }
    // The Models tab's revision (model_browser.h): a model file changed on disk rebuilds the scene.
    void set_models_revision(std::uint64_t revision) { models_revision_ = revision; }
    bool flying() const { return flying_; }
    bool animating() const { return lines_.building(); } // the navigation mesh is being built
    // --status-file: the viewport's keys; `level_shown`: the Level tab is shown (not the dojo).
    void status(nlohmann::json& status, bool level_shown) const;

  private:
    // viewport.cpp
    void single_view(Vec2 origin);
    void status_line(ImDrawList* draw, Vec2 area) const; // view, speed, grid, gizmo along the bottom
    void pane_overlays(ImDrawList* draw, Vec2 origin, bool active);
    void open_group_hint(ImDrawList* draw, Vec2 origin, Vec2 size, bool pane) const; // "Inside group"
    void toolbar();
    // viewport_input.cpp
    void input(Vec2 origin, bool hovered);
    bool drag(Vec2 mouse);  // a patrol point or gizmo drag going on; true: it had the mouse
    void click(Vec2 mouse); // a left click with no tool armed: a group, a patrol point, the gizmo, a box
    void end_box_select(Vec2 origin, Vec2 mouse);
    void model_drop(Vec2 origin); // a Models tab thumbnail dragged over the view just drawn (view_'s)
    int pick(const geometry::Ray& ray) const;
    ShownFn shown_fn() const { // what the views show and picking finds
        return [this](const level::Entity& e) {
            return overlays_.shows(ctx_.editor.doc(), e) && !(section_ && in_front_of_cut(*section_, e));
        };
    }
    GizmoFrame gizmo_frame() const; // the selection's pivot and the rings' axes in the gizmo's space
    // The viewport's tools: a new tool is a member below and an entry in both lists.
    std::array<ViewportTool*, 1> tools() { return {&place_}; }
    std::array<const ViewportTool*, 1> tools() const { return {&place_}; }
    ViewportTool* armed_tool();
    bool tool_armed() const;
    // viewport_panes.cpp
    void quad_view(Vec2 origin, Vec2 size);
    void draw_lines(render::DebugDraw& debug, const ViewCamera& view); // a view's lines in the render pass
    void sync_active_pane(); // view_ is the active pane's camera between frames: write it back
    void panes_status(nlohmann::json& status) const; // viewport_status.cpp

    ViewportContext ctx_;
    ViewportScene& scene_;
    ViewCamera view_; // the single view's camera; in the 4-up view, the pane's being drawn (between frames:
                      // the active pane's)
    QuadView quad_;
    std::array<PaneRect, kQuadPanes> pane_rects_{};
    PaneRect area_;                            // the single view's or the four panes' area (window pixels)
    Vec2 origin_{0.0f}, size_{640.0f, 360.0f}; // the active view's picture (window pixels)
    std::optional<geometry::Ray> place_ray_;   // the mouse's ray in the active view, while it is hovered
    Overlays overlays_;
    std::optional<SectionCut> section_; // this frame's cut while overlays_.section is on
    std::uint64_t models_revision_ = 0;
    ModelCollisionOverlay model_collision_; // the selected models' collision (model_overlay.h)
    ViewportLines lines_;
    LogicOverlay logic_overlay_; // trigger, spawner and message markers; link arrows
    Gizmo gizmo_;
    PatrolDrag patrol_drag_;
    FaceDrag face_drag_; // a press on a selected face drags its texture (face_drag.h)
    Handle hovered_handle_ = Handle::None;
    bool flying_ = false;
    bool box_selecting_ = false;
    Vec2 box_start_{0.0f};
    PlaceTool place_;          // palette or prefab: the next click places one
    GeometryToolsUi geometry_; // draw, clip, measure (geometry_tools_ui.h): the left mouse while active
};

} // namespace ks::editor::ui
