#pragma once
// Where a geometry tool's click lands (tool_draw.h, tool_clip.h, tool_measure.h), window-free: a brush
// vertex within a few pixels of the mouse, else the point where the ray enters the nearest shown brush (on
// an axis-aligned face its two other coordinates snapped to the grid), else the grid: the ground y = 0 in
// perspective, the plane through the origin across the view in an axis view, snapped. The draw tool's plane
// follows from it.
#include "brush/plane.h"
#include "model/tool_draw.h"
#include "view/picking.h"

#include <optional>

namespace ks::editor {

enum class PointKind { vertex, face, grid };
const char* point_kind_name(PointKind kind);

struct ToolPoint {
    DVec3 point{0.0};
    PointKind kind = PointKind::grid;
    std::optional<brush::Plane> face; // a face's plane (facing out of its brush): "match a face"
    int entity = 0;                   // the brush of a vertex or face
};

struct PointerOptions {
    bool vertices = true, faces = true; // off: the grid only (drawing in an axis view)
    float vertex_pixels = 8.0f;
};

// The world axis an axis view looks along (top: y, front: z, side: x); nullopt in perspective.
std::optional<int> view_axis(const ViewCamera& view);

// The point under `mouse` (viewport pixels); nullopt when a perspective ray meets neither a brush nor the
// ground in front of the camera.
std::optional<ToolPoint> tool_point(const Document& doc, const ViewCamera& view, Vec2 mouse,
                                    const ShownFn& shown, const PointerOptions& options = {});

// Where the ray under `mouse` meets `plane` (in an axis view, the point under the mouse on it), its two
// other coordinates snapped to the grid; nullopt when a perspective ray runs along it or away from it.
std::optional<DVec3> point_on_plane(const Document& doc, const ViewCamera& view, Vec2 mouse,
                                    const DrawPlane& plane);

// The plane a drawing starting at `at` lies on: across the view in an axis view (the range along it is the
// draw tool's), else the axis-aligned face under it (growing out of it), else the horizontal through it.
DrawPlane draw_plane_at(const ToolPoint& at, const ViewCamera& view);

} // namespace ks::editor
