#pragma once
// A view frustum as six planes, for culling boxes and spheres against a camera's view-projection.
#include "geometry/aabb.h"

#include <array>

namespace ks::geometry {

// Six inward-facing planes (a·x + b·y + c·z + d >= 0 inside), extracted from a view-projection matrix.
class Frustum {
  public:
    explicit Frustum(const Mat4& view_projection);
    // Conservative: true for every box that reaches inside (or touches a plane), possibly for a few
    // outside near the frustum's corners.
    bool intersects(const Aabb& box) const;
    bool intersects_sphere(const Vec3& center, float radius) const;

  private:
    std::array<Vec4, 6> planes_;
};

} // namespace ks::geometry
