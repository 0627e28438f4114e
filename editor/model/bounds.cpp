#include "model/bounds.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ks::editor {
namespace {
using level::Entity;

geometry::Obb make_obb(const Entity& e, Vec3 local_center, Vec3 half) {
    geometry::Obb box;
    box.axes = glm::mat3_cast(e.orientation());
    box.center = e.position + box.axes * local_center;
    box.half = half;
    return box;
}

} // namespace

geometry::Obb entity_obb(const Entity& e) {
    using namespace level;
    switch (e.type()) {
    case EntityType::Wall: {
        const Vec3 s = e.as<WallProps>().size;
        return make_obb(e, {0, s.y / 2, 0}, s / 2.0f);
    }
    case EntityType::Floor: {
        const auto& f = e.as<FloorProps>();
        const float t = f.thickness;
        return make_obb(e, {0, f.ceiling ? t / 2 : -t / 2, 0}, {f.size.x / 2, t / 2, f.size.y / 2});
    }
    case EntityType::Stair: {
        const Vec3 s = e.as<StairProps>().size;
        return make_obb(e, {0, s.y / 2, 0}, s / 2.0f);
    }
    case EntityType::Door: { // the doorway with its closed leaves (0.14 thick, seed facts §4.4)
        const auto& d = e.as<DoorProps>();
        return make_obb(e, {0, d.height / 2, 0}, {d.width / 2, d.height / 2, 0.07f});
    }
    case EntityType::FloorLight: { // the lamp stand; its head overhangs a little
        const float h = e.as<FloorLightProps>().height;
        return make_obb(e, {0, h / 2, 0}, {0.5f, h / 2, 0.5f});
    }
    case EntityType::TopLight: { // hangs below its ceiling fixture
        const float hang = std::max(e.as<TopLightProps>().hang, 0.1f);
        return make_obb(e, {0, -hang / 2, 0}, {0.75f, hang / 2, 0.75f});
    }
    case EntityType::Robot: // the robot model: 3 tall, about 1.6 wide (asset conventions)
        return make_obb(e, {0, 1.5f, 0}, {0.8f, 1.5f, 0.8f});
    case EntityType::Pickup: // a 0.8 cube centred 0.8 above its position (seed facts §4.8)
        return make_obb(e, {0, 0.8f, 0}, {0.4f, 0.4f, 0.4f});
    case EntityType::GasCylinder: {
        const auto& g = e.as<GasCylinderProps>();
        return make_obb(e, {0, g.height / 2, 0}, {g.radius, g.height / 2, g.radius});
    }
    case EntityType::ControlPanel: {
        const Vec3 s = e.as<ControlPanelProps>().size;
        return make_obb(e, {0, s.y / 2, 0}, s / 2.0f);
    }
    case EntityType::Count:
        break;
    }
    return make_obb(e, Vec3(0.0f), Vec3(0.5f));
}

geometry::Obb player_obb(const level::PlayerStart& start) {
    geometry::Obb box;
    box.axes = glm::mat3_cast(quat_from_ypr(radians(start.yaw), 0, 0));
    box.center = start.position + Vec3(0, 1.5f, 0);
    box.half = {1.0f, 1.5f, 1.0f};
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

} // namespace ks::editor
