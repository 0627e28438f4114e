#pragma once
// The clip tool, window-free: a plane through 2 or 3 points clicked on brush faces or the grid (with 2
// points in an axis view the plane also contains the view direction), or the plane of a picked face ("match
// a face"); which side to keep (back, front or both, cycled by Tab); the preview (the cut's outline on each
// selected brush, the points, the side kept); Enter applies it to the selected brushes through
// edit_brushes.h's clip_selected_brushes, one undo step. Refusals (collinear or repeated points, a plane
// missing the brushes, a clip that would leave nothing) change nothing and say why.
// Tests: tests/editor/test_geometry_tools.cpp.
#include "brush/plane.h"
#include "model/edit_brushes.h"
#include "model/tool_preview.h"

#include <optional>
#include <vector>

namespace ks::editor {

const char* clip_keep_name(ClipKeep keep);

class ClipTool {
  public:
    // Where a point is clicked; at most 3 are kept (a fourth starts a new plane). Refused when it repeats
    // one already clicked.
    Result<void> add_point(const DVec3& point);
    // The view's direction in an axis view (two points then make a plane), nullopt in perspective.
    void set_view_direction(std::optional<DVec3> direction) { view_direction_ = direction; }
    // The plane of a picked face, facing out of its brush: the clicked points are dropped.
    void match_face(const brush::Plane& face);
    void cycle_keep();
    void set_keep(ClipKeep keep) { keep_ = keep; }
    ClipKeep keep() const { return keep_; }

    const std::vector<DVec3>& points() const { return points_; }
    bool matched_face() const { return face_.has_value(); }
    bool busy() const { return !points_.empty() || face_.has_value(); }
    // The plane (unit normal) or why there is none yet.
    Result<brush::Plane> plane() const;

    // The plane's cut on each selected brush, the points, the side kept and what stops Enter.
    ToolPreview preview(const Document& doc) const;
    // Clips the selected brushes (one undo step) and starts over; refused when the plane misses them all.
    Result<void> apply(Editor& editor);
    void reset();

  private:
    std::vector<DVec3> points_;
    std::optional<brush::Plane> face_;
    std::optional<DVec3> view_direction_;
    ClipKeep keep_ = ClipKeep::back;
};

} // namespace ks::editor
