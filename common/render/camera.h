#pragma once
// A perspective camera and its view frustum. Pure math (no GL) so culling is testable without a context.
#include "core/math.h"

#include <array>
#include <vector>

namespace ks::render {

struct Aabb {
    Vec3 min{0.0f};
    Vec3 max{0.0f};
    bool valid() const { return min.x <= max.x && min.y <= max.y && min.z <= max.z; }
    Vec3 center() const { return (min + max) * 0.5f; }
    Vec3 extent() const { return (max - min) * 0.5f; }
};

Aabb transform_aabb(const Aabb& box, const Mat4& m);
Aabb merge(const Aabb& a, const Aabb& b);
Aabb empty_aabb(); // min = +inf, max = -inf: merging anything into it gives that thing

struct Camera {
    Vec3 position{0.0f, 3.0f, 0.0f};
    float yaw = 0.0f;   // radians about +y; 0 looks along -z
    float pitch = 0.0f; // radians, positive looks up (±90° exactly is fine: no look-at singularity)
    float roll = 0.0f;  // radians about the view direction, positive leans the head to the right (a fall
                        // to the right; the world turns anticlockwise on screen)
    float fov_y = radians(60.0f);
    float near_plane = 0.1f;
    float far_plane = 1000.0f;
    float aspect = 16.0f / 9.0f;
    // > 0: an orthographic projection showing this many world units vertically (the editor's top, front
    // and side views); 0: perspective with fov_y.
    float ortho_height = 0.0f;

    Vec3 forward() const;
    Vec3 right() const; // the image's +x direction in world space (includes roll)
    Vec3 up() const;    // the image's +y direction in world space (includes roll)
    bool orthographic() const { return ortho_height > 0.0f; }
    Mat4 view() const;
    Mat4 projection() const;
};

// Occlusion culling against solid boxes. A face of an opaque box that faces the eye hides everything that
// lies behind its plane and projects (from the eye) inside it; by convexity, checking a box's 8 corners
// decides for the whole box. lo/hi bound the face on the other two axes ((axis+1)%3, (axis+2)%3).
struct OccluderFace {
    int axis = 0;
    float plane = 0.0f;
    Vec2 lo{0.0f}, hi{0.0f};
};
// Appends the faces of `solid` that face `eye` (none when the eye is inside it).
void append_occluder_faces(const Aabb& solid, const Vec3& eye, std::vector<OccluderFace>& out);
// Joins faces on the same plane whose rectangles share an edge (two closed door leaves side by side), so that
// what straddles the seam is hidden too.
void merge_occluder_faces(std::vector<OccluderFace>& faces);
// True if all of `box` is hidden from the perspective `camera` behind `face`: every corner beyond the
// face's plane, projecting inside the face (with a margin), and the face drawn there (not clipped by
// the near or far plane). Conservative: false whenever in doubt.
bool hidden_behind(const Aabb& box, const OccluderFace& face, const Camera& camera);

// Six inward-facing planes (a·x + b·y + c·z + d >= 0 inside), extracted from a view-projection matrix.
class Frustum {
  public:
    explicit Frustum(const Mat4& view_projection);
    bool intersects(const Aabb& box) const;
    bool intersects_sphere(const Vec3& center, float radius) const;

  private:
    std::array<Vec4, 6> planes_;
};

} // namespace ks::render
