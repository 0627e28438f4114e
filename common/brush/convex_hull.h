#pragma once
// The convex hull of points in double precision, through Qhull (libqhull_r), facets within 1e-9 of coplanar
// merged. Qhull decides the topology; each face's plane is then recomputed from three of its own input
// points (see hull_face_plane), so hull planes through grid points are as exact as double allows.
#include "brush/plane.h"
#include "core/result.h"

#include <span>
#include <vector>

namespace ks::brush {

struct HullFace {
    Plane plane;             // outward
    std::vector<int> points; // indices into the input of the points on this face
};

struct Hull {
    std::vector<int> corners; // indices of the input points that are corners of the hull
    std::vector<HullFace> faces;
};

inline constexpr std::size_t kMaxHullPoints = 100000;

// Refuses fewer than 4 points, non-finite ones, more than kMaxHullPoints, and points that span no volume
// (all coplanar, collinear or equal).
Result<Hull> convex_hull(std::span<const DVec3> points);

// The convex hull's size as Qhull sums it over its facets (no planes recomputed): the measure the convex
// decomposition compares cuts and merges by. The same refusals as convex_hull.
struct HullMeasure {
    double volume = 0.0;
    double area = 0.0;
    std::vector<int> corners; // indices of the input points that are corners of the hull
};
Result<HullMeasure> convex_hull_measure(std::span<const DVec3> points);
Result<double> convex_hull_volume(std::span<const DVec3> points);

} // namespace ks::brush
