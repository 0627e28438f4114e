#pragma once
// A tool of the level viewport (the place tool, place_tool.h; a draw, clip or measure tool the same way): a
// member object of LevelViewport listed in its tools() (level_viewport.h). While armed it takes the active
// view's left button from selection, patrol points and the gizmo: it is given the mouse every frame (ImGui's
// mouse state is this frame's), draws its lines into every view's picture (render pass) and its hint over
// the viewport; Esc disarms it. Every edit it makes is an Editor call.
#include "geometry/obb.h"
#include "geometry/ray.h"
#include "model/editor.h"
#include "render/debug_draw.h"
#include "ui/editor_log.h"
#include "view/picking.h"
#include "view/view_camera.h"

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>

namespace ks::editor::ui {

// The active view's mouse, while the tool is armed.
struct ToolInput {
    Editor& editor;
    EditorLog& log;
    const ViewCamera& view; // the active view's camera
    Vec2 mouse;             // in the view's pixels
    bool hovered;           // the mouse is over the view (never in screenshot mode)
    const ShownFn& shown;   // what the viewport shows (hidden entities are not picked)
};

// One view being drawn (render pass): in the 4-up view, each pane in turn.
struct ToolView {
    const Editor& editor;
    const ViewCamera& view;                        // the camera of the view being drawn
    const std::optional<geometry::Ray>& mouse_ray; // the mouse's ray in the active view, while hovered
    const ShownFn& shown;                          // what the viewport shows (hidden entities are not picked)
};

// An oriented box's edges in a view's lines (viewport_lines.cpp): selection, collision and preview boxes.
void draw_obb(render::DebugDraw& debug, const geometry::Obb& box, const Vec4& colour);

class ViewportTool {
  public:
    virtual ~ViewportTool() = default;
    virtual bool armed() const = 0;
    // Every frame while armed, unless the camera flies, pick mode or a gizmo / patrol drag has the mouse, or
    // Alt (orbit) is held.
    virtual void input(const ToolInput& in) = 0;
    virtual void draw_lines(render::DebugDraw& debug, const ToolView& view) const = 0;
    virtual std::string hint() const = 0; // over the viewport's top-left corner while armed
    virtual void disarm() = 0;            // Esc, or the inspector's pick mode took the viewport's clicks
    virtual void status(nlohmann::json& status) const = 0; // --status-file: the tool's own keys
};

} // namespace ks::editor::ui
