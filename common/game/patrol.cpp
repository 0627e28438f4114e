#include "game/patrol.h"

#include <algorithm>
#include <cmath>

namespace ks::game {

void advance_patrol(const level::Patrol& patrol, PatrolProgress& progress) {
    const int count = static_cast<int>(patrol.points.size());
    if (count <= 1) {
        progress.target = 0;
        return;
    }
    if (!patrol.ping_pong()) {
        progress.target = (progress.target + 1) % count;
        return;
    }
    if (progress.direction != 1 && progress.direction != -1) progress.direction = 1;
    const int next = progress.target + progress.direction;
    if (next < 0 || next >= count) progress.direction = -progress.direction;
    progress.target = std::clamp(progress.target + progress.direction, 0, count - 1);
}

std::optional<Vec3> patrol_heading(const level::Patrol& patrol, PatrolProgress& progress, const Vec3& feet,
                                   float dt) {
    if (!patrol.active()) return std::nullopt;
    if (progress.target < 0 || progress.target >= static_cast<int>(patrol.points.size())) progress.target = 0;
    if (progress.waiting > 0.0f) {
        progress.waiting = std::max(0.0f, progress.waiting - dt);
        if (progress.waiting > 0.0f) return std::nullopt;
        advance_patrol(patrol, progress);
    }
    const Vec3 to = patrol.points[static_cast<std::size_t>(progress.target)] - feet;
    const Vec3 flat(to.x, 0.0f, to.z);
    const float distance = glm::length(flat);
    if (distance > kPatrolArriveDistance) return flat / distance;
    // Arrived: stand for the wait, or head straight on to the next point when there is none.
    if (patrol.wait > 0.0f) {
        progress.waiting = patrol.wait;
        return std::nullopt;
    }
    advance_patrol(patrol, progress);
    const Vec3 next = patrol.points[static_cast<std::size_t>(progress.target)] - feet;
    const Vec3 next_flat(next.x, 0.0f, next.z);
    const float next_distance = glm::length(next_flat);
    if (next_distance > kPatrolArriveDistance) return next_flat / next_distance;
    return std::nullopt; // a one-point route (or points on top of each other): stand guard
}

} // namespace ks::game
