#pragma once
// The draw tool, window-free: a brush drawn with the mouse, either a box dragged on a plane or a polygon
// clicked corner by corner, closed, then extruded. The viewport feeds it snapped points (view/tool_pointer.h)
// and keys; it keeps the state, builds the preview (the brush's edges, its live dimensions and edge lengths)
// and commits through edit_brushes.h, one undo step. A refused commit changes nothing and says why.
//
// The plane a drawing lies on is across a world axis: the top view's is across y, the front view's across z,
// the side view's across x (the drag gives the two other axes), the perspective view's is the face under the
// cursor (an axis-aligned one) or the ground. Along that axis the brush takes, in an axis view, the range of
// the selection (`reference`: a window selects a wall, then draws the doorway through it, TrenchBroom's
// reference bounds) or else of the last brush drawn; in perspective it grows from the plane by the last
// brush's height; the first is the grid step. A typed height keeps the range's start.
// Tests: tests/editor/test_geometry_tools.cpp.
#include "geometry/ray.h"
#include "model/edit_brushes.h"
#include "model/tool_preview.h"

#include <array>
#include <optional>
#include <vector>

namespace ks::editor {

// Across world axis `axis` (0 x, 1 y, 2 z) at that coordinate `level`. `grows` is +1 or -1: the side the
// brush grows to from a face (out of it); nullopt in an axis view, where the range along the axis is the
// remembered one.
struct DrawPlane {
    int axis = 1;
    double level = 0.0;
    std::optional<int> grows;
};

enum class DrawShape { box, polygon };
enum class DrawStage { idle, dragging, placing_points, extruding };

class DrawTool {
  public:
    DrawShape shape = DrawShape::box;
    double grid = 1.0; // the document's grid step: the first height and the height's step
    BrushLook look;
    // The selected brushes' bounds (lo, hi), set by the window before each press: the range along an axis
    // view's axis; nullopt when nothing is selected.
    std::optional<std::array<DVec3, 2>> reference;

    DrawStage stage() const { return stage_; }
    bool busy() const { return stage_ != DrawStage::idle; }

    // Box: a drag from `point` (on the plane) to wherever move() takes it; release() commits.
    void press(const DrawPlane& plane, const DVec3& point);
    void move(const DVec3& point);
    Result<int> release(Editor& editor);

    // Polygon: the first point fixes the plane; a click on the first point (or close()) closes the loop,
    // refused when the polygon is not convex, has repeated or collinear corners or fewer than 3.
    Result<void> add_point(const DrawPlane& plane, const DVec3& point);
    Result<void> close();
    // Backspace: the last corner goes (a closed polygon opens again).
    void remove_last_point();
    // While extruding: the height from where `ray` passes nearest the line along the plane's axis through
    // the polygon's centre (snapped to the grid step; never below one step).
    void extrude_toward(const geometry::Ray& ray);
    Result<int> commit(Editor& editor);

    // The height along the plane's axis of the box being dragged or the polygon extruded (and of the next
    // brush): set, or changed by `steps` grid steps; never below one step.
    void set_height(double height);
    void step_height(int steps);
    double height() const;

    void cancel();

    // The box or extrusion being made: its bounds (empty when nothing is), and width (x), depth (z) and
    // height (y) in level units.
    std::optional<std::array<DVec3, 2>> bounds() const;
    std::optional<DVec3> dimensions() const;
    const std::vector<DVec3>& points() const { return points_; }
    const DrawPlane& plane() const { return plane_; } // of the drawing under way
    ToolPreview preview() const;

  private:
    std::array<double, 2> range_along(const DrawPlane& plane) const;
    std::array<DVec3, 2> drag_box() const;
    std::vector<DVec3> polygon_at(double level) const;
    void finish(); // back to idle, remembering the range along the plane's axis

    DrawStage stage_ = DrawStage::idle;
    DrawPlane plane_;
    DVec3 start_{0.0}, end_{0.0};
    std::vector<DVec3> points_;
    std::array<double, 2> range_{0.0, 1.0};                          // along plane_.axis, while busy
    std::array<std::optional<std::array<double, 2>>, 3> last_range_; // the last brush's, per axis
    std::optional<double> next_height_; // typed while idle: the next brush's height
};

} // namespace ks::editor
