#pragma once
// The transform gizmo: move (three axis arrows and three plane squares), rotate (a yaw ring) and scale
// (three axis handles that multiply the size fields), with the grid's snapping. Hit tests and drags work in
// screen space against the same projection as the picture. A drag is one history step: the editor opens a
// transaction when it starts, applies increments while it moves (each snapped from the drag's start, so
// rounding never accumulates) and commits on release; Escape cancels it.
#include "model/editor.h"
#include "ui/view_camera.h"

struct ImDrawList;

namespace ks::editor::ui {

enum class GizmoMode { Move, Rotate, Scale };
const char* gizmo_mode_name(GizmoMode mode);

enum class Handle { None, AxisX, AxisY, AxisZ, PlaneXY, PlaneXZ, PlaneYZ, Yaw };

struct GizmoView {
    const ViewCamera* camera = nullptr;
    Vec2 origin{0.0f}; // viewport's top-left in screen pixels
    Vec2 size{1.0f};   // viewport size in pixels
};

class Gizmo {
  public:
    GizmoMode mode = GizmoMode::Move;

    // The handle under the mouse (viewport pixels) for a gizmo at `pivot`.
    Handle hit(const GizmoView& view, const Vec3& pivot, Vec2 mouse) const;
    bool dragging() const { return active_ != Handle::None; }
    // Starts a drag on `handle` (opens the transaction).
    void begin(Editor& editor, const GizmoView& view, const Vec3& pivot, Handle handle, Vec2 mouse);
    // Applies the drag so far; returns an error message from the edit, if any.
    std::string drag(Editor& editor, const GizmoView& view, Vec2 mouse);
    void end(Editor& editor);    // commits
    void cancel(Editor& editor); // reverts the whole drag

    void draw(ImDrawList* draw, const GizmoView& view, const Vec3& pivot, Handle hovered) const;
    // World length of the handles at `pivot`: a constant size on screen.
    float handle_length(const GizmoView& view, const Vec3& pivot) const;
    // A short readout of the drag ("dx 2.0  dy 0.0  dz -1.0", "yaw 45"), empty when idle.
    const std::string& readout() const { return readout_; }

  private:
    float axis_parameter(const GizmoView& view, Vec2 mouse, const Vec3& axis) const;
    bool plane_point(const GizmoView& view, Vec2 mouse, const Vec3& normal, Vec3& out) const;

    Handle active_ = Handle::None;
    Vec3 pivot_{0.0f};
    Vec3 start_point_{0.0f};   // where the drag grabbed (plane/axis) in world space
    float start_param_ = 0.0f; // axis parameter or angle at the grab
    Vec3 applied_move_{0.0f};  // total already applied in this drag
    float applied_angle_ = 0.0f;
    Vec3 applied_scale_{1.0f};
    std::string readout_;
};

} // namespace ks::editor::ui
