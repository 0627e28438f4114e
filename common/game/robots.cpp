// Robot AI (seed-facts §5.2): idle wander, or the patrol route where the level gives one (patrol.h); alert on
// seeing the player inside the minimum eye radius; follow inside the maximum one (hysteresis); shoot pose
// inside shooting distance; shots on a cooldown with a probability; angry after being shot; death clip, then
// explosion and removal. Robots never hurt robots.
#include "game/explosives.h"
#include "game/player_system.h"
#include "game/robot_motion.h"
#include "game/robot_system.h"
#include "level/entity_shapes.h"

#include "anim/easing.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace ks::game {

Vec3 RobotSystem::muzzle(std::size_t index) const {
    const Robot& r = robots_[index];
    const anim::Rig& rig = animations_->rig;
    std::array<Mat4, 32> local_world{};
    if (rig.size() > static_cast<int>(local_world.size())) return r.feet + Vec3(0, 1.8f, 0);
    const Mat4 root = level::robot_model_matrix(r.feet, r.yaw);
    anim::compute_world(rig, anims_[index].pose(), std::span<Mat4>(local_world.data(), rig.size()), root);
    return Vec3(local_world[static_cast<std::size_t>(hand_tip_node_)][3]);
}

// Nothing that blocks sight between the robot at `height` above its feet and the player's centre.
bool RobotSystem::line_to_player(const Robot& r, float height) const {
    const Vec3 from = r.feet + Vec3(0, height, 0);
    const Vec3 target = player_.state().feet + Vec3(0, core_.settings.player_height * 0.5f, 0);
    const Vec3 d = target - from;
    const float len = glm::length(d);
    if (!(len > 1e-4f)) return true;
    physics::RayFilter filter;
    filter.layers = physics::layer::kBlocksSight;
    filter.ignore = r.body;
    return !core_.world.ray_any({from, d / len, len}, filter);
}

bool RobotSystem::sees_player(const Robot& r) const {
    return line_to_player(r, core_.settings.robot_height * 0.9f); // from the eye
}

void RobotSystem::damage(std::size_t index, float amount, bool by_player) {
    Robot& r = robots_[index];
    if (!r.alive() || !(amount > 0.0f)) return;
    r.health = std::max(0.0f, r.health - amount);
    r.hit_flash = kRobotHitFlashSeconds;
    if (by_player) r.angry = r.props.angry_duration;
    core_.push(EventType::RobotHurt, r.feet, r.entity_id, amount);
    if (r.health <= 0.0f) {
        r.mode = RobotMode::Dying;
        r.mode_time = 0.0f;
        anims_[index].play(clips_.death);
        auto& mv = core_.world.character(r.body).movement;
        mv.velocity.x = mv.velocity.z = 0.0f;
    }
}

void RobotSystem::update(float dt) {
    for (std::size_t i = 0; i < robots_.size(); ++i) {
        if (robots_[i].dormant) hold_dormant(i, dt); // hurt, it wakes and acts at once
        if (!robots_[i].dormant) update_robot(i, dt);
    }
}

void RobotSystem::read_back(float dt) {
    for (std::size_t i = 0; i < robots_.size(); ++i) {
        Robot& r = robots_[i];
        if (r.mode == RobotMode::Dead) continue;
        r.feet = core_.world.transform(r.body).position - Vec3(0, core_.settings.robot_height * 0.5f, 0);
        anims_[i].advance(dt);
        clip_events(i);
        if (r.feet.y < core_.settings.fall_limit && r.alive()) damage(i, r.health, false);
    }
}

void RobotSystem::wake(std::size_t index, bool alert) {
    Robot& r = robots_[index];
    if (!r.alive()) return;
    r.dormant = false;
    if (alert) { // it knows where the player is: fights, or goes to look
        r.angry = std::max(r.angry, r.props.angry_duration);
        r.heard = true;
        r.last_known = player_.state().feet;
    }
}

// A dormant robot stands where it is, blind and deaf; any damage wakes it (and then it acts this step).
void RobotSystem::hold_dormant(std::size_t index, float dt) {
    Robot& r = robots_[index];
    if (!r.alive() || r.angry > 0.0f || r.health < r.props.health) {
        r.dormant = false;
        return;
    }
    r.heard = false;
    r.hit_flash = std::max(0.0f, r.hit_flash - dt);
    r.knockback *= std::exp(-core_.settings.knockback_decay * dt);
    auto& mv = core_.world.character(r.body).movement;
    mv.velocity.x = r.knockback.x;
    mv.velocity.z = r.knockback.z;
}

void RobotSystem::update_robot(std::size_t index, float dt) {
    Robot& r = robots_[index];
    if (r.mode == RobotMode::Dead) return;
    r.mode_time += dt;
    r.hit_flash = std::max(0.0f, r.hit_flash - dt);
    r.knockback *= std::exp(-core_.settings.knockback_decay * dt);
    auto& mv = core_.world.character(r.body).movement;
    if (r.mode == RobotMode::Dying) {
        mv.velocity.x = r.knockback.x;
        mv.velocity.z = r.knockback.z;
        if (r.mode_time >= death_length_) {
            r.mode = RobotMode::Dead;
            core_.world.set_enabled(r.body, false);
            ++killed_;
            core_.push(EventType::RobotDied, r.feet, r.entity_id);
            core_.push(EventType::Explosion, r.feet + Vec3(0, 1.5f, 0), r.entity_id, 0.0f);
        }
        return;
    }
    r.angry = std::max(0.0f, r.angry - dt);
    r.cooldown = std::max(0.0f, r.cooldown - dt);

    const Vec3 centre = r.feet + Vec3(0, core_.settings.robot_height * 0.5f, 0);
    const Vec3 target = player_.state().feet + Vec3(0, core_.settings.player_height * 0.5f, 0);
    const Vec3 to = target - centre;
    const float distance = glm::length(to);
    const bool same_level = std::abs(to.y) < core_.settings.robot_same_level;
    const bool heard = std::exchange(r.heard, false);
    if (engaged(r, distance, same_level)) {
        r.last_known = player_.state().feet;
        r.hunt_left = r.props.search_time;
        fight(index, distance, dt);
        return;
    }
    const bool fighting = r.mode == RobotMode::Alert || r.mode == RobotMode::Chase ||
                          r.mode == RobotMode::Aim || r.mode == RobotMode::Shoot;
    if (fighting || (heard && (r.mode == RobotMode::Idle || r.mode == RobotMode::Search))) {
        if (heard && r.mode == RobotMode::Idle) core_.push(EventType::RobotAlerted, r.feet, r.entity_id);
        start_hunt(index);
    }
    if (r.mode == RobotMode::Hunt || r.mode == RobotMode::Search) {
        hunt(index, dt);
        return;
    }
    if (r.props.patrol.active())
        walk_patrol(r, dt);
    else
        wander(r, dt);
}

// The reference's rules: anger always engages; a robot already fighting keeps on while the player is on its
// level inside the maximum eye radius; any other notices the player on its level inside the minimum eye
// radius with a line of sight.
bool RobotSystem::engaged(const Robot& r, float distance, bool same_level) const {
    if (!core_.playing()) return false;
    if (r.angry > 0.0f) return true;
    const bool fighting = r.mode == RobotMode::Alert || r.mode == RobotMode::Chase ||
                          r.mode == RobotMode::Aim || r.mode == RobotMode::Shoot;
    if (fighting) return same_level && distance < r.props.eye_radius_max;
    return same_level && distance < r.props.eye_radius_min && sees_player(r);
}

// Whether a shot from the robot's chest would reach the player: a window the robot sees through may still
// be too high to shoot through, and then it walks round instead of shooting the wall.
bool RobotSystem::has_clear_shot(const Robot& r) const {
    return line_to_player(r, core_.settings.robot_height * 0.6f); // from the chest
}

void RobotSystem::fight(std::size_t index, float distance, float dt) {
    Robot& r = robots_[index];
    auto& mv = core_.world.character(r.body).movement;
    if (r.mode == RobotMode::Idle) {
        r.mode = RobotMode::Alert;
        r.mode_time = 0.0f;
        anims_[index].play(clips_.alert);
        core_.push(EventType::RobotAlerted, r.feet, r.entity_id);
    } else if (r.mode == RobotMode::Hunt || r.mode == RobotMode::Search) { // found again: no second alert
        r.mode = RobotMode::Chase;
        r.mode_time = 0.0f;
    }
    const Vec3 to = player_.state().feet - r.feet;
    Vec3 velocity(0.0f);
    switch (r.mode) {
    case RobotMode::Alert:
        if (r.mode_time >= alert_length_) {
            r.mode = RobotMode::Chase;
            r.mode_time = 0.0f;
        }
        break;
    case RobotMode::Chase:
        if (distance <= r.props.shooting_distance && has_clear_shot(r)) {
            r.mode = RobotMode::Aim;
            r.mode_time = 0.0f;
            anims_[index].play(clips_.shoot_pose);
        } else {
            velocity = follow_path(r, player_.state().feet, r.props.velocity, dt);
        }
        break;
    case RobotMode::Aim:
    case RobotMode::Shoot:
        if (distance > r.props.shooting_distance || !has_clear_shot(r)) {
            r.mode = RobotMode::Chase;
            r.mode_time = 0.0f;
            anims_[index].play(clips_.shoot_pose_reverse);
            break;
        }
        if (r.mode == RobotMode::Aim &&
            r.mode_time >=
                std::max(0.0f, aim_length_ + difficulty_scale(core_.settings.difficulty).reaction_delay)) {
            r.mode = RobotMode::Shoot;
            r.mode_time = 0.0f;
        }
        if (r.mode == RobotMode::Shoot && r.cooldown <= 0.0f) {
            r.cooldown = r.props.cooldown;
            anims_[index].play(clips_.shooting);
            if (!shot_on_event_) fire(index); // else at the clip's muzzle_flash (robot_clip_events)
        }
        break;
    default:
        break;
    }
    // Face where it walks (round a wall, the path leads away from the player); the player when it stands.
    const Vec3 facing = glm::dot(velocity, velocity) > 0.0f ? velocity : Vec3(to.x, 0, to.z);
    r.yaw = turn_toward(r.yaw, yaw_of(facing), r.props.rotation_velocity * dt);
    mv.velocity.x = velocity.x + r.knockback.x;
    mv.velocity.z = velocity.z + r.knockback.z;
}

// Idle along the patrol route: turn toward the next point and walk at the wander speed, slower while still
// turning (no walking sideways), standing while the route says to wait. The way to the point follows the
// navigation mesh (round a wall between two points); straight where there is no mesh or no path.
void RobotSystem::walk_patrol(Robot& r, float dt) {
    auto& mv = core_.world.character(r.body).movement;
    Vec3 velocity(0.0f);
    if (auto heading = patrol_heading(r.props.patrol, r.patrol, r.feet, dt)) {
        const Vec3 point = r.props.patrol.points[static_cast<std::size_t>(r.patrol.target)];
        const Vec3 along_mesh = follow_path(r, point, 1.0f, dt);
        if (glm::dot(along_mesh, along_mesh) > 0.0f) heading = along_mesh;
        r.yaw = turn_toward(r.yaw, yaw_of(*heading), r.props.rotation_velocity * dt);
        const Vec3 forward(-std::sin(r.yaw), 0.0f, -std::cos(r.yaw));
        velocity =
            *heading * (core_.settings.robot_wander_speed * std::max(0.0f, glm::dot(forward, *heading)));
    }
    mv.velocity.x = velocity.x + r.knockback.x;
    mv.velocity.z = velocity.z + r.knockback.z;
}

void RobotSystem::wander(Robot& r, float dt) {
    (void)dt; // the wander is a function of mode_time, advanced by update_robot
    auto& mv = core_.world.character(r.body).movement;
    if (r.mode_time >= r.wander_length) { // next phase
        r.mode_time = 0.0f;
        if (!r.wander_turning || r.wander_length == 0.0f) {
            // Turn: ±(0.5..1)·π/2 over 1.4 s, plus 3π/4 after bumping into something.
            const float sign = core_.rng.chance(0.5f) ? 1.0f : -1.0f;
            float delta = sign * core_.rng.uniform(0.5f, 1.0f) * kPi * 0.5f;
            if (r.collided) delta += 0.75f * kPi;
            r.collided = false;
            r.wander_turning = true;
            r.wander_from = r.yaw;
            r.wander_to = r.yaw + delta;
            r.wander_length = 1.4f;
        } else {
            r.wander_turning = false;
            r.wander_length = core_.rng.uniform(3.2f, 4.0f);
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
            core_.settings.robot_wander_speed * std::max(0.0f, 1.0f - r.mode_time / r.wander_length);
        velocity = Vec3(-std::sin(r.yaw), 0, -std::cos(r.yaw)) * speed;
    }
    mv.velocity.x = velocity.x + r.knockback.x;
    mv.velocity.z = velocity.z + r.knockback.z;
}

void RobotSystem::clip_events(std::size_t index) {
    const Robot& r = robots_[index];
    for (const anim::FiredEvent& fired : anims_[index].fired_events()) {
        core_.push_cue(EventType::ClipCue, r.feet + Vec3(0, core_.settings.robot_height * 0.5f, 0),
                       r.entity_id, fired.event->sound);
        // A shot cut short (the robot turned away or died before the flash) never fires: its clip is no
        // longer the one playing, so its event is not reported.
        if (fired.clip == clips_.shooting && fired.event->name == kMuzzleFlashEvent && r.alive()) fire(index);
    }
}

void RobotSystem::fire(std::size_t index) {
    Robot& r = robots_[index];
    const Vec3 tip = muzzle(index);
    const Vec3 target = player_.state().feet + Vec3(0, core_.settings.player_height * 0.5f, 0);
    Vec3 dir = target - tip;
    const float len = glm::length(dir);
    dir = len > 1e-5f ? dir / len : Vec3(-std::sin(r.yaw), 0, -std::cos(r.yaw));
    // The reference: with probability 1 - p the shot fires no ray at all (still drawn as a muzzle flash).
    const DifficultyScale scale = difficulty_scale(core_.settings.difficulty);
    if (!core_.rng.chance(std::min(1.0f, r.props.hit_probability * scale.accuracy))) {
        core_.push(EventType::RobotShot, tip, r.entity_id, 0.0f, tip + dir);
        return;
    }
    const geometry::Ray ray{tip, dir, core_.settings.robot_shot_range};
    physics::RayHit hit;
    const bool any = core_.shoot_ray(ray, r.body, true, hit);
    core_.push(EventType::RobotShot, tip, r.entity_id, 1.0f, any ? hit.point : tip + dir * ray.max_distance);
    if (!any) return;
    const std::uint64_t user = core_.world.user_data(hit.body);
    if (user_kind(user) == BodyKind::Player) {
        const float damage = r.props.damage * scale.damage;
        core_.push(EventType::Hit, hit.point, -1, damage, hit.normal);
        player_.damage(damage, tip);
    } else if (user_kind(user) == BodyKind::Cylinder) {
        core_.push(EventType::Hit, hit.point, explosives_.cylinders()[user_index(user)].entity_id, 0.0f,
                   hit.normal);
        explosives_.explode(user_index(user));
    } else { // a wall, a door, a prop: sparks where it struck
        core_.push(EventType::Hit, hit.point, -1, 0.0f, hit.normal);
    }
}

} // namespace ks::game
