#pragma once
// Occlusion culling for the renderer: which boxes the faces of solid boxes hide from a perspective camera.
// Pure math (no GL) so it is testable without a context.
#include "geometry/camera.h"

#include <vector>

namespace ks::render {

// Occlusion culling against solid boxes. A face of an opaque box that faces the eye hides everything that
// lies behind its plane and projects (from the eye) inside it; by convexity, checking a box's 8 corners
// decides for the whole box. lo/hi bound the face on the other two axes ((axis+1)%3, (axis+2)%3).
struct OccluderFace {
    int axis = 0;
    float plane = 0.0f;
    Vec2 lo{0.0f}, hi{0.0f};
};
// Appends the faces of `solid` that face `eye` (none when the eye is inside it).
void append_occluder_faces(const geometry::Aabb& solid, const Vec3& eye, std::vector<OccluderFace>& out);
// Joins faces on the same plane whose rectangles share an edge (two closed door leaves side by side), so that
// what straddles the seam is hidden too.
void merge_occluder_faces(std::vector<OccluderFace>& faces);
// True if all of `box` is hidden from the perspective `camera` behind `face`: every corner beyond the
// face's plane, projecting inside the face (with a margin), and the face drawn there (not clipped by
// the near or far plane). Conservative: false whenever in doubt.
bool hidden_behind(const geometry::Aabb& box, const OccluderFace& face, const geometry::Camera& camera);

} // namespace ks::render
