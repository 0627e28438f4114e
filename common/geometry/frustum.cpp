#include "geometry/frustum.h"

namespace ks::geometry {

Frustum::Frustum(const Mat4& m) {
    // Gribb-Hartmann: rows of the matrix combine into the clip planes.
    auto row = [&](int r) { return Vec4(m[0][r], m[1][r], m[2][r], m[3][r]); };
    planes_ = {row(3) + row(0), row(3) - row(0), row(3) + row(1),
               row(3) - row(1), row(3) + row(2), row(3) - row(2)};
    for (auto& p : planes_) p /= glm::length(Vec3(p));
}

bool Frustum::intersects(const Aabb& box) const {
    const Vec3 c = box.center(), e = box.extent();
    for (const auto& p : planes_) {
        const float r = e.x * std::abs(p.x) + e.y * std::abs(p.y) + e.z * std::abs(p.z);
        if (glm::dot(Vec3(p), c) + p.w < -r) return false;
    }
    return true;
}

bool Frustum::intersects_sphere(const Vec3& center, float radius) const {
    for (const auto& p : planes_)
        if (glm::dot(Vec3(p), center) + p.w < -radius) return false;
    return true;
}

} // namespace ks::geometry
