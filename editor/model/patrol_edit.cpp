#include "model/patrol_edit.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ks::editor {
namespace {

constexpr float kPointLimit = 1e5f; // the level format's position range (level_checks.h kPositionLimit)

std::string point_text(Vec3 p) {
    auto n = [](float v) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%g", static_cast<double>(v));
        return std::string(buf);
    };
    return n(p.x) + "," + n(p.y) + "," + n(p.z);
}

Result<void> check_point(Vec3 point) {
    if (!is_finite(point))
        return Error("patrol point " + point_text(point) + " is not finite", Location{},
                     "write three finite numbers, like 10,0,-5");
    for (int i = 0; i < 3; ++i)
        if (std::fabs(point[i]) > kPointLimit)
            return Error("patrol point " + point_text(point) + " is out of range", Location{},
                         "each coordinate within -100000 .. 100000");
    return ok();
}

Result<void> check_patrol_index(const level::Patrol& patrol, int index) {
    if (index >= 0 && index < static_cast<int>(patrol.points.size())) return ok();
    if (patrol.points.empty())
        return Error("the robot has no patrol points", Location{}, "add one first: patrol ID add X,Y,Z");
    return Error("no patrol point " + std::to_string(index), Location{},
                 "points are numbered 0 .. " + std::to_string(patrol.points.size() - 1));
}

} // namespace

Result<void> add_patrol_point(level::Patrol& patrol, Vec3 point, std::optional<int> after) {
    if (auto r = check_point(point); !r) return r;
    if (patrol.points.size() >= static_cast<size_t>(level::kMaxPatrolPoints))
        return Error("the patrol already has " + std::to_string(patrol.points.size()) + " points; at most " +
                         std::to_string(level::kMaxPatrolPoints),
                     Location{}, "a patrol is a route of a few points; remove some first");
    const int count = static_cast<int>(patrol.points.size());
    const int insert_at = after ? *after + 1 : count;
    if (insert_at < 0 || insert_at > count)
        return Error("cannot add after point " + std::to_string(*after), Location{},
                     "after -1 (first) .. " + std::to_string(count - 1) + " (last)");
    patrol.points.insert(patrol.points.begin() + insert_at, point);
    return ok();
}

Result<void> move_patrol_point(level::Patrol& patrol, int index, Vec3 point) {
    if (auto r = check_patrol_index(patrol, index); !r) return r;
    if (auto r = check_point(point); !r) return r;
    patrol.points[static_cast<size_t>(index)] = point;
    return ok();
}

Result<void> remove_patrol_point(level::Patrol& patrol, int index) {
    if (auto r = check_patrol_index(patrol, index); !r) return r;
    patrol.points.erase(patrol.points.begin() + index);
    if (patrol.points.empty()) patrol = {};
    return ok();
}

Result<void> set_patrol_mode(level::Patrol& patrol, std::string_view mode) {
    const auto& options = patrol.mode.options;
    if (std::find(options.begin(), options.end(), mode) == options.end())
        return Error("unknown patrol mode '" + std::string(mode) + "'", Location{}, "modes: loop, ping_pong");
    patrol.mode.value = std::string(mode);
    return ok();
}

Result<void> set_patrol_wait(level::Patrol& patrol, float seconds) {
    if (!std::isfinite(seconds) || seconds < 0.0f || seconds > static_cast<float>(level::kMaxPatrolWait))
        return Error("patrol wait must be 0 .. 600 seconds", Location{}, "one wait, the same at every point");
    patrol.wait = seconds;
    return ok();
}

} // namespace ks::editor
