#pragma once
// Questions asked of a brush in the world by tools that place things on it, pick it or check a level: the
// top of the brush over a point of the ground plane (what stands on it stands there), where a ray enters it
// (both clip a line by every face's half-space, so they are exact for any convex brush, ramps and turned
// brushes too) and whether a point is inside (a door's jamb against a brush wall).
#include "brush/brush.h"

#include <optional>

namespace ks::brush {

// The height where the vertical line through (x, z) leaves the brush at the top, or nullopt when the line
// misses the brush (or only grazes an edge or a vertical face).
std::optional<double> top_at(const Brush& brush, double x, double z);

// The distance along `direction` (any length: the result is in its units) at which the ray from `origin`
// enters the brush; 0 when the origin is inside; nullopt when it misses.
std::optional<double> ray_entry(const Brush& brush, const DVec3& origin, const DVec3& direction);

// Where the ray from `origin` enters the brush and through which face (its index in faces()); nullopt when
// it misses or starts inside (no face is entered). Picking a face with the mouse asks this.
struct RayEntry {
    double distance = 0.0;
    int face = -1;
};
std::optional<RayEntry> ray_entry_face(const Brush& brush, const DVec3& origin, const DVec3& direction);

// Whether `point` is inside the brush or within `tolerance` of every face's plane (a point just outside one
// face but within tolerance counts as inside).
bool contains(const Brush& brush, const DVec3& point, double tolerance = 0.0);

} // namespace ks::brush
