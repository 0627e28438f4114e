#pragma once
// A perspective camera and its view frustum. Pure math (no GL) so culling is testable without a context.
#include "core/math.h"

#include <array>

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
    float pitch = 0.0f; // radians, positive looks up
    float fov_y = radians(60.0f);
    float near_plane = 0.1f;
    float far_plane = 1000.0f;
    float aspect = 16.0f / 9.0f;

    Vec3 forward() const;
    Mat4 view() const;
    Mat4 projection() const;
};

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
