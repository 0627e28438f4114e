#pragma once
// The vertex tool's handles in a view (model/tool_vertex.h), window-free: the handle under the mouse (the
// nearest on screen within a few pixels, the nearer to the eye on a tie, a vertex before a split handle),
// the handles inside a dragged screen rectangle (box select), and the plane a drag moves on with its snapped
// delta: in an axis view the plane across the view through the grabbed handle, in perspective the
// horizontal through it; a vertex or a split handle lands on the grid, an edge or face moves by whole grid
// steps.
#include "model/tool_draw.h"
#include "model/tool_vertex.h"
#include "view/view_camera.h"

#include <optional>
#include <vector>

namespace ks::editor {

std::optional<VertexHandle> handle_under(const std::vector<VertexHandle>& handles, const ViewCamera& view,
                                         Vec2 mouse, float pixels = 8.0f);

// The positions of the non-split handles whose screen points lie in the rectangle with corners a and b.
std::vector<DVec3> handles_in_rect(const std::vector<VertexHandle>& handles, const ViewCamera& view, Vec2 a,
                                   Vec2 b);

// A drag under way: the plane it moves on and the point the delta is measured from.
struct VertexDrag {
    DrawPlane plane;
    DVec3 from{0.0};
};

// The drag of the handle at `grabbed` pressed at `mouse`; `on_grid` (a vertex or a split handle): the
// delta takes the handle itself onto the grid; else it is measured from the snapped pressed point.
VertexDrag start_vertex_drag(const Document& doc, const ViewCamera& view, Vec2 mouse, const DVec3& grabbed,
                             bool on_grid);
// The snapped delta with the mouse at `mouse`; nullopt when a perspective ray misses the plane.
std::optional<DVec3> vertex_drag_delta(const Document& doc, const ViewCamera& view, Vec2 mouse,
                                       const VertexDrag& drag);

} // namespace ks::editor
