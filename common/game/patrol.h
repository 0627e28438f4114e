#pragma once
// A robot's progress along its patrol route (level::Patrol) while idle: the point it heads for, the turn at
// either end of a ping-pong route and the wait at each point. It answers only "where to next"; the straight
// walk toward that point lives in robots.cpp, so path following on the navigation mesh can replace the
// walking without touching the route.
#include "core/math.h"
#include "level/level.h"

#include <optional>

namespace ks::game {

// Plain data, hashed by Game::state_hash so a replay reproduces the route bit for bit.
struct PatrolProgress {
    int target = 0;       // index of the point the robot is heading for (or standing at, while waiting)
    int direction = 1;    // +1, or -1 on the way back along a ping-pong route
    float waiting = 0.0f; // seconds left standing at the target
};

// Horizontal distance at which a point counts as reached: well under the robot's radius, and far more than
// one step of walking, so a robot never overshoots and circles a point.
inline constexpr float kPatrolArriveDistance = 0.5f;

// The index after `progress.target` along the route: loops wrap to the first point, ping-pong routes turn
// round at either end. Turning updates `progress.direction`.
void advance_patrol(const level::Patrol& patrol, PatrolProgress& progress);

// One step of `dt` seconds for a robot with its feet at `feet`: counts the wait down (moving on when it
// ends), notices arrival (starting the wait), and returns the flat unit direction to walk in, or none while
// the robot stands at a point.
std::optional<Vec3> patrol_heading(const level::Patrol& patrol, PatrolProgress& progress, const Vec3& feet,
                                   float dt);

} // namespace ks::game
