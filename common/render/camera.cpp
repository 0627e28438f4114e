#include "render/camera.h"

#include <glm/gtc/matrix_transform.hpp>

#include <limits>

namespace ks::render {

Aabb empty_aabb() {
    constexpr float inf = std::numeric_limits<float>::infinity();
    return {Vec3(inf), Vec3(-inf)};
}

Aabb merge(const Aabb& a, const Aabb& b) {
    return {glm::min(a.min, b.min), glm::max(a.max, b.max)};
}

Aabb transform_aabb(const Aabb& box, const Mat4& m) {
    // Arvo's method: the transformed box of a box is centre moved, extent through |M|.
    Vec3 c = Vec3(m * Vec4(box.center(), 1.0f));
    Vec3 e = box.extent();
    Mat3 a(m);
    Vec3 ext(std::abs(a[0][0]) * e.x + std::abs(a[1][0]) * e.y + std::abs(a[2][0]) * e.z,
             std::abs(a[0][1]) * e.x + std::abs(a[1][1]) * e.y + std::abs(a[2][1]) * e.z,
             std::abs(a[0][2]) * e.x + std::abs(a[1][2]) * e.y + std::abs(a[2][2]) * e.z);
    return {c - ext, c + ext};
}

Vec3 Camera::forward() const {
    return Vec3(-std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch));
}

Mat4 Camera::view() const {
    return glm::lookAt(position, position + forward(), Vec3(0, 1, 0));
}

Mat4 Camera::projection() const {
    return glm::perspective(fov_y, aspect, near_plane, far_plane);
}

Frustum::Frustum(const Mat4& m) {
    // Gribb-Hartmann: rows of the matrix combine into the clip planes.
    auto row = [&](int r) { return Vec4(m[0][r], m[1][r], m[2][r], m[3][r]); };
    planes_ = {row(3) + row(0), row(3) - row(0), row(3) + row(1),
               row(3) - row(1), row(3) + row(2), row(3) - row(2)};
    for (auto& p : planes_) p /= glm::length(Vec3(p));
}

bool Frustum::intersects(const Aabb& box) const {
    Vec3 c = box.center(), e = box.extent();
    for (const auto& p : planes_) {
        float r = e.x * std::abs(p.x) + e.y * std::abs(p.y) + e.z * std::abs(p.z);
        if (glm::dot(Vec3(p), c) + p.w < -r) return false;
    }
    return true;
}

bool Frustum::intersects_sphere(const Vec3& center, float radius) const {
    for (const auto& p : planes_)
        if (glm::dot(Vec3(p), center) + p.w < -radius) return false;
    return true;
}

} // namespace ks::render
