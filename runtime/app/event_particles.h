#pragma once
// Which particle emitters a game event spawns: muzzle flashes (player yellow, robots red), impact sparks
// (scenery: hot orange sparks sprayed out of the surface and falling, with a puff of dust; robots: a
// crackle of blue-white sparks, more and faster; nothing where a robot's shot struck the player, whose
// feedback is the HUD's), and fire plus smoke on explosions. Header-only and GL-free: WorldView spawns what
// this returns, tests/runtime/test_feedback.cpp checks it.
#include "game/game.h"
#include "render/particles.h"

#include <algorithm>
#include <array>

namespace ks::runtime {

// What a Hit event struck.
enum class HitTarget { Scenery, Robot, Cylinder, Player };

inline HitTarget hit_target(const game::Game& game, const game::Event& e) {
    if (e.entity < 0) return e.amount > 0.0f ? HitTarget::Player : HitTarget::Scenery;
    for (const auto& r : game.robots())
        if (r.entity_id == e.entity) return HitTarget::Robot;
    for (const auto& c : game.cylinders())
        if (c.entity_id == e.entity) return HitTarget::Cylinder;
    return HitTarget::Scenery;
}

using EventEmitters = std::array<render::ParticleParams, 2>;

namespace detail {

inline int muzzle_flash(const game::Event& e, EventEmitters& out) {
    render::ParticleParams& p = out[0];
    p.position = e.position;
    p.spawn_radius = Vec3(0.05f);
    p.size = e.type == game::EventType::ShotFired ? 0.18f : 0.3f;
    p.life = 0.08f;
    p.velocity = Vec3(0.6f);
    p.per_frame = 3;
    p.duration = 0.05f;
    p.grow = 2.5f;
    p.max_particles = 24;
    if (e.type == game::EventType::RobotShot) {
        p.color_start = Vec3(1.0f, 0.3f, 0.2f);
        p.color_end = Vec3(1.0f, 0.1f, 0.05f);
    }
    return 1;
}

inline int impact(const game::Event& e, HitTarget target, EventEmitters& out) {
    if (target == HitTarget::Player) return 0;
    const Vec3 normal = is_finite(e.end) && glm::length(e.end) > 0.5f ? glm::normalize(e.end) : Vec3(0, 1, 0);
    render::ParticleParams& sparks = out[0];
    sparks.texture = "spark";
    sparks.position = e.position + normal * 0.05f; // in front of the surface, not half inside it
    sparks.spawn_radius = Vec3(0.04f);
    sparks.drag = 1.5f;
    sparks.duration = 0.03f;
    if (target == HitTarget::Robot) {
        // Electric: a dense, fast crackle of blue-white, short-lived, barely falling.
        sparks.size = 1.1f;
        sparks.life = 0.25f;
        sparks.velocity = Vec3(4.5f, 4.0f, 4.5f);
        sparks.drift = normal * 2.0f;
        sparks.gravity = 4.0f;
        sparks.per_frame = 10;
        sparks.grow = 1.6f;
        sparks.color_start = Vec3(0.35f, 0.65f, 1.0f); // the sprite's white core turns cyan
        sparks.color_end = Vec3(0.15f, 0.3f, 1.0f);
        sparks.max_particles = 48;
        return 1;
    }
    // Scenery (and a cylinder's shell): hot sparks out of the surface, arcing down, and a dust puff.
    sparks.size = 1.0f;
    sparks.life = 0.5f;
    sparks.velocity = Vec3(2.2f, 2.2f, 2.2f);
    sparks.drift = normal * 4.0f;
    sparks.gravity = 14.0f;
    sparks.per_frame = 10;
    sparks.grow = 0.7f; // they shrink as they cool
    sparks.color_start = Vec3(1.0f, 0.9f, 0.6f);
    sparks.color_end = Vec3(1.0f, 0.4f, 0.08f);
    sparks.max_particles = 40;
    render::ParticleParams& dust = out[1];
    dust.texture = "smoke";
    dust.blend = render::ParticleBlend::Alpha;
    dust.position = e.position + normal * 0.15f;
    dust.spawn_radius = Vec3(0.08f);
    dust.size = 0.35f;
    dust.life = 0.7f;
    dust.velocity = Vec3(0.3f, 0.35f, 0.3f);
    dust.drift = normal * 0.9f;
    dust.per_frame = 2;
    dust.duration = 0.03f;
    dust.grow = 2.5f;
    dust.drag = 2.0f;
    dust.color_start = Vec3(0.5f, 0.48f, 0.45f);
    dust.color_end = Vec3(0.35f);
    dust.max_particles = 8;
    return 2;
}

inline int explosion(const game::Event& e, EventEmitters& out) {
    // Robot deaths carry radius 0 (visual only); cylinders their blast radius.
    const float r = e.amount > 0.0f ? std::min(e.amount, 20.0f) : 2.5f;
    render::ParticleParams& fire = out[0];
    fire.position = e.position;
    fire.spawn_radius = Vec3(r * 0.25f);
    fire.size = r * 0.2f;
    fire.life = 0.7f;
    fire.velocity = Vec3(r * 0.6f, r * 0.9f, r * 0.6f);
    fire.per_frame = 6;
    fire.duration = 0.35f;
    fire.max_particles = 256;
    render::ParticleParams& smoke = out[1];
    smoke = fire;
    smoke.texture = "smoke";
    smoke.blend = render::ParticleBlend::Alpha;
    smoke.life = 1.6f;
    smoke.size = r * 0.3f;
    smoke.velocity = Vec3(r * 0.2f, r * 0.5f, r * 0.2f);
    smoke.per_frame = 2;
    smoke.duration = 0.6f;
    smoke.grow = 2.0f;
    smoke.color_start = Vec3(0.3f);
    smoke.color_end = Vec3(0.15f);
    smoke.max_particles = 160;
    return 2;
}

} // namespace detail

// Fills `out` with the emitters `e` spawns and returns how many (0 for events without particles).
// `target` matters only for Hit events (hit_target).
inline int event_particles(const game::Event& e, HitTarget target, EventEmitters& out) {
    out = {};
    switch (e.type) {
    case game::EventType::ShotFired:
    case game::EventType::RobotShot:
        return detail::muzzle_flash(e, out);
    case game::EventType::Hit:
        return detail::impact(e, target, out);
    case game::EventType::Explosion:
        return detail::explosion(e, out);
    default:
        return 0;
    }
}

} // namespace ks::runtime
