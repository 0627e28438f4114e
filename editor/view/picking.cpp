#include "view/picking.h"

#include <algorithm>
#include <cmath>

namespace ks::editor {

float ray_obb(const Ray& ray, const Obb& box) {
    const Vec3 o = box.to_local(ray.origin);
    const Vec3 d = glm::transpose(box.axes) * ray.direction;
    float t0 = 0.0f, t1 = 1e30f;
    for (int i = 0; i < 3; ++i) {
        if (std::abs(d[i]) < 1e-8f) { // parallel to this slab: inside it or a miss
            if (std::abs(o[i]) > box.half[i]) return -1.0f;
            continue;
        }
        float a = (-box.half[i] - o[i]) / d[i], b = (box.half[i] - o[i]) / d[i];
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
        if (t0 > t1) return -1.0f;
    }
    return t0;
}

PickHit pick_entity(const Document& doc, const Ray& ray, const ShownFn& shown) {
    PickHit best{0, 1e30f};
    for (const auto& e : doc.level.entities) {
        if (!shown(e) || doc.locked.contains(e.id)) continue;
        const float t = ray_obb(ray, entity_obb(e));
        if (t >= 0.0f && t < best.distance) best = {e.id, t};
    }
    return best;
}

namespace {
bool is_surface(level::EntityType t) {
    return t == level::EntityType::Floor || t == level::EntityType::Stair || t == level::EntityType::Wall;
}
} // namespace

Vec3 place_point(const Document& doc, const Ray& ray, const ShownFn& shown, const Vec3& fallback) {
    float best_t = 1e30f;
    for (const auto& e : doc.level.entities) {
        if (!shown(e) || !is_surface(e.type())) continue;
        const float t = ray_obb(ray, entity_obb(e));
        if (t >= 0.0f && t < best_t) best_t = t;
    }
    Vec3 p;
    if (best_t < 1e29f) {
        p = ray.origin + ray.direction * best_t;
    } else if (std::abs(ray.direction.y) > 1e-4f && -ray.origin.y / ray.direction.y > 0.0f) {
        p = ray.origin + ray.direction * (-ray.origin.y / ray.direction.y); // the ground plane y = 0
    } else { // level ray (front / side view): the plane through the fallback point facing the ray
        p = ray.origin + ray.direction * std::max(0.0f, glm::dot(fallback - ray.origin, ray.direction));
    }
    return Vec3(doc.grid.snap_value(p.x), p.y, doc.grid.snap_value(p.z));
}

} // namespace ks::editor
