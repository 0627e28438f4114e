#include "model/ambush_validation.h"

#include "brush/brush_query.h"
#include "level/entity_shapes.h"

#include <cmath>
#include <cstdio>

namespace ks::editor {
namespace {

// Whether a wall, door (shut at the start), floor, stair or brush lies on the segment from `from` to `to`.
bool sight_blocked(const level::Level& level, const Vec3& from, const Vec3& to) {
    const Vec3 d = to - from;
    const float length = glm::length(d);
    if (!(length > 1e-4f)) return false;
    const geometry::Ray ray{from, d / length, length};
    for (const level::Entity& e : level.entities) {
        if (!is_finite(e.position) || !is_finite(e.rotation)) continue;
        switch (e.type()) {
        case level::EntityType::Wall:
        case level::EntityType::Door:
        case level::EntityType::Floor:
        case level::EntityType::Stair:
            if (geometry::ray_obb(ray, entity_obb(e)) >= 0.0f) return true;
            break;
        case level::EntityType::Brush:
            if (auto world = level::world_brush(e)) {
                const auto t = brush::ray_entry(*world, DVec3(from), DVec3(ray.direction));
                if (t && *t <= static_cast<double>(length)) return true;
            }
            break;
        default:
            break;
        }
    }
    return false;
}

} // namespace

void check_start_ambush(const level::Level& level, std::vector<Issue>& out) {
    const Vec3 player = level.player_start.position + Vec3(0.0f, level::kPlayerHeight * 0.5f, 0.0f);
    if (!is_finite(player)) return;
    for (const level::Entity& e : level.entities) {
        const auto* robot = e.try_as<level::RobotProps>();
        if (!robot || robot->dormant || !is_finite(e.position)) continue;
        const Vec3 eye = e.position + Vec3(0.0f, level::kRobotHeight * 0.9f, 0.0f);
        const Vec3 to = player - (e.position + Vec3(0.0f, level::kRobotHeight * 0.5f, 0.0f));
        const float distance = glm::length(to);
        // The game's noticing rule (game/robots.cpp, engaged): on its level, inside the minimum eye radius.
        if (std::abs(to.y) >= 6.0f || distance >= robot->eye_radius_min) continue;
        if (sight_blocked(level, eye, player)) continue;
        const float walk =
            std::max(0.0f, distance - robot->shooting_distance) / std::max(robot->velocity, 0.1f);
        const float seconds = kRobotSecondsToAim + walk;
        if (seconds >= kAmbushSeconds) continue;
        char text[320];
        std::snprintf(
            text, sizeof text,
            "%s %d%s%s%s sees the player start %.1f units away and can shoot within %.1f s: put a wall "
            "between them, move it beyond its eye radius (%.0f), or make it dormant until a link "
            "wakes it",
            std::string(level::type_name(e.type())).c_str(), e.id, e.name.empty() ? "" : " '", e.name.c_str(),
            e.name.empty() ? "" : "'", static_cast<double>(distance), static_cast<double>(seconds),
            static_cast<double>(robot->eye_radius_min));
        out.push_back({Rule::StartAmbush, IssueSeverity::Warning, e.id, text, {}});
    }
}

} // namespace ks::editor
