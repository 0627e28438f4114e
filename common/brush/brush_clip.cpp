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

} // namespace

Result<Split> split(const Brush& brush, const Plane& plane_in, const FaceAttributes& cap) {
    const double len = glm::length(plane_in.normal);
    if (!is_finite(plane_in.normal) || !std::isfinite(plane_in.distance) || !(len > 1e-150))
        return Error("the cutting plane is not finite or has no normal", Location({}, 0, 0, "plane"),
                     "give a finite plane with a non-zero normal");
    const Plane plane{plane_in.normal / len, plane_in.distance / len};
    double lowest = 0, highest = 0;
    for (const DVec3& v : brush.vertices()) {
        const double d = plane.signed_distance(v);
        lowest = std::min(lowest, d), highest = std::max(highest, d);
    }
    Split out;
    if (highest <= kOnPlaneEpsilon) {
        out.back = brush;
        return out;
    }
    if (lowest >= -kOnPlaneEpsilon) {
        out.front = brush;
        return out;
    }
    auto back = piece(brush, plane, cap);
    if (!back) return back.error();
    auto front = piece(brush, plane.flipped(), cap);
    if (!front) return front.error();
    out.back = std::move(*back);
    out.front = std::move(*front);
    return out;
}

Result<Brush> clip(const Brush& brush, const Plane& plane, ClipSide side, const FaceAttributes& cap) {
    auto parts = split(brush, side == ClipSide::keep_back ? plane : plane.flipped(), cap);
    if (!parts) return parts.error();
    if (!parts->back)
        return Error("nothing of the brush is on the kept side of the plane", Location({}, 0, 0, "plane"),
                     "keep the other side, or move the plane into the brush");
    return std::move(*parts->back);
}

} // namespace ks::brush
