// The player's part of a step: view and walking before the physics, the rifle's shot, footsteps and landings
// after it; damage, pickups and the death camera.
#include "game/player_system.h"

#include "anim/easing.h"
#include "game/explosives.h"
#include "game/robot_system.h"

#include <algorithm>
#include <cmath>

namespace ks::game {
namespace {

float approach_zero(float v, float by) {
    return v > by ? v - by : 0.0f;
}

} // namespace

Vec3 PlayerState::view_direction() const {
    const float c = std::cos(pitch);
    return {-std::sin(yaw) * c, std::sin(pitch), -std::cos(yaw) * c};
}

PlayerSystem::PlayerSystem(GameCore& core, RobotSystem& robots, Explosives& explosives)
    : core_(core), robots_(robots), explosives_(explosives) {}

Result<void> PlayerSystem::add(const level::Level& level, float gravity) {
    using physics::Shape;
    const GameSettings& settings = core_.settings;
    physics::BodyDesc pd;
    pd.shape = Shape::capsule(settings.player_radius, settings.player_height * 0.5f - settings.player_radius);
    pd.transform = {level.player_start.position +
                        Vec3(0, settings.player_height * 0.5f + pd.character.skin, 0),
                    Quat(1, 0, 0, 0)};
    pd.motion = physics::Motion::Character;
    pd.layers = physics::layer::kSolid | physics::layer::kShootable | physics::layer::kCharacter;
    pd.user_data = pack_user(BodyKind::Player, 0);
    pd.movement.gravity = gravity;
    pd.movement.max_speed = 200.0f;
    auto pid = core_.world.add(pd, "player");
    if (!pid) return pid.error();
    player_.body = *pid;
    player_.feet = level.player_start.position;
    start_ = level.player_start.position;
    player_.yaw = radians(level.player_start.yaw);
    player_.health = settings.start_health;
    player_.shield = settings.start_shield;
    player_.ammo = settings.start_ammo;
    player_.recoil = 10.0f;
    return ok();
}

void PlayerSystem::update(const Input& input, float dt) {
    const GameSettings& settings = core_.settings;
    PlayerState& p = player_;
    p.damage_flash = approach_zero(p.damage_flash, dt);
    p.hit_marker = approach_zero(p.hit_marker, dt);
    p.recoil += dt;
    p.knockback *= std::exp(-settings.knockback_decay * dt);
    auto& mv = core_.world.character(p.body).movement;
    if (!core_.playing()) { // dead or won: the body stops, the camera animation runs
        mv.velocity.x = p.knockback.x;
        mv.velocity.z = p.knockback.z;
        return;
    }
    p.yaw = std::remainder(p.yaw + input.look_yaw, 2.0f * kPi);
    p.pitch = std::clamp(p.pitch + input.look_pitch, -kPi * 0.5f, kPi * 0.5f);
    Vec2 axes(input.move_right, input.move_forward);
    if (glm::dot(axes, axes) > 1.0f) axes = glm::normalize(axes);
    const Vec3 forward(-std::sin(p.yaw), 0, -std::cos(p.yaw));
    const Vec3 right(std::cos(p.yaw), 0, -std::sin(p.yaw));
    const Vec3 wish = (forward * axes.y + right * axes.x) * settings.player_speed;
    mv.velocity.x = wish.x + p.knockback.x;
    mv.velocity.z = wish.z + p.knockback.z;
    if (input.jump && core_.world.jump(p.body, settings.jump_speed)) core_.push(EventType::Jump, p.feet);
    if (input.fire) fire_shot();
}

void PlayerSystem::read_back(float dt) {
    const physics::World& world = core_.world;
    const auto& pc = world.character(player_.body);
    const Vec3 old_velocity = player_.velocity;
    const bool was_grounded = player_.grounded;
    player_.feet = world.transform(player_.body).position - Vec3(0, core_.settings.player_height * 0.5f, 0);
    player_.velocity = pc.movement.velocity;
    player_.grounded = pc.grounded;
    if (core_.playing()) feet_events(was_grounded, old_velocity, pc.ground_normal, dt);
}

// Footsteps (one per stride of ground walked, so their pace follows the speed; on a slope they are stair
// steps), and a landing after a real fall. Sound only: nothing here changes the simulation.
void PlayerSystem::feet_events(bool was_grounded, const Vec3& old_velocity, const Vec3& ground_normal,
                               float dt) {
    const GameSettings& settings = core_.settings;
    PlayerState& p = player_;
    if (!p.grounded) {
        p.air_time += dt;
        return;
    }
    if (!was_grounded && p.air_time >= settings.land_min_air_time &&
        -old_velocity.y >= settings.land_min_speed) {
        core_.push(EventType::Land, p.feet, -1, -old_velocity.y);
        p.stride = 0.0f;
    }
    p.air_time = 0.0f;
    const float speed = std::hypot(p.velocity.x, p.velocity.z);
    p.stride += speed * dt;
    if (p.stride >= settings.footstep_stride) {
        p.stride -= settings.footstep_stride;
        const bool slope = ground_normal.y < 0.98f;
        core_.push(EventType::Footstep, p.feet, -1, slope ? 1.0f : 0.0f);
    }
}

void PlayerSystem::fire_shot() {
    PlayerState& p = player_;
    if (p.ammo <= 0) {
        core_.push(EventType::DryFire, p.eye());
        return;
    }
    --p.ammo;
    ++p.shots;
    p.recoil = 0.0f;
    const Vec3 dir = p.view_direction();
    const geometry::Ray ray{p.eye(), dir, core_.settings.shot_range};
    // The tracer starts at the rifle tip (camera-local (0.3, -0.25, -1)); the hit ray is the crosshair's.
    const Vec3 right(std::cos(p.yaw), 0, -std::sin(p.yaw));
    const Vec3 up = glm::cross(right, dir);
    const Vec3 tip = p.eye() + right * 0.3f - up * 0.25f + dir * 1.0f;
    physics::RayHit hit;
    const bool any = core_.shoot_ray(ray, p.body, false, hit);
    const Vec3 end = any ? hit.point : ray.origin + dir * ray.max_distance;
    core_.push(EventType::ShotFired, tip, -1, 0.0f, end);
    robots_.hear_sound(p.feet);
    if (!any) return;
    const std::uint64_t user = core_.world.user_data(hit.body);
    const BodyKind kind = user_kind(user);
    int entity = -1;
    if (kind == BodyKind::Robot) {
        const std::size_t i = user_index(user);
        const Robot& robot = robots_.robots()[i];
        entity = robot.entity_id;
        if (robot.alive()) {
            robots_.damage(i, core_.settings.player_shot_damage, true);
            p.hit_marker = 0.3f;
            ++p.hits;
        }
    } else if (kind == BodyKind::Cylinder) {
        const std::size_t i = user_index(user);
        entity = explosives_.cylinders()[i].entity_id;
        explosives_.explode(i);
    }
    core_.push(EventType::Hit, hit.point, entity, 0.0f, hit.normal);
}

void PlayerSystem::damage(float amount) {
    damage(amount, player_.eye());
}

void PlayerSystem::damage(float amount, const Vec3& source) {
    if (!core_.playing() || !(amount > 0.0f)) return;
    PlayerState& p = player_;
    const float absorbed = std::min(p.shield, amount);
    p.shield -= absorbed;
    const float rest = amount - absorbed;
    p.damage_taken += std::min(amount, 1e6f);
    p.health = std::max(0.0f, p.health - rest);
    p.damage_flash = 0.4f;
    if (absorbed > 0.0f) core_.push(EventType::ShieldHit, p.feet, -1, std::min(absorbed, 1e6f));
    core_.push(EventType::PlayerDamaged, source, -1, std::min(amount, 1e6f), p.eye());
    if (p.health <= 0.0f) core_.set_phase(Phase::Dead, p.feet);
}

void PlayerSystem::knock(const Vec3& push, float lift) {
    player_.knockback = push;
    core_.world.character(player_.body).movement.velocity.y += lift;
}

std::optional<float> PlayerSystem::take(PickupKind kind, float amount) {
    const GameSettings& settings = core_.settings;
    PlayerState& p = player_;
    // The reference's condition: only when below the maximum; the setter caps the result.
    switch (kind) {
    case PickupKind::Health: {
        if (p.health >= settings.max_health) return std::nullopt;
        const float added = std::min(amount, settings.max_health - p.health);
        p.health += added;
        return added;
    }
    case PickupKind::Shield: {
        if (p.shield >= settings.max_shield) return std::nullopt;
        const float added = std::min(amount, settings.max_shield - p.shield);
        p.shield += added;
        return added;
    }
    case PickupKind::Ammo:
        break;
    }
    if (p.ammo >= settings.max_ammo) return std::nullopt;
    const int add = std::min(static_cast<int>(amount), settings.max_ammo - p.ammo);
    p.ammo += add;
    return static_cast<float>(add);
}

void PlayerSystem::teleport(const Vec3& feet, float yaw, float pitch) {
    core_.world.set_transform(
        player_.body, {feet + Vec3(0, core_.settings.player_height * 0.5f + 0.01f, 0), Quat(1, 0, 0, 0)});
    core_.world.character(player_.body).movement.velocity = Vec3(0.0f);
    player_.feet = feet;
    player_.yaw = yaw;
    player_.pitch = pitch;
}

DeathCamera PlayerSystem::death_camera() const {
    DeathCamera cam;
    if (core_.phase != Phase::Dead) return cam;
    const double t = core_.phase_time;
    const GameSettings& settings = core_.settings;
    const float drop = settings.eye_height - settings.player_height * 0.5f; // eye → body centre
    const double k1 = std::clamp(t / 0.3, 0.0, 1.0);
    cam.eye_drop =
        drop * static_cast<float>(anim::tweenjs_formula(anim::EaseFamily::Quadratic, anim::EaseMode::In, k1));
    const double k2 = std::clamp((t - 0.3) / 0.3, 0.0, 1.0);
    const float b =
        static_cast<float>(anim::tweenjs_formula(anim::EaseFamily::Bounce, anim::EaseMode::InOut, k2));
    cam.pitch = kPi * 0.25f * b;
    cam.roll = -kPi * 0.5f * b;
    cam.menu_ready = t >= 1.6 - 1e-9;
    return cam;
}

} // namespace ks::game
