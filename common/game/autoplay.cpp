#include "game/autoplay.h"

#include <algorithm>
#include <cmath>

namespace ks::game {
namespace {

float wrap_angle(float a) {
    return std::remainder(a, 2.0f * kPi);
}

float yaw_toward(const Vec3& from, const Vec3& to) {
    return std::atan2(-(to.x - from.x), -(to.z - from.z));
}

} // namespace

Autoplay::Autoplay(const Game& game, std::uint64_t seed, AutoplaySettings settings)
    : settings_(settings), rng_(seed, 0x626f74ull) {
    geometry::Aabb region = game.level_bounds();
    if (region.min.x > region.max.x)
        region = {game.player_start() - Vec3(50), game.player_start() + Vec3(50)};
    grid_ = NavGrid::build(game.world(), region, game.player_start().y);
    path_.reserve(1024);
}

Vec3 Autoplay::goal(const Game& game) const {
    if (!game.panels().empty()) return game.panels().front().centre;
    return game.player().feet;
}

int Autoplay::pick_target(const Game& game) const {
    const PlayerState& p = game.player();
    const Vec3 eye = p.eye();
    int best = -1;
    float best_distance = settings_.engage_range;
    physics::RayFilter filter;
    filter.layers = physics::layer::kShootable;
    filter.ignore = p.body;
    const auto robots = game.robots();
    for (std::size_t i = 0; i < robots.size(); ++i) {
        const Robot& r = robots[i];
        if (!r.alive()) continue;
        const Vec3 centre = r.feet + Vec3(0, 1.5f, 0);
        const Vec3 d = centre - eye;
        const float dist = glm::length(d);
        if (dist >= best_distance || dist < 1e-3f) continue;
        physics::RayHit hit;
        if (!game.world().ray_closest({eye, d / dist, dist + 2.0f}, hit, filter) || !(hit.body == r.body))
            continue;
        best = static_cast<int>(i);
        best_distance = dist;
    }
    return best;
}

void Autoplay::aim_at(const Game& game, const Vec3& point, Input& in, float& yaw_error,
                      float& pitch_error) const {
    const PlayerState& p = game.player();
    const Vec3 eye = p.eye();
    const Vec3 d = point - eye;
    const float horizontal = std::sqrt(d.x * d.x + d.z * d.z);
    const float want_yaw = yaw_toward(eye, point);
    const float want_pitch = std::atan2(d.y, std::max(horizontal, 1e-4f));
    const float max_turn = settings_.turn_rate * static_cast<float>(game.settings().step);
    yaw_error = wrap_angle(want_yaw - p.yaw);
    pitch_error = want_pitch - p.pitch;
    in.look_yaw = std::clamp(yaw_error, -max_turn, max_turn);
    in.look_pitch = std::clamp(pitch_error, -max_turn, max_turn);
}

Input Autoplay::decide(const Game& game) {
    Input in;
    if (game.phase() != Phase::Playing || game.paused()) return in;
    const float dt = static_cast<float>(game.settings().step);
    const PlayerState& p = game.player();
    fire_wait_ = std::max(0.0f, fire_wait_ - dt);
    interact_wait_ = std::max(0.0f, interact_wait_ - dt);
    since_plan_ += dt;
    float yaw_error = 0.0f, pitch_error = 0.0f;

    // Fight: the nearest robot in sight — with ammo. Without, fighting is standing still (the soak found the
    // bot aiming at robots for an hour with an empty rifle): it ignores robots and heads for the panel.
    if (const int target = p.ammo > 0 ? pick_target(game) : -1; target >= 0) {
        const Robot& r = game.robots()[static_cast<std::size_t>(target)];
        const Vec3 centre = r.feet + Vec3(0, 1.5f, 0);
        aim_at(game, centre, in, yaw_error, pitch_error);
        const float distance = glm::length(centre - p.eye());
        const float tolerance =
            settings_.aim_tolerance * game.settings().robot_radius / std::max(distance, 1.0f);
        const float residual_yaw = yaw_error - in.look_yaw, residual_pitch = pitch_error - in.look_pitch;
        if (std::abs(residual_yaw) < tolerance && std::abs(residual_pitch) < tolerance &&
            fire_wait_ <= 0.0f && p.ammo > 0) {
            in.fire = true;
            fire_wait_ = settings_.fire_interval;
        }
        stuck_time_ = 0.0f;
        stuck_anchor_ = p.feet;
        return in;
    }

    const Vec3 goal_point = goal(game);
    // At the panel: face it and press E.
    if (!game.panels().empty() && game.interact_target() == game.panels().front().entity_id) {
        aim_at(game, goal_point, in, yaw_error, pitch_error);
        if (interact_wait_ <= 0.0f) {
            in.interact = true;
            interact_wait_ = 0.3f;
        }
        return in;
    }

    if (since_plan_ >= settings_.replan_interval || waypoint_ >= path_.size()) {
        since_plan_ = 0.0f;
        grid_.find_path(p.feet, goal_point, path_);
        waypoint_ = 0;
    }
    while (waypoint_ < path_.size() &&
           glm::length(Vec3(path_[waypoint_].x - p.feet.x, 0, path_[waypoint_].z - p.feet.z)) < 1.5f)
        ++waypoint_;

    // A closed door on the way: stop in its sensor, face it, press E, wait for it to open.
    for (const Door& d : game.doors()) {
        if (!d.player_inside || d.progress >= 0.95f) continue;
        bool on_path = false;
        for (std::size_t k = waypoint_; k < std::min(path_.size(), waypoint_ + 16); ++k)
            if (glm::length(Vec3(path_[k].x - d.frame.position.x, 0, path_[k].z - d.frame.position.z)) < 3.0f)
                on_path = true;
        if (!on_path) continue;
        aim_at(game, d.frame.position + Vec3(0, 2.5f, 0), in, yaw_error, pitch_error);
        if (!d.opening && game.interact_target() == d.entity_id && interact_wait_ <= 0.0f) {
            in.interact = true;
            interact_wait_ = 0.3f;
        }
        return in;
    }

    if (path_.empty()) return in;
    const Vec3 next = path_[std::min(waypoint_ + 1, path_.size() - 1)];
    aim_at(game, next + Vec3(0, p.eye().y - next.y, 0), in, yaw_error, pitch_error);
    in.look_pitch = std::clamp(-p.pitch, -0.1f, 0.1f);
    in.move_forward = std::abs(yaw_error) < 0.5f ? 1.0f : 0.2f;

    // Unstick: no progress for 2 s, strafe a random way for half a second and replan.
    stuck_time_ += dt;
    if (glm::length(p.feet - stuck_anchor_) > 1.5f) {
        stuck_time_ = 0.0f;
        stuck_anchor_ = p.feet;
    }
    if (stuck_time_ > 2.0f) {
        stuck_time_ = 0.0f;
        unstick_time_ = 0.5f;
        unstick_side_ = rng_.chance(0.5f) ? 1.0f : -1.0f;
        since_plan_ = 1e9f;
    }
    if (unstick_time_ > 0.0f) {
        unstick_time_ -= dt;
        in.move_right = unstick_side_;
        in.move_forward = -0.5f;
    }
    return in;
}

} // namespace ks::game
