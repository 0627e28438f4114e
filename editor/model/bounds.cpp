#include "model/bounds.h"

#include "level/entity_shapes.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ks::editor {
namespace {
using level::Entity;

glm::dvec3 to_d(const Vec3& v) {
    return glm::dvec3(v);
}
} // namespace

Aabb Obb::aabb() const {
    Vec3 extent(0.0f);
    for (int i = 0; i < 3; ++i) extent += glm::abs(axes[i]) * half[i];
    return {center - extent, center + extent};
}

Vec3 Obb::to_local(const Vec3& p) const {
    const Vec3 d = p - center;
    return {glm::dot(d, axes[0]), glm::dot(d, axes[1]), glm::dot(d, axes[2])};
}

bool Obb::contains(const Vec3& p, float margin) const {
    const Vec3 l = to_local(p);
    for (int i = 0; i < 3; ++i)
        if (std::abs(l[i]) > half[i] + margin) return false;
    return true;
}

Obb entity_obb(const Entity& e) {
    // The same shapes the game builds its bodies from (level/entity_shapes.h).
    const level::PlacedShape shape = level::bounding_shape(e);
    Obb box;
    box.axes = glm::mat3_cast(shape.rotation());
    box.center = shape.centre();
    box.half = shape.half;
    return box;
}

Obb player_obb(const level::PlayerStart& start) {
    Obb box;
    box.axes = glm::mat3_cast(quat_from_ypr(radians(start.yaw), 0, 0));
    box.center = start.position + Vec3(0, level::kPlayerHeight * 0.5f, 0);
    box.half = {level::kPlayerRadius, level::kPlayerHeight * 0.5f, level::kPlayerRadius};
    return box;
}

Overlap obb_overlap(const Obb& a, const Obb& b, float tolerance) {
    // Doubles: level coordinates reach 1e4 while overlaps of 1e-3 must still be told from touching.
    const glm::dvec3 t = to_d(b.center) - to_d(a.center);
    glm::dvec3 axes_a[3], axes_b[3];
    for (int i = 0; i < 3; ++i) {
        axes_a[i] = glm::normalize(to_d(a.axes[i]));
        axes_b[i] = glm::normalize(to_d(b.axes[i]));
    }
    const glm::dvec3 ha = to_d(a.half), hb = to_d(b.half);
    if (!std::isfinite(t.x + t.y + t.z + ha.x + ha.y + ha.z + hb.x + hb.y + hb.z)) return {};

    double best = std::numeric_limits<double>::infinity();
    glm::dvec3 best_axis(0.0);
    auto test = [&](glm::dvec3 axis) {
        double ra = 0, rb = 0;
        for (int i = 0; i < 3; ++i) {
            ra += ha[i] * std::abs(glm::dot(axes_a[i], axis));
            rb += hb[i] * std::abs(glm::dot(axes_b[i], axis));
        }
        const double dist = glm::dot(t, axis);
        const double depth = ra + rb - std::abs(dist);
        if (depth < best) {
            best = depth;
            best_axis = dist > 0 ? -axis : axis; // from b toward a
        }
        return depth > tolerance;
    };
    for (int i = 0; i < 3; ++i)
        if (!test(axes_a[i]) || !test(axes_b[i])) return {false, 0.0f, Vec3(0.0f)};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            glm::dvec3 c = glm::cross(axes_a[i], axes_b[j]);
            const double len = glm::length(c);
            if (len < 1e-6) continue; // parallel edges: a face axis already covers this direction
            if (!test(c / len)) return {false, 0.0f, Vec3(0.0f)};
        }
    return {true, static_cast<float>(best), Vec3(best_axis)};
}

std::optional<float> surface_height_at(const Entity& support, float x, float z) {
    const auto t = support.type();
    if (t != level::EntityType::Floor && t != level::EntityType::Stair) return std::nullopt;
    return surface_height_at(support, entity_obb(support), x, z);
}

std::optional<float> surface_height_at(const Entity& support, const Obb& box, float x, float z,
                                       bool stair_as_ramp) {
    using namespace level;
    if (const auto* f = support.try_as<FloorProps>()) {
        if (f->ceiling) return std::nullopt;
        const Vec3 l = box.to_local({x, box.center.y, z});
        if (std::abs(l.x) > box.half.x || std::abs(l.z) > box.half.z) return std::nullopt;
        return support.position.y;
    }
    if (const auto* s = support.try_as<StairProps>()) {
        const Vec3 l = box.to_local({x, box.center.y, z});
        if (std::abs(l.x) > box.half.x || std::abs(l.z) > box.half.z) return std::nullopt;
        if (stair_as_ramp)
            return support.position.y + s->size.y * std::clamp(0.5f - l.z / s->size.z, 0.0f, 1.0f);
        // Rises toward local -z: step k (from the +z end) has its tread at (k + 1) * rise / steps.
        const int steps = std::max(s->steps, 1);
        const float run_per_step = s->size.z / static_cast<float>(steps);
        const float from_front = s->size.z / 2 - l.z;
        const int k = std::clamp(static_cast<int>(std::floor(from_front / run_per_step)), 0, steps - 1);
        return support.position.y + s->size.y * static_cast<float>(k + 1) / static_cast<float>(steps);
    }
    return std::nullopt;
}

} // namespace ks::editor
