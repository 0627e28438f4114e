#include "geometry/camera.h"

#include <glm/gtc/matrix_transform.hpp>

namespace ks::geometry {

Mat3 Camera::basis() const {
    Mat4 m = glm::rotate(Mat4(1.0f), yaw, Vec3(0, 1, 0));
    m = glm::rotate(m, pitch, Vec3(1, 0, 0));
    m = glm::rotate(m, -roll, Vec3(0, 0, 1));
    return Mat3(m);
}

Vec3 Camera::forward() const {
    return Vec3(-std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch));
}

Vec3 Camera::right() const {
    return basis()[0];
}

Vec3 Camera::up() const {
    return basis()[1];
}

Mat4 Camera::view() const {
    const Mat3 b = basis(); // columns: right, up, back
    Mat4 v(glm::transpose(b));
    v[3] = Vec4(-(glm::transpose(b) * position), 1.0f);
    return v;
}

Mat4 Camera::projection() const {
    if (orthographic()) {
        const float half_h = 0.5f * ortho_height, half_w = half_h * aspect;
        return glm::ortho(-half_w, half_w, -half_h, half_h, near_plane, far_plane);
    }
    return glm::perspective(fov_y, aspect, near_plane, far_plane);
}

Ray screen_ray(const Camera& camera, Vec2 pixel, Vec2 viewport) {
    const Mat3 b = camera.basis();
    const float aspect = viewport.x / viewport.y;
    const float nx = 2.0f * pixel.x / viewport.x - 1.0f, ny = 1.0f - 2.0f * pixel.y / viewport.y;
    if (camera.orthographic()) {
        const float half_h = 0.5f * camera.ortho_height, half_w = half_h * aspect;
        return {camera.position + b[0] * (nx * half_w) + b[1] * (ny * half_h), -b[2]};
    }
    const float t = std::tan(camera.fov_y * 0.5f);
    return {camera.position, glm::normalize(-b[2] + b[0] * (nx * t * aspect) + b[1] * (ny * t))};
}

bool world_to_screen(const Camera& camera, const Vec3& world, Vec2 viewport, Vec2& pixel) {
    const Mat3 b = camera.basis();
    const Vec3 v = world - camera.position;
    const float depth = -glm::dot(v, b[2]);
    float half_h = 0.0f;
    if (camera.orthographic()) {
        if (depth < 0.0f) return false;
        half_h = 0.5f * camera.ortho_height;
    } else {
        if (depth <= 1e-4f) return false;
        half_h = depth * std::tan(camera.fov_y * 0.5f);
    }
    const float half_w = half_h * viewport.x / viewport.y;
    const float nx = glm::dot(v, b[0]) / half_w, ny = glm::dot(v, b[1]) / half_h;
    pixel = Vec2((nx + 1.0f) * 0.5f * viewport.x, (1.0f - ny) * 0.5f * viewport.y);
    return true;
}

} // namespace ks::geometry
