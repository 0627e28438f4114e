#include "brush/brush_clip.h"

#include <cmath>

namespace ks::brush {
namespace {

Result<Brush> piece(const Brush& brush, const Plane& keep_behind, const FaceAttributes& cap) {
    std::vector<Face> faces = brush.anchored_faces();
    faces.push_back({keep_behind.translated(-brush.anchor()), cap});
    // The cut may make faces of the brush redundant (wholly cut away): they are dropped.
    return Brush::from_anchored_faces(brush.anchor(), std::move(faces), RedundantPlanes::drop);
}

Result<Plane> unit_plane(const Plane& plane) {
    const double len = glm::length(plane.normal);
    if (!is_finite(plane.normal) || !std::isfinite(plane.distance) || !(len > 1e-150))
        return Error("the cutting plane is not finite or has no normal", Location({}, 0, 0, "plane"),
                     "give a finite plane with a non-zero normal");
    return Plane{plane.normal / len, plane.distance / len};
}

} // namespace

PlaneReach reach(const Brush& brush, const Plane& plane) {
    double lowest = 0, highest = 0;
    for (const DVec3& v : brush.vertices()) {
        const double d = plane.signed_distance(v);
        lowest = std::min(lowest, d), highest = std::max(highest, d);
    }
    if (highest <= kOnPlaneEpsilon) return PlaneReach::all_behind;
    if (lowest >= -kOnPlaneEpsilon) return PlaneReach::all_in_front;
    return PlaneReach::both_sides;
}

Result<Split> split(const Brush& brush, const Plane& plane_in, const FaceAttributes& cap) {
    auto plane = unit_plane(plane_in);
    if (!plane) return plane.error();
    Split out;
    switch (reach(brush, *plane)) {
    case PlaneReach::all_behind:
        out.back = brush;
        return out;
    case PlaneReach::all_in_front:
        out.front = brush;
        return out;
    case PlaneReach::both_sides:
        break;
    }
    auto back = piece(brush, *plane, cap);
    if (!back) return back.error();
    auto front = piece(brush, plane->flipped(), cap);
    if (!front) return front.error();
    out.back = std::move(*back);
    out.front = std::move(*front);
    return out;
}

Result<Brush> clip(const Brush& brush, const Plane& plane_in, ClipSide side, const FaceAttributes& cap) {
    auto plane = unit_plane(plane_in);
    if (!plane) return plane.error();
    const Plane keep_behind = side == ClipSide::keep_back ? *plane : plane->flipped();
    switch (reach(brush, keep_behind)) {
    case PlaneReach::all_behind:
        return brush;
    case PlaneReach::all_in_front:
        return Error("nothing of the brush is on the kept side of the plane", Location({}, 0, 0, "plane"),
                     "keep the other side, or move the plane into the brush");
    case PlaneReach::both_sides:
        break;
    }
    return piece(brush, keep_behind, cap);
}

} // namespace ks::brush
