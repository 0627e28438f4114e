#include "model/patrol_validation.h"

#include "nav/nav_mesh.h"

#include <cmath>
#include <cstdio>
#include <optional>

namespace ks::editor {
namespace {

std::vector<SupportSurface> walkable_surfaces(const level::Level& level) {
    std::vector<SupportSurface> out;
    for (const auto& e : level.entities)
        if (auto surface = SupportSurface::of(e)) out.push_back(std::move(*surface));
    return out;
}

std::string num(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", static_cast<double>(v));
    return buf;
}

// What is wrong with a point and where it belongs, or nothing when it stands on a surface.
struct PointProblem {
    std::string message;
    std::optional<float> fixed_y;
};

std::optional<PointProblem> point_problem(const std::vector<SupportSurface>& surfaces, Vec3 p,
                                          const ValidationOptions& o) {
    std::optional<float> below, sunk; // highest surface under the point; lowest one just above it
    bool over_any = false;
    for (const SupportSurface& s : surfaces) {
        const auto h = s.height_at(p.x, p.z);
        if (!h) continue;
        over_any = true;
        if (std::fabs(*h - p.y) <= o.support_tolerance) return std::nullopt;
        if (*h < p.y) {
            if (!below || *h > *below) below = h;
        } else if (*h <= p.y + o.sink_limit && (!sunk || *h < *sunk)) {
            sunk = h;
        }
    }
    if (sunk) return PointProblem{"is sunk " + num(*sunk - p.y) + " units into the floor", sunk};
    if (below) return PointProblem{"floats " + num(p.y - *below) + " units above the floor", below};
    if (over_any) return PointProblem{"is below every floor at its spot", std::nullopt};
    return PointProblem{"is outside every floor", std::nullopt};
}

} // namespace

void check_patrol_support(const level::Level& level, const ValidationOptions& options,
                          std::vector<Issue>& out) {
    std::optional<std::vector<SupportSurface>> surfaces; // built on the first robot with a route
    for (const auto& e : level.entities) {
        const auto* robot = e.try_as<level::RobotProps>();
        if (!robot || !robot->patrol.active()) continue;
        if (!surfaces) surfaces = walkable_surfaces(level);
        const std::string who =
            "robot " + std::to_string(e.id) + (e.name.empty() ? "" : " '" + e.name + "'") + " patrol point ";
        for (size_t i = 0; i < robot->patrol.points.size(); ++i) {
            const Vec3 p = robot->patrol.points[i];
            if (!is_finite(p)) continue; // a format error already
            auto problem = point_problem(*surfaces, p, options);
            if (!problem) continue;
            QuickFix fix;
            if (problem->fixed_y)
                fix = {"Snap onto the floor",
                       fixes::MovePatrolPoint{static_cast<int>(i), {p.x, *problem->fixed_y, p.z}}};
            out.push_back({Rule::Patrol, IssueSeverity::Warning, e.id,
                           who + std::to_string(i) + " " + problem->message, std::move(fix)});
        }
    }
}

void check_patrol_on_mesh(const level::Level& level, nav::NavMesh& mesh, const ValidationOptions& options,
                          std::vector<Issue>& out) {
    const float reach = options.character.radius + options.walk_cell;
    const Vec3 extents(reach, options.character.step_height + options.support_tolerance, reach);
    std::optional<std::vector<SupportSurface>> surfaces;
    for (const auto& e : level.entities) {
        const auto* robot = e.try_as<level::RobotProps>();
        if (!robot || !robot->patrol.active() || !is_finite(e.position)) continue;
        if (!surfaces) surfaces = walkable_surfaces(level);
        const auto feet = mesh.nearest_point(e.position, extents);
        const std::string who =
            "robot " + std::to_string(e.id) + (e.name.empty() ? "" : " '" + e.name + "'") + " patrol point ";
        for (size_t i = 0; i < robot->patrol.points.size(); ++i) {
            const Vec3 p = robot->patrol.points[i];
            if (!is_finite(p) || point_problem(*surfaces, p, options))
                continue; // reported by the support check
            // Detour's nearest polygon only has to overlap the box: measure the distance to the point found.
            const auto on_mesh = mesh.nearest_point(p, extents);
            if (!on_mesh || glm::length(Vec2(on_mesh->x - p.x, on_mesh->z - p.z)) > reach) {
                QuickFix fix;
                // The mesh floats a little above the floor (its height samples): keep the point's own
                // height, which the support check has just found on a surface.
                if (auto nearest = mesh.nearest_point(p, Vec3(8.0f, extents.y, 8.0f)))
                    fix = {"Snap to the nearest walkable point",
                           fixes::MovePatrolPoint{static_cast<int>(i), {nearest->x, p.y, nearest->z}}};
                out.push_back(
                    {Rule::Patrol, IssueSeverity::Warning, e.id,
                     who + std::to_string(i) + " is where robots cannot walk (too close to a wall or a prop)",
                     std::move(fix)});
            } else if (feet && !mesh.reachable(*feet, *on_mesh)) {
                out.push_back({Rule::Patrol,
                               IssueSeverity::Warning,
                               e.id,
                               who + std::to_string(i) + " cannot be walked to from where the robot stands",
                               {}});
            }
        }
    }
}

} // namespace ks::editor
