// The robots' use of the navigation mesh: built once at level load (the doors keep its door polygons as they
// stand, interactables.cpp), path following toward a goal, and sounds that travel along the mesh to robots'
// ears.
#include "core/log.h"
#include "game/interactables.h"
#include "game/robot_system.h"
#include "geometry/ground_plane.h"
#include "nav/nav_cache.h"
#include "physics/character.h"

#include <algorithm>
#include <cmath>

namespace ks::game {
namespace {

// A corner closer than this (horizontally) counts as reached: the next one is steered to.
constexpr float kCornerReached = 0.6f;
// A goal that moved farther than this since the last plan is planned for again at once.
constexpr float kGoalMoved = 1.5f;
// Robots closer than this many robot radii (centre to centre) push each other aside while walking.
constexpr float kSeparationRadii = 3.0f;

} // namespace

Result<std::unique_ptr<nav::NavMesh>> build_robot_navigation(const level::Level& level) {
    const physics::CharacterSettings character;
    return nav::build_cached(level,
                             nav::robot_nav_settings(character.step_height, character.max_slope_degrees));
}

void RobotSystem::build_navigation(const level::Level& level, std::shared_ptr<const nav::NavMesh> source,
                                   std::span<const Door> doors) {
    auto mesh = source ? source->clone() : build_robot_navigation(level);
    if (!mesh) {
        // One clear message; robots without a mesh stand guard (turn, aim and shoot, never walk).
        navigation_error_ = mesh.error().str();
        if (!robots_.empty()) log::warn("robots will stand guard: " + navigation_error_);
        return;
    }
    navigation_ = std::move(*mesh);
    for (const Door& d : doors) navigation_->set_door_open(d.entity_id, d.progress > 0.0f);
    for (Robot& r : robots_) r.path.reserve(kMaxPathCorners);
}

Vec3 RobotSystem::follow_path(Robot& r, const Vec3& goal, float speed, float dt) {
    if (!navigation_ || !(speed > 0.0f)) return Vec3(0.0f);
    r.replan_in -= dt;
    if (r.replan_in <= 0.0f || geometry::ground_distance(goal, r.path_goal) > kGoalMoved || r.path.empty()) {
        r.replan_in = core_.settings.robot_replan_interval;
        r.path_goal = goal;
        r.path_next = 0;
        const nav::PathStatus status = navigation_->find_path(r.feet, goal, r.path);
        if (status == nav::PathStatus::StartOffMesh || status == nav::PathStatus::EndOffMesh) r.path.clear();
        if (r.path.size() > kMaxPathCorners) r.path.resize(kMaxPathCorners);
    }
    while (r.path_next < r.path.size() &&
           geometry::ground_distance(r.path[r.path_next], r.feet) < kCornerReached)
        ++r.path_next;
    if (r.path_next >= r.path.size()) return Vec3(0.0f);
    const Vec3 corner = r.path[r.path_next];
    const Vec3 d(corner.x - r.feet.x, 0.0f, corner.z - r.feet.z);
    const float len = glm::length(d);
    if (!(len > 1e-4f)) return Vec3(0.0f);
    const Vec3 steer = d / len + separation(r);
    const float steer_len = glm::length(steer);
    return steer_len > 1e-4f ? steer / steer_len * speed : Vec3(0.0f);
}

// Robots walking the mesh keep clear of each other: a push away from every living robot closer than
// kSeparation (stronger the closer), so robots meeting in a doorway file through instead of pressing into
// each other; their capsules still collide.
Vec3 RobotSystem::separation(const Robot& r) const {
    const float reach = core_.settings.robot_radius * kSeparationRadii;
    Vec3 push(0.0f);
    for (const Robot& other : robots_) {
        if (&other == &r || !other.alive()) continue;
        const Vec3 away(r.feet.x - other.feet.x, 0.0f, r.feet.z - other.feet.z);
        const float distance_sq = glm::dot(away, away);
        if (distance_sq >= reach * reach || distance_sq < 1e-8f) continue;
        const float distance = std::sqrt(distance_sq);
        push += away / distance * (1.0f - distance / reach);
    }
    return push;
}

bool RobotSystem::path_finished(const Robot& r) const {
    return r.path_next >= r.path.size();
}

void RobotSystem::hear_sound(const Vec3& source) {
    if (!navigation_ || !core_.playing()) return;
    for (Robot& r : robots_) {
        if (!r.alive() || (r.mode != RobotMode::Idle && r.mode != RobotMode::Search)) continue;
        const float radius = r.props.hearing_radius;
        // The straight line is never longer than the way round: only robots inside it ask the mesh.
        if (!(radius > 0.0f) || glm::length(source - r.feet) > radius) continue;
        const auto along_mesh = navigation_->path_length(r.feet, source);
        if (!along_mesh || *along_mesh > radius) continue;
        r.heard = true;
        r.last_known = source;
    }
}

} // namespace ks::game
