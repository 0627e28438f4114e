#pragma once
// The transform gizmo's maths, window-free: move (three axis arrows and three plane squares), rotate (rings
// about x, y and z, in world space or the primary entity's own; only the y ring where the selection turns
// by its yaw alone) and scale (three axis handles that multiply the size fields), with the grid's snapping.
// The handles have a constant size on screen in both projections (world_per_pixel); hit tests work in
// screen pixels on the same projection as the picture. Handles seen end-on (an axis pointing at the viewer,
// a plane or a ring edge-on, as in the axis views) are neither drawn nor hit. A drag is one history step:
// begin opens a transaction, drag applies increments (each snapped from the drag's start, so rounding never
// accumulates), end commits, cancel reverts. The ImGui front end draws GizmoShape (ui/gizmo_draw.cpp).
#include "model/editor.h"
#include "model/rotation.h"
#include "view/view_camera.h"

#include <array>
#include <string>

namespace ks::editor {

enum class GizmoMode { Move, Rotate, Scale };
const char* gizmo_mode_name(GizmoMode mode);

enum class Handle { None, AxisX, AxisY, AxisZ, PlaneXY, PlaneXZ, PlaneYZ, RingX, RingY, RingZ };
// 0, 1, 2 for the rings about x, y, z; -1 for the other handles.
int ring_axis(Handle handle);

inline constexpr float kGizmoPickPixels = 9.0f;
inline constexpr float kGizmoScreenFraction = 0.16f; // handle length as a fraction of the viewport height
inline constexpr int kGizmoRingSegments = 48;

// Where the gizmo stands and how its rings turn: `axes` (columns x, y, z) are the world's, or the primary
// entity's own for local turns; `three_axes` offers the x and z rings (selection_turns_on_three_axes).
struct GizmoFrame {
    Vec3 pivot{0.0f};
    Mat3 axes{1.0f};
    bool three_axes = false;
};
// The selection's frame: the mean of the selected positions (the player start's too), turned like the
// primary entity in local space.
GizmoFrame gizmo_frame(const Document& doc, RotationSpace space);

// Where the gizmo's handles are on screen (viewport pixels).
struct GizmoShape {
    bool valid = false; // the pivot is in front of the camera
    Vec2 centre{0.0f};
    float length = 0.0f; // world length of an axis handle
    std::array<Vec2, 3> tips{};
    std::array<bool, 3> axis_visible{};
    std::array<std::array<Vec2, 4>, 3> planes{}; // XY, XZ, YZ squares
    std::array<bool, 3> plane_visible{};
    // Ring k turns about the frame's axis k; each starts on the next axis (y for x, z for y, x for z).
    std::array<std::array<Vec2, kGizmoRingSegments + 1>, 3> rings{};
    std::array<bool, 3> ring_visible{};
};
GizmoShape gizmo_shape(const ViewCamera& view, const GizmoFrame& frame);
// The world-aligned gizmo at `pivot`, with the yaw ring only.
inline GizmoShape gizmo_shape(const ViewCamera& view, const Vec3& pivot) {
    return gizmo_shape(view, GizmoFrame{pivot});
}
Handle gizmo_hit(GizmoMode mode, const GizmoShape& shape, Vec2 mouse);

// Drag maths: the parameter along `pivot + axis * s` closest to the ray (nullopt when the ray is parallel
// to the axis), and the ray's point on the plane through `pivot` (nullopt when edge-on or behind).
std::optional<float> axis_parameter(const geometry::Ray& ray, const Vec3& pivot, const Vec3& axis);
std::optional<Vec3> plane_point(const geometry::Ray& ray, const Vec3& pivot, const Vec3& normal);
// The angle of `offset` in the plane of unit axes u and v, from u toward v; and about ring k of `frame` (a
// positive angle is a positive turn about the frame's axis k).
float angle_in_plane(const Vec3& offset, const Vec3& u, const Vec3& v);
float ring_angle(const GizmoFrame& frame, int k, const Vec3& offset);

class Gizmo;
// The mode as the viewport's status line shows it: "Move", "Rotate (world)", "Rotate (local)", "Scale".
std::string gizmo_label(const Gizmo& gizmo);

class Gizmo {
  public:
    GizmoMode mode = GizmoMode::Move;
    RotationSpace space = RotationSpace::World; // which axes the rotate rings turn about

    Handle hit(const ViewCamera& view, const GizmoFrame& frame, Vec2 mouse) const {
        return gizmo_hit(mode, gizmo_shape(view, frame), mouse);
    }
    Handle hit(const ViewCamera& view, const Vec3& pivot, Vec2 mouse) const {
        return hit(view, GizmoFrame{pivot}, mouse);
    }
    bool dragging() const { return active_ != Handle::None; }
    Handle active() const { return active_; }
    // Starts a drag on `handle` (opens the transaction).
    void begin(Editor& editor, const ViewCamera& view, const GizmoFrame& frame, Handle handle, Vec2 mouse);
    void begin(Editor& editor, const ViewCamera& view, const Vec3& pivot, Handle handle, Vec2 mouse) {
        begin(editor, view, GizmoFrame{pivot}, handle, mouse);
    }
    // Applies the drag so far; returns an error message from the edit, if any. `free` drags without the
    // grid's snapping (Ctrl held), whatever the grid says.
    std::string drag(Editor& editor, const ViewCamera& view, Vec2 mouse, bool free = false);
    void end(Editor& editor);    // commits
    void cancel(Editor& editor); // reverts the whole drag
    // A short readout of the drag ("move +2.00, +0.00, -1.00", "yaw +45.0 deg"), empty when idle.
    const std::string& readout() const { return readout_; }

  private:
    std::string drag_ring(Editor& editor, const geometry::Ray& ray, const GridSettings& grid);

    Handle active_ = Handle::None;
    Vec3 pivot_{0.0f};
    Vec3 ring_axis_{0, 1, 0}, ring_u_{0, 0, 1}, ring_v_{1, 0, 0}; // the turned ring's axis and plane
    float length_ = 1.0f;      // handle length at the grab (scale drags are relative to it)
    Vec3 start_point_{0.0f};   // where the drag grabbed (plane handles) in world space
    float start_param_ = 0.0f; // axis parameter or angle at the grab
    Vec3 applied_move_{0.0f};  // total already applied in this drag
    float applied_angle_ = 0.0f;
    Vec3 applied_scale_{1.0f};
    std::string readout_;
};

} // namespace ks::editor
