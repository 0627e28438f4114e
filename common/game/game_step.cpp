// One fixed step: input, player, robots, doors, fuses, physics, what the physics reported, E, then the level
// logic (which reads what all of that did).
#include "game/game.h"

#include "anim/easing.h"

#include <algorithm>
#include <cmath>

namespace ks::game {
namespace {

float finite_or_zero(float v, float limit) {
    return std::isfinite(v) ? std::clamp(v, -limit, limit) : 0.0f;
}

Input sanitised(const Input& in) {
    Input out = in;
    out.move_forward = finite_or_zero(in.move_forward, 1.0f);
    out.move_right = finite_or_zero(in.move_right, 1.0f);
    out.look_yaw = finite_or_zero(in.look_yaw, kPi);
    out.look_pitch = finite_or_zero(in.look_pitch, kPi);
    return out;
}

float approach_zero(float v, float by) {
    return v > by ? v - by : 0.0f;
}

} // namespace

void Game::push(EventType type, Vec3 position, int entity, float amount, Vec3 end) {
    events_.push_back({type, position, end, entity, amount, {}});
}

void Game::push_cue(EventType type, Vec3 position, int entity, std::string_view cue) {
    events_.push_back({type, position, Vec3(0.0f), entity, 0.0f, cue});
}

void Game::set_phase(Phase phase) {
    if (phase_ == phase) return;
    phase_ = phase;
    phase_time_ = 0.0;
    if (phase == Phase::Dead) push(EventType::PlayerDied, player_.feet);
    if (phase == Phase::Won) push(EventType::Won, player_.feet);
}

void Game::step(const Input& raw) {
    events_.clear();
    const Input input = sanitised(raw);
    if (input.pause && phase_ == Phase::Playing) {
        paused_ = !paused_;
        push(EventType::Paused, player_.feet, -1, paused_ ? 1.0f : 0.0f);
    }
    if (paused_) return;
    const float dt = static_cast<float>(settings_.step);
    ++steps_;
    phase_time_ += dt;

    update_player(input, dt);
    for (std::size_t i = 0; i < robots_.size(); ++i) {
        if (robots_[i].dormant) hold_dormant(i, dt); // hurt, it wakes and acts at once
        if (!robots_[i].dormant) update_robot(i, dt);
    }
    update_doors(dt);
    update_cylinders(dt);
    world_.step(dt);
    handle_physics_events();

    // Read back the characters' new positions.
    const auto& pc = world_.character(player_.body);
    const Vec3 old_velocity = player_.velocity;
    const bool was_grounded = player_.grounded;
    player_.feet = world_.transform(player_.body).position - Vec3(0, settings_.player_height * 0.5f, 0);
    player_.velocity = pc.movement.velocity;
    player_.grounded = pc.grounded;
    if (phase_ == Phase::Playing) player_feet_events(was_grounded, old_velocity, pc.ground_normal, dt);
    for (std::size_t i = 0; i < robots_.size(); ++i) {
        Robot& r = robots_[i];
        if (r.mode == RobotMode::Dead) continue;
        r.feet = world_.transform(r.body).position - Vec3(0, settings_.robot_height * 0.5f, 0);
        robot_anims_[i].advance(dt);
        robot_clip_events(i);
        if (r.feet.y < settings_.fall_limit && r.alive()) damage_robot(i, r.health, false);
    }
    if (phase_ == Phase::Playing && player_.feet.y < settings_.fall_limit) damage_player(1e9f);
    if (phase_ == Phase::Playing) update_interaction(input);
    update_logic(dt);
}

// Footsteps (one per stride of ground walked, so their pace follows the speed; on a slope they are stair
// steps), and a landing after a real fall. Sound only: nothing here changes the simulation.
void Game::player_feet_events(bool was_grounded, const Vec3& old_velocity, const Vec3& ground_normal,
                              float dt) {
    PlayerState& p = player_;
    if (!p.grounded) {
        p.air_time += dt;
        return;
    }
    if (!was_grounded && p.air_time >= settings_.land_min_air_time &&
        -old_velocity.y >= settings_.land_min_speed) {
        push(EventType::Land, p.feet, -1, -old_velocity.y);
        p.stride = 0.0f;
    }
    p.air_time = 0.0f;
    const float speed = std::hypot(p.velocity.x, p.velocity.z);
    p.stride += speed * dt;
    if (p.stride >= settings_.footstep_stride) {
        p.stride -= settings_.footstep_stride;
        const bool slope = ground_normal.y < 0.98f;
        push(EventType::Footstep, p.feet, -1, slope ? 1.0f : 0.0f);
    }
}

void Game::update_player(const Input& input, float dt) {
    PlayerState& p = player_;
    p.damage_flash = approach_zero(p.damage_flash, dt);
    p.hit_marker = approach_zero(p.hit_marker, dt);
    p.recoil += dt;
    p.knockback *= std::exp(-settings_.knockback_decay * dt);
    auto& mv = world_.character(p.body).movement;
    if (phase_ != Phase::Playing) { // dead or won: the body stops, the camera animation runs
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
    const Vec3 wish = (forward * axes.y + right * axes.x) * settings_.player_speed;
    mv.velocity.x = wish.x + p.knockback.x;
    mv.velocity.z = wish.z + p.knockback.z;
    if (input.jump && world_.jump(p.body, settings_.jump_speed)) push(EventType::Jump, p.feet);
    if (input.fire) fire_player_shot();
}

bool Game::shoot_ray(const geometry::Ray& ray, physics::BodyId ignore, bool skip_robots,
                     physics::RayHit& hit) {
    physics::RayFilter filter(physics::layer::kShootable, ignore);
    if (skip_robots)
        filter.accept_user_data = [](std::uint64_t user) { return user_kind(user) != BodyKind::Robot; };
    return world_.ray_closest(ray, hit, filter);
}

void Game::fire_player_shot() {
    PlayerState& p = player_;
    if (p.ammo <= 0) {
        push(EventType::DryFire, p.eye());
        return;
    }
    --p.ammo;
    ++p.shots;
    p.recoil = 0.0f;
    const Vec3 dir = p.view_direction();
    const geometry::Ray ray{p.eye(), dir, settings_.shot_range};
    // The tracer starts at the rifle tip (camera-local (0.3, -0.25, -1)); the hit ray is the crosshair's.
    const Vec3 right(std::cos(p.yaw), 0, -std::sin(p.yaw));
    const Vec3 up = glm::cross(right, dir);
    const Vec3 tip = p.eye() + right * 0.3f - up * 0.25f + dir * 1.0f;
    physics::RayHit hit;
    const bool any = shoot_ray(ray, p.body, false, hit);
    const Vec3 end = any ? hit.point : ray.origin + dir * ray.max_distance;
    push(EventType::ShotFired, tip, -1, 0.0f, end);
    hear_sound(p.feet);
    if (!any) return;
    const std::uint64_t user = world_.user_data(hit.body);
    const BodyKind kind = user_kind(user);
    int entity = -1;
    if (kind == BodyKind::Robot) {
        const std::size_t i = user_index(user);
        entity = robots_[i].entity_id;
        if (robots_[i].alive()) {
            damage_robot(i, settings_.player_shot_damage, true);
            p.hit_marker = 0.3f;
            ++p.hits;
        }
    } else if (kind == BodyKind::Cylinder) {
        const std::size_t i = user_index(user);
        entity = cylinders_[i].entity_id;
        explode_cylinder(i);
    }
    push(EventType::Hit, hit.point, entity, 0.0f, hit.normal);
}

void Game::damage_player(float amount) {
    damage_player(amount, player_.eye());
}

void Game::damage_player(float amount, const Vec3& source) {
    if (phase_ != Phase::Playing || !(amount > 0.0f)) return;
    PlayerState& p = player_;
    const float absorbed = std::min(p.shield, amount);
    p.shield -= absorbed;
    const float rest = amount - absorbed;
    p.damage_taken += std::min(amount, 1e6f);
    p.health = std::max(0.0f, p.health - rest);
    p.damage_flash = 0.4f;
    if (absorbed > 0.0f) push(EventType::ShieldHit, p.feet, -1, std::min(absorbed, 1e6f));
    push(EventType::PlayerDamaged, source, -1, std::min(amount, 1e6f), p.eye());
    if (p.health <= 0.0f) set_phase(Phase::Dead);
}

void Game::teleport_player(const Vec3& feet, float yaw, float pitch) {
    world_.set_transform(player_.body,
                         {feet + Vec3(0, settings_.player_height * 0.5f + 0.01f, 0), Quat(1, 0, 0, 0)});
    world_.character(player_.body).movement.velocity = Vec3(0.0f);
    player_.feet = feet;
    player_.yaw = yaw;
    player_.pitch = pitch;
}

void Game::handle_physics_events() {
    using Kind = physics::TriggerEvent::Kind;
    for (const physics::TriggerEvent& t : world_.trigger_events()) {
        if (!world_.valid(t.trigger) || !world_.valid(t.other)) continue;
        if (user_kind(world_.user_data(t.other)) != BodyKind::Player) continue;
        const std::uint64_t user = world_.user_data(t.trigger);
        switch (user_kind(user)) {
        case BodyKind::DoorSensor:
            doors_[user_index(user)].player_inside = t.kind != Kind::Exit;
            break;
        case BodyKind::Pickup:
            if (t.kind != Kind::Exit) take_pickup(pickups_[user_index(user)]);
            break;
        default:
            break;
        }
    }
    // A character touching a gas cylinder sets it off (the reference's onCollision).
    for (const physics::Collision& c : world_.collisions()) {
        if (!world_.valid(c.self) || !world_.valid(c.other)) continue;
        const std::uint64_t user = world_.user_data(c.self);
        const BodyKind other = user_kind(world_.user_data(c.other));
        if (user_kind(user) == BodyKind::Cylinder &&
            (other == BodyKind::Player || other == BodyKind::Robot)) {
            Cylinder& cyl = cylinders_[user_index(user)];
            if (!cyl.exploded && cyl.fuse < 0.0f) cyl.fuse = 0.0f; // explodes at the next step's fuse check
        }
        if (user_kind(user) == BodyKind::Robot && std::abs(c.normal.y) < 0.5f)
            robots_[user_index(user)].collided = true;
    }
}

void Game::take_pickup(Pickup& k) {
    if (k.taken || phase_ != Phase::Playing) return;
    PlayerState& p = player_;
    float added = 0.0f;
    // The reference's condition: only when below the maximum; the setter caps the result.
    switch (k.kind) {
    case PickupKind::Health:
        if (p.health >= settings_.max_health) return;
        added = std::min(k.amount, settings_.max_health - p.health);
        p.health += added;
        break;
    case PickupKind::Shield:
        if (p.shield >= settings_.max_shield) return;
        added = std::min(k.amount, settings_.max_shield - p.shield);
        p.shield += added;
        break;
    case PickupKind::Ammo: {
        if (p.ammo >= settings_.max_ammo) return;
        const int add = std::min(static_cast<int>(k.amount), settings_.max_ammo - p.ammo);
        p.ammo += add;
        added = static_cast<float>(add);
        break;
    }
    }
    k.taken = true;
    world_.set_enabled(k.trigger, false);
    push(EventType::PickupTaken, k.centre, k.entity_id, added);
}

DeathCamera Game::death_camera() const {
    DeathCamera cam;
    if (phase_ != Phase::Dead) return cam;
    const double t = phase_time_;
    const float drop = settings_.eye_height - settings_.player_height * 0.5f; // eye → body centre
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
