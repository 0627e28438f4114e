#include "model/bounds.h"

#include "brush/brush_query.h"
#include "level/entity_shapes.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ks::editor {
using level::Entity;

geometry::Obb entity_obb(const Entity& e) {
    // The same shapes the game builds its bodies from (level/entity_shapes.h).
    const level::PlacedShape shape = level::bounding_shape(e);
    geometry::Obb box;
    box.axes = glm::mat3_cast(shape.rotation());
    box.center = shape.centre();
    box.half = shape.half;
    return box;
}

namespace {
// A brush's box is its world vertices' (a turned brush's box around its turned box would be larger).
geometry::Aabb entity_aabb(const Entity& e) {
    if (e.type() == level::EntityType::Brush)
        if (const auto world = level::world_brush(e))
            return {Vec3(world->bounds_min()), Vec3(world->bounds_max())};
    return entity_obb(e).aabb();
}
} // namespace

geometry::Aabb selection_bounds(const std::vector<const Entity*>& entities) {
    geometry::Aabb box = geometry::Aabb::empty();
    for (const Entity* e : entities) box.grow(entity_aabb(*e));
    return box;
}

geometry::Aabb selection_bounds(const std::vector<Entity>& entities) {
    geometry::Aabb box = geometry::Aabb::empty();
    for (const Entity& e : entities) box.grow(entity_aabb(e));
    return box;
}

geometry::Obb player_obb(const level::PlayerStart& start) {
    geometry::Obb box;
    box.axes = glm::mat3_cast(quat_from_ypr(radians(start.yaw), 0, 0));
    box.center = start.position + Vec3(0, level::kPlayerHeight * 0.5f, 0);
    box.half = {level::kPlayerRadius, level::kPlayerHeight * 0.5f, level::kPlayerRadius};
    return box;
}

std::optional<float> surface_height_at(const Entity& support, float x, float z) {
    const auto t = support.type();
    if (t != level::EntityType::Floor && t != level::EntityType::Stair) return std::nullopt;
    return surface_height_at(support, entity_obb(support), x, z);
}

std::optional<float> surface_height_at(const Entity& support, const geometry::Obb& box, float x, float z,
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

std::optional<SupportSurface> SupportSurface::of(const Entity& entity) {
    const auto type = entity.type();
    if (!is_finite(entity.position) || !is_finite(entity.rotation)) return std::nullopt;
    if (type == level::EntityType::Floor || type == level::EntityType::Stair)
        return SupportSurface(entity, entity_obb(entity));
    if (type != level::EntityType::Brush) return std::nullopt;
    auto world = level::world_brush(entity);
    if (!world) return std::nullopt;
    return of_brush(entity, std::make_shared<const brush::Brush>(std::move(*world)));
}

SupportSurface SupportSurface::of_brush(const Entity& entity, std::shared_ptr<const brush::Brush> world) {
    SupportSurface surface(entity, entity_obb(entity));
    surface.world_brush_ = std::move(world);
    return surface;
}

std::optional<float> SupportSurface::height_at(float x, float z, bool stair_as_ramp) const {
    if (!world_brush_) return surface_height_at(*entity_, box_, x, z, stair_as_ramp);
    auto top = brush::top_at(*world_brush_, x, z);
    if (!top) {
        // A point on the brush's side (a door centred on the floor's edge) is over it, as on a floor entity's
        // box; brush::top_at counts touching a face as outside (right for rays), so the point is moved a hair
        // toward the brush's middle and asked again.
        constexpr double kEdge = 1e-6;
        const DVec3 mid = (world_brush_->bounds_min() + world_brush_->bounds_max()) * 0.5;
        top = brush::top_at(*world_brush_, x + std::clamp(mid.x - x, -kEdge, kEdge),
                            z + std::clamp(mid.z - z, -kEdge, kEdge));
    }
    if (!top) return std::nullopt;
    return static_cast<float>(*top);
}

} // namespace ks::editor
