#include "view/logic_markers.h"

#include "level/entity_shapes.h"

#include <cmath>

namespace ks::editor {

void spawner_marker(const Vec3& feet, float yaw_degrees, std::vector<MarkerLine>& out) {
    const Vec3 base = feet + Vec3(0, 0.08f, 0);
    const float ring = level::kRobotRadius * 2.0f;
    constexpr int kSegments = 24;
    Vec3 previous = base + Vec3(ring, 0, 0);
    for (int i = 1; i <= kSegments; ++i) {
        const float a = 2.0f * kPi * static_cast<float>(i) / kSegments;
        const Vec3 p = base + Vec3(std::cos(a) * ring, 0, std::sin(a) * ring);
        out.push_back({previous, p});
        previous = p;
    }
    // A robot's body as a wire box (upright: where each one appears), the post through it, and a plus on
    // top: "robots are made here".
    const float r = level::kRobotRadius, h = level::kRobotHeight;
    const Vec3 corners[4] = {{-r, 0, -r}, {r, 0, -r}, {r, 0, r}, {-r, 0, r}};
    for (int k = 0; k < 4; ++k) {
        const Vec3 a = feet + corners[k], b = feet + corners[(k + 1) % 4];
        out.push_back({a, b});
        out.push_back({a + Vec3(0, h, 0), b + Vec3(0, h, 0)});
        out.push_back({a, a + Vec3(0, h, 0)});
    }
    const Vec3 top = feet + Vec3(0, level::kRobotHeight, 0);
    out.push_back({base, top});
    const float arm = level::kRobotRadius * 0.8f;
    out.push_back({top - Vec3(arm, 0, 0), top + Vec3(arm, 0, 0)});
    out.push_back({top - Vec3(0, 0, arm), top + Vec3(0, 0, arm)});
    out.push_back({top - Vec3(0, arm, 0), top + Vec3(0, arm, 0)});
    // The way the robots face, an arrow on the ground from the ring outward.
    const float yaw = radians(yaw_degrees);
    const Vec3 forward(-std::sin(yaw), 0, -std::cos(yaw)), side(-forward.z, 0, forward.x);
    const Vec3 start = base + forward * ring, tip = base + forward * (ring + 1.2f);
    out.push_back({start, tip});
    out.push_back({tip, tip - forward * 0.5f + side * 0.35f});
    out.push_back({tip, tip - forward * 0.5f - side * 0.35f});
}

void message_marker(const Vec3& centre, const Vec3& right, const Vec3& up, float half_size,
                    std::vector<MarkerLine>& out) {
    // In icon units (1 = half_size): u to the right, v up. A bubble over a tail at its lower left.
    auto at = [&](float u, float v) { return centre + (right * u + up * v) * half_size; };
    auto line = [&](float u0, float v0, float u1, float v1) { out.push_back({at(u0, v0), at(u1, v1)}); };
    const float l = -0.95f, r = 0.95f, t = 0.8f, b = -0.45f;
    line(l, t, r, t);
    line(r, t, r, b);
    line(r, b, -0.3f, b);
    line(-0.3f, b, -0.65f, -0.95f); // the tail
    line(-0.65f, -0.95f, -0.6f, b);
    line(-0.6f, b, l, b);
    line(l, b, l, t);
    // Three lines of text, the last one short.
    line(-0.7f, 0.5f, 0.7f, 0.5f);
    line(-0.7f, 0.18f, 0.7f, 0.18f);
    line(-0.7f, -0.14f, 0.2f, -0.14f);
}

std::array<std::array<Vec3, 4>, 6> box_faces(const geometry::Obb& box) {
    auto corner = [&](float x, float y, float z) {
        return box.center + box.axes * (Vec3(x, y, z) * box.half);
    };
    std::array<std::array<Vec3, 4>, 6> faces;
    for (int axis = 0; axis < 3; ++axis) {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        for (int side = 0; side < 2; ++side) {
            const float s = side == 0 ? -1.0f : 1.0f;
            const float square[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
            for (int k = 0; k < 4; ++k) {
                Vec3 unit(0.0f);
                unit[axis] = s;
                unit[u] = square[k][0];
                unit[v] = square[k][1];
                faces[static_cast<size_t>(axis * 2 + side)][static_cast<size_t>(k)] =
                    corner(unit.x, unit.y, unit.z);
            }
        }
    }
    return faces;
}

} // namespace ks::editor
