#pragma once
// Making brushes: from an axis-aligned box, from a convex polygon extruded along a direction, from a point
// cloud (its convex hull, through Qhull). Every face gets `attributes`.
#include "brush/brush.h"

#include <span>

namespace ks::brush {

// Faces in the order -x, +x, -y, +y, -z, +z.
Result<Brush> make_box(const DVec3& min, const DVec3& max, const FaceAttributes& attributes = {});

// A prism: `polygon` (planar, convex, either winding, no repeated or collinear points) swept by
// `direction`, which must not lie in the polygon's plane. Faces: the polygon, the swept polygon, then one
// per polygon edge in order.
Result<Brush> make_extrusion(std::span<const DVec3> polygon, const DVec3& direction,
                             const FaceAttributes& attributes = {});

// The convex hull of `points`; points inside it are ignored.
Result<Brush> make_from_points(std::span<const DVec3> points, const FaceAttributes& attributes = {});

// The convex hull of `points`, each face taking the attributes of the face of `sources` that matches it
// best: the same plane if one has it, else the most nearly parallel one (the vertex edits and merge use it).
// With `require_all_corners`, refused when some point is not a corner of the hull.
Result<Brush> make_hull_of(std::span<const DVec3> points, std::span<const Brush* const> sources,
                           bool require_all_corners = false);

} // namespace ks::brush
