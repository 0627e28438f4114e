#include "nav/nav_levels.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

namespace ks::test {

nav::NavSettings robot_settings() {
    return nav::robot_nav_settings(0.65f, 50.0f);
}

std::unique_ptr<nav::NavMesh> build_robot_mesh(const level::Level& level) {
    auto mesh = nav::NavMesh::build(level, robot_settings());
    REQUIRE_MESSAGE(mesh.ok(), (mesh.ok() ? "" : mesh.error().str()));
    return std::move(mesh.value());
}

level::Entity& add_floor(level::Level& level, Vec3 centre, Vec2 size) {
    auto& f = level.add(level::EntityType::Floor, centre, "floor");
    f.as<level::FloorProps>().size = size;
    return f;
}

level::Entity& add_wall(level::Level& level, Vec3 a, Vec3 b, float thickness, float height) {
    const Vec3 centre = (a + b) * 0.5f;
    auto& w = level.add(level::EntityType::Wall, centre, "wall");
    w.as<level::WallProps>().size = Vec3(glm::length(b - a), height, thickness);
    w.rotation.x = std::abs(b.x - a.x) >= std::abs(b.z - a.z) ? 0.0f : 90.0f;
    return w;
}

void add_wall_with_gap(level::Level& level, Vec3 a, Vec3 b, float gap_min_x, float gap, float thickness) {
    add_wall(level, a, Vec3(gap_min_x, a.y, a.z), thickness);
    add_wall(level, Vec3(gap_min_x + gap, b.y, b.z), b, thickness);
}

level::Entity& add_door(level::Level& level, Vec3 bottom_centre, float width, bool open) {
    auto& d = level.add(level::EntityType::Door, bottom_centre, "door");
    d.as<level::DoorProps>().width = width;
    d.as<level::DoorProps>().open = open;
    return d;
}

level::Entity& add_cylinder(level::Level& level, Vec3 bottom_centre, float radius) {
    auto& c = level.add(level::EntityType::GasCylinder, bottom_centre, "gas cylinder");
    c.as<level::GasCylinderProps>().radius = radius;
    return c;
}

std::optional<float> crossing_x(const std::vector<Vec3>& path, float z) {
    for (size_t i = 1; i < path.size(); ++i) {
        const Vec3 a = path[i - 1], b = path[i];
        if ((a.z - z) * (b.z - z) > 0.0f || a.z == b.z) continue;
        const float t = (z - a.z) / (b.z - a.z);
        return a.x + t * (b.x - a.x);
    }
    return std::nullopt;
}

float closest_approach(const std::vector<Vec3>& path, Vec3 point) {
    float best = 1e30f;
    const Vec2 p(point.x, point.z);
    for (size_t i = 1; i < path.size(); ++i) {
        const Vec2 a(path[i - 1].x, path[i - 1].z), b(path[i].x, path[i].z);
        const Vec2 ab = b - a;
        const float len2 = glm::dot(ab, ab);
        const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
        best = std::min(best, glm::length(a + ab * t - p));
    }
    return best;
}

} // namespace ks::test
