#pragma once
// The convex hull of points in a plane (Andrew's monotone chain, exact orientation tests in double): the
// screen footprint the renderer's view-model layer composites over, instead of its bounding rectangle.
// Points in 3D are brush/convex_hull.h's (Qhull).
#include "core/math.h"

#include <vector>

namespace ks::geometry {

// Replaces `points` by their convex hull, counter-clockwise (y up), starting at the lowest-x (then lowest-y)
// point, without repeated or collinear vertices. Non-finite points are dropped. Fewer than three distinct,
// non-collinear points leave the distinct extremes (0, 1 or 2 points): an empty area.
void convex_hull_2d(std::vector<Vec2>& points);

// Cuts a convex polygon to the rectangle [lo, hi] (Sutherland-Hodgman against its four sides); fewer than
// three points left: empty.
void clip_convex_polygon(std::vector<Vec2>& polygon, const Vec2& lo, const Vec2& hi);

// Twice the signed area (counter-clockwise positive) of a closed polygon.
double polygon_area2(const std::vector<Vec2>& polygon);

} // namespace ks::geometry
