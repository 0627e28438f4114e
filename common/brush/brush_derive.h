#pragma once
// Derives a brush's vertices and ordered face polygons from its planes, in double precision.
//
// Method: the map compilers' windings, then a polish. Each plane starts as a square of half size 2^18 on the
// plane (larger than any brush within +-kMaxCoordinate) and is clipped by every other plane, keeping the
// part behind it. Each winding point remembers the planes its two edges lie on, so every polygon corner is
// known to lie on three planes. Corners of all faces closer than kWeldDistance are one vertex, and its
// position is recomputed as the intersection of the best-conditioned three of the planes through it.
//
// Why not only one of the two: clipping alone is O(n^2) and yields ordered polygons and the topology, but
// its points carry the rounding of the big square (about 1e-10 at the world's edge); intersecting plane
// triples alone is O(n^4) and needs the topology rebuilt. Together: O(n^2) for the topology, and each
// vertex is as exact as its planes allow (about 1e-12 for a grid brush within +-10 000; tests hold it to the
// grid within 1e-9).
#include "brush/plane.h"
#include "core/result.h"

#include <vector>

namespace ks::brush {

struct DerivedGeometry {
    std::vector<DVec3> vertices;
    // One per input plane, counter-clockwise from outside; empty when the plane contributes no face.
    std::vector<std::vector<int>> polygons;
};

// Errors: a plane reaching the world's edge (unbounded or too large, naming the face), faces that do not
// close (degenerate). Planes must be unit and finite (validate_faces).
Result<DerivedGeometry> derive_geometry(const std::vector<Plane>& planes);

} // namespace ks::brush
