#include "render/debug_draw.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace ks::render {

void DebugDraw::line(const Vec3& a, const Vec3& b, const Vec4& color) {
    vertices_.push_back({a, color});
    vertices_.push_back({b, color});
}

void DebugDraw::box(const geometry::Aabb& b, const Vec4& color) {
    Mat4 t = glm::translate(Mat4(1.0f), b.center());
    box(t, b.extent(), color);
}

void DebugDraw::box(const Mat4& t, const Vec3& h, const Vec4& color) {
    Vec3 c[8];
    for (int i = 0; i < 8; ++i)
        c[i] = Vec3(t * Vec4((i & 1) ? h.x : -h.x, (i & 2) ? h.y : -h.y, (i & 4) ? h.z : -h.z, 1.0f));
    const int edges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                              {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    for (const auto& e : edges) line(c[e[0]], c[e[1]], color);
}

void DebugDraw::capsule(const Vec3& a, const Vec3& b, float radius, const Vec4& color, int segments) {
    segments = std::max(segments, 4);
    Vec3 axis = b - a;
    float len = glm::length(axis);
    Vec3 up = len > 1e-6f ? axis / len : Vec3(0, 1, 0);
    Vec3 side = std::abs(up.y) < 0.99f ? glm::normalize(glm::cross(up, Vec3(0, 1, 0))) : Vec3(1, 0, 0);
    Vec3 fwd = glm::cross(side, up);
    for (int i = 0; i < segments; ++i) {
        float a0 = 2.0f * kPi * i / segments, a1 = 2.0f * kPi * (i + 1) / segments;
        Vec3 r0 = (side * std::cos(a0) + fwd * std::sin(a0)) * radius;
        Vec3 r1 = (side * std::cos(a1) + fwd * std::sin(a1)) * radius;
        line(a + r0, a + r1, color);
        line(b + r0, b + r1, color);
    }
    for (int k = 0; k < 4; ++k) {
        Vec3 dir = k == 0 ? side : k == 1 ? -side : k == 2 ? fwd : -fwd;
        line(a + dir * radius, b + dir * radius, color);
        // Half circles closing the ends.
        for (int i = 0; i < segments / 2; ++i) {
            float t0 = kPi * 0.5f * i / (segments / 2), t1 = kPi * 0.5f * (i + 1) / (segments / 2);
            line(b + (dir * std::cos(t0) + up * std::sin(t0)) * radius,
                 b + (dir * std::cos(t1) + up * std::sin(t1)) * radius, color);
            line(a + (dir * std::cos(t0) - up * std::sin(t0)) * radius,
                 a + (dir * std::cos(t1) - up * std::sin(t1)) * radius, color);
        }
    }
}

void DebugDraw::ray(const Vec3& origin, const Vec3& direction, float length, const Vec4& color) {
    float n = glm::length(direction);
    if (!(n > 1e-12f) || !is_finite(direction)) return;
    Vec3 d = direction / n;
    Vec3 end = origin + d * length;
    line(origin, end, color);
    Vec3 side = std::abs(d.y) < 0.99f ? glm::normalize(glm::cross(d, Vec3(0, 1, 0))) : Vec3(1, 0, 0);
    float head = std::min(0.3f, length * 0.2f);
    line(end, end - d * head + side * head * 0.5f, color);
    line(end, end - d * head - side * head * 0.5f, color);
}

} // namespace ks::render
