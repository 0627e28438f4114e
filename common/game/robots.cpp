// Robot AI (seed-facts §5.2): idle wander, or the patrol route where the level gives one (patrol.h); alert on seeing the player inside the minimum eye radius; follow
// inside the maximum one (hysteresis); shoot pose inside shooting distance; shots on a cooldown with a
// probability; angry after being shot; death clip, then explosion and removal. Robots never hurt robots.
#include "game/game.h"
#include "level/entity_shapes.h"

#include "anim/easing.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace ks::game {
namespace {

float wrap_angle(float a) {
    return std::remainder(a, 2.0f * kPi);
}

// Turns `yaw` toward `target` by at most `max_step` radians.
float turn_toward(float yaw, float target, float max_step) {
    const float d = wrap_angle(target - yaw);
    return wrap_angle(yaw + std::clamp(d, -max_step, max_step));
}

float yaw_of(const Vec3& d) {
    return std::atan2(-d.x, -d.z); // level convention: 0 faces -z
}

// Idle along the patrol route: turn toward the next point and walk at the wander speed, slower while still
// turning (no walking sideways), standing while the route says to wait.
void walk_patrol(Robot& r, physics::MovementState& mv, float speed, float dt) {
    Vec3 velocity(0.0f);
    if (const auto heading = patrol_heading(r.props.patrol, r.patrol, r.feet, dt)) {
        r.yaw = turn_toward(r.yaw, yaw_of(*heading), r.props.rotation_velocity * dt);
        const Vec3 forward(-std::sin(r.yaw), 0.0f, -std::cos(r.yaw));
        velocity = *heading * (speed * std::max(0.0f, glm::dot(forward, *heading)));
    }
    mv.velocity.x = velocity.x + r.knockback.x;
    mv.velocity.z = velocity.z + r.knockback.z;
}

} // namespace

Vec3 Game::robot_muzzle(std::size_t index) const {
    const Robot& r = robots_[index];
    const anim::Rig& rig = animations_->rig;
    std::array<Mat4, 32> local_world{};
    if (rig.size() > static_cast<int>(local_world.size())) return r.feet + Vec3(0, 1.8f, 0);
    const Mat4 root = level::robot_model_matrix(r.feet, r.yaw);
    anim::compute_world(rig, robot_anims_[index].pose(), std::span<Mat4>(local_world.data(), rig.size()),
                        root);
    return Vec3(local_world[static_cast<std::size_t>(hand_tip_node_)][3]);
}

bool Game::robot_sees_player(const Robot& r) const {
    const Vec3 eye = r.feet + Vec3(0, settings_.robot_height * 0.9f, 0);
    const Vec3 target = player_.feet + Vec3(0, settings_.player_height * 0.5f, 0);
    const Vec3 d = target - eye;
    const float len = glm::length(d);
    if (!(len > 1e-4f)) return true;
    physics::RayFilter filter;
    filter.layers = physics::layer::kBlocksSight;
    filter.ignore = r.body;
    return !world_.ray_any({eye, d / len, len}, filter);
}

void Game::damage_robot(std::size_t index, float amount, bool by_player) {
    Robot& r = robots_[index];
    if (!r.alive() || !(amount > 0.0f)) return;
    r.health = std::max(0.0f, r.health - amount);
    r.hit_flash = 0.4f;
    if (by_player) r.angry = r.props.angry_duration;
    push(EventType::RobotHurt, r.feet, r.entity_id, amount);
    if (r.health <= 0.0f) {
        r.mode = RobotMode::Dying;
        r.mode_time = 0.0f;
        robot_anims_[index].play(clips_.death);
        auto& mv = world_.character(r.body).movement;
        mv.velocity.x = mv.velocity.z = 0.0f;
    }
}

void Game::update_robot(std::size_t index, float dt) {
    Robot& r = robots_[index];
    if (r.mode == RobotMode::Dead) return;
    r.mode_time += dt;
    r.hit_flash = std::max(0.0f, r.hit_flash - dt);
    r.knockback *= std::exp(-settings_.knockback_decay * dt);
    auto& mv = world_.character(r.body).movement;
    if (r.mode == RobotMode::Dying) {
        mv.velocity.x = r.knockback.x;
        mv.velocity.z = r.knockback.z;
        if (r.mode_time >= death_length_) {
            r.mode = RobotMode::Dead;
            world_.set_enabled(r.body, false);
            ++robots_killed_;
            push(EventType::RobotDied, r.feet, r.entity_id);
            push(EventType::Explosion, r.feet + Vec3(0, 1.5f, 0), r.entity_id, 0.0f);
        }
        return;
    }
    r.angry = std::max(0.0f, r.angry - dt);
    r.cooldown = std::max(0.0f, r.cooldown - dt);

    const Vec3 centre = r.feet + Vec3(0, settings_.robot_height * 0.5f, 0);
    const Vec3 target = player_.feet + Vec3(0, settings_.player_height * 0.5f, 0);
    const Vec3 to = target - centre;
    const float distance = glm::length(to);
    const bool same_level = std::abs(to.y) < settings_.robot_same_level;
    const bool engaged_before = r.mode != RobotMode::Idle;
    bool engaged = false;
    if (phase_ == Phase::Playing) {
        if (r.angry > 0.0f)
            engaged = true;
        else if (engaged_before)
            engaged = same_level && distance < r.props.eye_radius_max;
        else
            engaged = same_level && distance < r.props.eye_radius_min && robot_sees_player(r);
    }
    const float turn = r.props.rotation_velocity * dt;
    const float facing = yaw_of(Vec3(to.x, 0, to.z));

    if (!engaged) {
        if (engaged_before) {
            if (r.mode == RobotMode::Aim || r.mode == RobotMode::Shoot)
                robot_anims_[index].play(clips_.shoot_pose_reverse);
            else
                robot_anims_[index].play(clips_.idle);
            r.mode = RobotMode::Idle;
            r.mode_time = 0.0f;
            r.wander_length = 0.0f;
            r.patrol.waiting = 0.0f; // back to the point it was heading for, then on along the route
        }
        if (r.props.patrol.active())
            walk_patrol(r, mv, settings_.robot_wander_speed, dt);
        else
            robot_wander(r, index, dt);
        return;
    }
    if (!engaged_before) {
        r.mode = RobotMode::Alert;
        r.mode_time = 0.0f;
        robot_anims_[index].play(clips_.alert);
        push(EventType::RobotAlerted, r.feet, r.entity_id);
    }
    r.yaw = turn_toward(r.yaw, facing, turn);
    Vec3 velocity(0.0f);
    switch (r.mode) {
    case RobotMode::Alert:
        if (r.mode_time >= alert_length_) {
            r.mode = RobotMode::Chase;
            r.mode_time = 0.0f;
        }
        break;
    case RobotMode::Chase:
        if (distance <= r.props.shooting_distance) {
            r.mode = RobotMode::Aim;
            r.mode_time = 0.0f;
            robot_anims_[index].play(clips_.shoot_pose);
        } else {
            const Vec3 flat = glm::normalize(Vec3(to.x, 0, to.z) + Vec3(1e-9f, 0, 0));
            velocity = flat * r.props.velocity;
        }
        break;
    case RobotMode::Aim:
    case RobotMode::Shoot:
        if (distance > r.props.shooting_distance) {
            r.mode = RobotMode::Chase;
            r.mode_time = 0.0f;
            robot_anims_[index].play(clips_.shoot_pose_reverse);
            break;
        }
        if (r.mode == RobotMode::Aim && r.mode_time >= aim_length_) {
            r.mode = RobotMode::Shoot;
            r.mode_time = 0.0f;
        }
        if (r.mode == RobotMode::Shoot && r.cooldown <= 0.0f) {
            r.cooldown = r.props.cooldown;
            robot_anims_[index].play(clips_.shooting);
            robot_fire(index);
        }
        break;
    default:
        break;
    }
    mv.velocity.x = velocity.x + r.knockback.x;
    mv.velocity.z = velocity.z + r.knockback.z;
}

void Game::robot_wander(Robot& r, std::size_t index, float dt) {
    (void)index;
    (void)dt; // the wander is a function of mode_time, advanced by update_robot
    auto& mv = world_.character(r.body).movement;
    if (r.mode_time >= r.wander_length) { // next phase
        r.mode_time = 0.0f;
        if (!r.wander_turning || r.wander_length == 0.0f) {
            // Turn: ±(0.5..1)·π/2 over 1.4 s, plus 3π/4 after bumping into something.
            const float sign = rng_.chance(0.5f) ? 1.0f : -1.0f;
            float delta = sign * rng_.uniform(0.5f, 1.0f) * kPi * 0.5f;
            if (r.collided) delta += 0.75f * kPi;
            r.collided = false;
            r.wander_turning = true;
            r.wander_from = r.yaw;
            r.wander_to = r.yaw + delta;
            r.wander_length = 1.4f;
        } else {
            r.wander_turning = false;
            r.wander_length = rng_.uniform(3.2f, 4.0f);
        }
    }
    Vec3 velocity(0.0f);
    if (r.wander_turning) {
        const double k = std::clamp(r.mode_time / r.wander_length, 0.0f, 1.0f);
        const float e =
            static_cast<float>(anim::tweenjs_formula(anim::EaseFamily::Quadratic, anim::EaseMode::InOut, k));
        r.yaw = wrap_angle(r.wander_from + (r.wander_to - r.wander_from) * e);
    } else {
        const float speed =
            settings_.robot_wander_speed * std::max(0.0f, 1.0f - r.mode_time / r.wander_length);
        velocity = Vec3(-std::sin(r.yaw), 0, -std::cos(r.yaw)) * speed;
    }
    mv.velocity.x = velocity.x + r.knockback.x;
    mv.velocity.z = velocity.z + r.knockback.z;
}

void Game::robot_fire(std::size_t index) {
    Robot& r = robots_[index];
    const Vec3 muzzle = robot_muzzle(index);
    const Vec3 target = player_.feet + Vec3(0, settings_.player_height * 0.5f, 0);
    Vec3 dir = target - muzzle;
    const float len = glm::length(dir);
    dir = len > 1e-5f ? dir / len : Vec3(-std::sin(r.yaw), 0, -std::cos(r.yaw));
    // The reference: with probability 1 - p the shot fires no ray at all (still drawn as a muzzle flash).
    if (!rng_.chance(r.props.hit_probability)) {
        push(EventType::RobotShot, muzzle, r.entity_id, 0.0f, muzzle + dir);
        return;
    }
    const geometry::Ray ray{muzzle, dir, settings_.robot_shot_range};
    physics::RayHit hit;
    const bool any = shoot_ray(ray, r.body, true, hit);
    push(EventType::RobotShot, muzzle, r.entity_id, 1.0f, any ? hit.point : muzzle + dir * ray.max_distance);
    if (!any) return;
    const std::uint64_t user = world_.user_data(hit.body);
    if (user_kind(user) == BodyKind::Player) {
        push(EventType::Hit, hit.point, -1, r.props.damage, hit.normal);
        damage_player(r.props.damage);
    } else if (user_kind(user) == BodyKind::Cylinder) {
        push(EventType::Hit, hit.point, cylinders_[user_index(user)].entity_id, 0.0f, hit.normal);
        explode_cylinder(user_index(user));
    }
}

} // namespace ks::game
