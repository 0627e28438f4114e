#include "level/patrol_checks.h"

#include "geometry/aabb.h"
#include "geometry/obb.h"
#include "jsonio/json_path.h"
#include "jsonio/number_text.h"
#include "jsonio/suggest.h"
#include "jsonio/text.h"
#include "level/entity_shapes.h"
#include "level/level_checks.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace ks::level {
namespace {

using jsonio::element_path;
using jsonio::member_path;

std::string point_text(const Vec3& p) {
    return "(" + jsonio::readable_float(p.x) + ", " + jsonio::readable_float(p.y) + ", " +
           jsonio::readable_float(p.z) + ")";
}

void check_point(const Vec3& point, const std::string& path, DiagnosticSink& sink) {
    if (!is_finite(point)) {
        sink.error(path, "patrol point " + point_text(point) + " is not finite",
                   "write finite numbers [x, y, z] within ±" + jsonio::format_readable(kPositionLimit));
        return;
    }
    for (int i = 0; i < 3; ++i)
        if (std::fabs(point[i]) > kPositionLimit) {
            sink.error(path, "patrol point " + point_text(point) + " is out of range",
                       "valid: -" + jsonio::format_readable(kPositionLimit) + " .. " +
                           jsonio::format_readable(kPositionLimit) + " units each");
            return;
        }
}

// The box around every entity's shape (robots by their bodies), or none for a level of nothing finite.
std::optional<geometry::Aabb> level_extent(const Level& level) {
    std::optional<geometry::Aabb> extent;
    for (const Entity& e : level.entities) {
        if (!is_finite(e.position) || !is_finite(e.rotation)) continue;
        const PlacedShape shape = bounding_shape(e);
        const geometry::Obb box{shape.centre(), glm::mat3_cast(shape.rotation()), shape.half};
        const geometry::Aabb bounds = box.aabb();
        if (!is_finite(bounds.min) || !is_finite(bounds.max)) continue;
        if (!extent)
            extent = bounds;
        else
            extent = geometry::Aabb{glm::min(extent->min, bounds.min), glm::max(extent->max, bounds.max)};
    }
    return extent;
}

float distance_outside(const geometry::Aabb& box, const Vec3& p) {
    const Vec3 outside = glm::max(glm::max(box.min - p, p - box.max), Vec3(0.0f));
    return glm::length(outside);
}

std::string extent_text(const geometry::Aabb& box) {
    return "x " + jsonio::readable_float(box.min.x) + " .. " + jsonio::readable_float(box.max.x) + ", y " +
           jsonio::readable_float(box.min.y) + " .. " + jsonio::readable_float(box.max.y) + ", z " +
           jsonio::readable_float(box.min.z) + " .. " + jsonio::readable_float(box.max.z);
}

} // namespace

void check_patrol(const Patrol& patrol, const std::string& path, DiagnosticSink& sink) {
    if (!patrol.active()) return; // no patrol: nothing is saved, the robot wanders
    const std::string points_path = member_path(path, "points");
    if (patrol.points.size() > static_cast<size_t>(kMaxPatrolPoints)) {
        sink.error(points_path,
                   "patrol has " + std::to_string(patrol.points.size()) + " points; at most " +
                       std::to_string(kMaxPatrolPoints),
                   "a patrol is a route of a few points; keep the corners and drop the rest");
    } else {
        for (size_t i = 0; i < patrol.points.size(); ++i)
            check_point(patrol.points[i], element_path(points_path, i), sink);
    }
    check_patrol_mode_and_wait(patrol, path, sink);
}

void check_patrol_mode_and_wait(const Patrol& patrol, const std::string& path, DiagnosticSink& sink) {
    const auto& options = patrol.mode.options;
    if (std::find(options.begin(), options.end(), patrol.mode.value) == options.end()) {
        std::string hint = "valid: " + jsonio::join(options);
        if (std::string near = jsonio::closest_match(patrol.mode.value, options); !near.empty())
            hint = "did you mean \"" + near + "\"? " + hint;
        sink.error(member_path(path, "mode"), "unknown patrol mode " + jsonio::quote_text(patrol.mode.value),
                   hint);
    }
    if (!std::isfinite(patrol.wait) || patrol.wait < 0.0f || patrol.wait > static_cast<float>(kMaxPatrolWait))
        sink.error(member_path(path, "wait"),
                   "patrol wait " + jsonio::readable_float(patrol.wait) + " is out of range",
                   "valid: 0 .. " + jsonio::format_readable(kMaxPatrolWait) + " s, the same at every point");
}

void check_patrol_reach(const Level& level, DiagnosticSink& sink, const std::vector<size_t>& source_index) {
    std::optional<geometry::Aabb> extent;
    bool measured = false;
    for (size_t i = 0; i < level.entities.size(); ++i) {
        const Entity& entity = level.entities[i];
        // A spawner's robots walk its patrol (its robot fields are the spawner's own, props.patrol).
        const Patrol* patrol = nullptr;
        if (const auto* robot = entity.try_as<RobotProps>())
            patrol = &robot->patrol;
        else if (const auto* spawner = entity.try_as<SpawnerProps>())
            patrol = &spawner->robot.patrol;
        if (!patrol || !patrol->active() || patrol->points.size() > kMaxPatrolPoints) continue;
        if (!measured) extent = level_extent(level), measured = true;
        if (!extent) return;
        const size_t shown = i < source_index.size() ? source_index[i] : i;
        const std::string points_path = member_path(
            member_path(member_path(element_path("entities", shown), "props"), "patrol"), "points");
        SubjectScope scope(sink, entity_subject(entity));
        for (size_t k = 0; k < patrol->points.size(); ++k) {
            const Vec3& point = patrol->points[k];
            if (!is_finite(point)) continue; // reported by check_patrol
            const float outside = distance_outside(*extent, point);
            if (outside <= static_cast<float>(kPatrolReach)) continue;
            sink.error(element_path(points_path, k),
                       "patrol point " + point_text(point) + " is " +
                           jsonio::readable_float(std::round(outside)) + " units outside the level (" +
                           extent_text(*extent) + ")",
                       std::string("move it to where ") +
                           (entity.type() == EntityType::Spawner ? "the spawned robots" : "the robot") +
                           " can walk; at most " + jsonio::format_readable(kPatrolReach) +
                           " units outside the level's entities");
        }
    }
}

} // namespace ks::level
