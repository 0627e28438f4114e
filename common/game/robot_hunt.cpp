// Hunting and searching: a robot that lost the player (or heard a shot) walks the navigation mesh to where
// the player was last seen or heard, looks around there until its search time runs out, then goes back to
// its patrol or wander.
#include "game/robot_motion.h"
#include "game/robot_system.h"

namespace ks::game {
namespace {

// Close enough to the last known position (or a search point) to look round for the next one.
constexpr float kArrived = 1.5f;

} // namespace

void RobotSystem::start_hunt(std::size_t index) {
    Robot& r = robots_[index];
    if (!navigation_ || !(r.props.search_time > 0.0f)) { // nothing to walk on, or told not to search
        stop_hunting(index);
        return;
    }
    if (r.mode == RobotMode::Aim || r.mode == RobotMode::Shoot) anims_[index].play(clips_.shoot_pose_reverse);
    r.mode = RobotMode::Hunt;
    r.mode_time = 0.0f;
    r.hunt_left = r.props.search_time;
    r.replan_in = 0.0f; // plan toward the new goal at once
}

void RobotSystem::stop_hunting(std::size_t index) {
    Robot& r = robots_[index];
    if (r.mode == RobotMode::Aim || r.mode == RobotMode::Shoot)
        anims_[index].play(clips_.shoot_pose_reverse);
    else if (r.mode != RobotMode::Idle)
        anims_[index].play(clips_.idle);
    r.mode = RobotMode::Idle;
    r.mode_time = 0.0f;
    r.wander_length = 0.0f;
    r.patrol.waiting = 0.0f; // back to the point it was heading for, then on along the route
    r.path.clear();
}

void RobotSystem::hunt(std::size_t index, float dt) {
    Robot& r = robots_[index];
    r.hunt_left -= dt;
    if (r.hunt_left <= 0.0f) {
        stop_hunting(index);
        return;
    }
    Vec3 velocity(0.0f);
    if (r.mode == RobotMode::Hunt) {
        velocity = follow_path(r, r.last_known, r.props.velocity, dt);
        const Vec3 left = r.last_known - r.feet;
        if (path_finished(r) || glm::length(Vec2(left.x, left.z)) < kArrived) {
            r.mode = RobotMode::Search;
            r.mode_time = 0.0f;
            r.search_point = r.feet;
        }
    } else { // Search: walk to points around the last known position, one after another
        const Vec3 left = r.search_point - r.feet;
        if (glm::length(Vec2(left.x, left.z)) < kArrived || path_finished(r)) {
            const float angle = core_.rng.uniform(0.0f, 2.0f * kPi);
            const float reach = core_.rng.uniform(0.3f, 1.0f) * core_.settings.robot_search_radius;
            const Vec3 wanted = r.last_known + Vec3(std::cos(angle), 0.0f, std::sin(angle)) * reach;
            const auto on_mesh = navigation_->nearest_point(wanted, Vec3(2.0f, 4.0f, 2.0f));
            r.search_point = on_mesh ? *on_mesh : r.last_known;
            r.replan_in = 0.0f;
        }
        velocity = follow_path(r, r.search_point, core_.settings.robot_wander_speed, dt);
    }
    if (glm::dot(velocity, velocity) > 0.0f)
        r.yaw = turn_toward(r.yaw, yaw_of(velocity), r.props.rotation_velocity * dt);
    auto& mv = core_.world.character(r.body).movement;
    mv.velocity.x = velocity.x + r.knockback.x;
    mv.velocity.z = velocity.z + r.knockback.z;
}

} // namespace ks::game
