#include "view/picking.h"

#include "brush/brush_query.h"
#include "level/entity_shapes.h"
#include "view/player_start_marker.h"

#include <algorithm>
#include <cmath>

namespace ks::editor {
namespace {
// Where the ray meets the entity: its box, or for a brush the brush itself (a ramp is picked on its slope,
// not anywhere in its box); negative when it misses.
float ray_distance(const level::Entity& e, const geometry::Ray& ray) {
    const float t = geometry::ray_obb(ray, entity_obb(e));
    if (t < 0.0f || e.type() != level::EntityType::Brush) return t;
    const auto world = level::world_brush(e);
    if (!world) return t;
    const auto entry = brush::ray_entry(*world, DVec3(ray.origin), DVec3(ray.direction));
    return entry ? static_cast<float>(*entry) : -1.0f;
}
} // namespace

PickHit pick_entity(const Document& doc, const geometry::Ray& ray, const ShownFn& shown) {
    PickHit best{0, 1e30f};
    for (const auto& e : doc.level.entities) {
        if (!shown(e) || doc.locked.contains(e.id)) continue;
        const float t = ray_distance(e, ray);
        if (t >= 0.0f && t < best.distance) best = {e.id, t};
    }
    return best;
}

PickHit pick_selectable(const Document& doc, const geometry::Ray& ray, const ShownFn& shown,
                        bool player_start_shown) {
    PickHit best = pick_entity(doc, ray, shown);
    if (!player_start_shown) return best;
    if (const auto t = pick_player_start(doc.level.player_start, ray);
        t && (best.id == 0 || *t < best.distance))
        best = {kPlayerStartId, *t};
    return best;
}

namespace {
bool is_surface(level::EntityType t) {
    return t == level::EntityType::Floor || t == level::EntityType::Stair || t == level::EntityType::Wall ||
           t == level::EntityType::Brush;
}
} // namespace

Vec3 place_point(const Document& doc, const geometry::Ray& ray, const ShownFn& shown, const Vec3& fallback) {
    float best_t = 1e30f;
    for (const auto& e : doc.level.entities) {
        if (!shown(e) || !is_surface(e.type())) continue;
        const float t = ray_distance(e, ray);
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

std::optional<float> overhead_height(const Document& doc, const Vec3& surface) {
    // From just above the surface, so the slab clicked on is not its own ceiling.
    const geometry::Ray up{surface + Vec3(0, 0.05f, 0), Vec3(0, 1, 0)};
    float best_t = 1e30f;
    for (const auto& e : doc.level.entities) {
        if (!is_surface(e.type())) continue;
        const float t = ray_distance(e, up);
        if (t > 0.0f && t < best_t) best_t = t; // 0: the ray starts inside it (a wall clicked on its face)
    }
    if (best_t >= 1e29f) return std::nullopt;
    return up.origin.y + best_t;
}

Vec3 placement_for(const Document& doc, level::EntityType type, const Vec3& surface) {
    switch (type) {
    case level::EntityType::Sound:
        return surface + Vec3(0, kSoundPlaceHeight, 0);
    case level::EntityType::TopLight:
        return Vec3(surface.x, overhead_height(doc, surface).value_or(surface.y + kTopLightPlaceHeight),
                    surface.z);
    default:
        return surface;
    }
}

} // namespace ks::editor
