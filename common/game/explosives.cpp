// Gas cylinders: fuses, explosions and their chains.
#include "game/explosives.h"

#include "game/player_system.h"
#include "game/robot_system.h"

#include <algorithm>
#include <cmath>

namespace ks::game {

Explosives::Explosives(GameCore& core, PlayerSystem& player, RobotSystem& robots)
    : core_(core), player_(player), robots_(robots) {}

void Explosives::update(float dt) {
    // Fuses burn in index order; an explosion lights its neighbours' fuses, so chains go off one fuse apart.
    for (std::size_t i = 0; i < cylinders_.size(); ++i) {
        Cylinder& c = cylinders_[i];
        if (c.exploded || c.fuse < 0.0f) continue;
        c.fuse -= dt;
        if (c.fuse <= 0.0f) explode(i);
    }
}

// Radial damage with linear falloff from the blast centre to the blast radius, measured to the nearest
// point of the target's body; walls and doors (sight blockers) shelter what is behind them. Everything
// with health takes it: the player (shield first), robots, and other cylinders, whose fuses it lights.
void Explosives::explode(std::size_t index) {
    Cylinder& c = cylinders_[index];
    if (c.exploded) return;
    c.exploded = true;
    c.fuse = -1.0f;
    core_.world.set_enabled(c.body, false);
    const float radius = c.props.blast_radius;
    core_.push(EventType::Explosion, c.centre, c.entity_id, radius);
    robots_.hear_sound(c.centre);
    if (!(radius > 0.0f)) return;
    physics::RayFilter filter;
    filter.layers = physics::layer::kBlocksSight;
    auto sheltered = [&](const Vec3& target, float distance) {
        const Vec3 d = target - c.centre;
        return distance > 1e-4f && core_.world.ray_any({c.centre, d / distance, distance}, filter);
    };
    auto falloff = [&](float surface_distance) {
        return std::clamp(1.0f - surface_distance / radius, 0.0f, 1.0f);
    };
    auto push_dir = [&](const Vec3& target) {
        Vec3 d(target.x - c.centre.x, 0, target.z - c.centre.z);
        const float len = glm::length(d);
        return len > 1e-4f ? d / len : Vec3(1, 0, 0);
    };

    if (core_.playing()) {
        const Vec3 centre = player_.state().feet + Vec3(0, core_.settings.player_height * 0.5f, 0);
        const float dist = glm::length(centre - c.centre);
        const float f = falloff(std::max(0.0f, dist - core_.settings.player_radius));
        if (f > 0.0f && !sheltered(centre, dist)) {
            const Vec3 dir = push_dir(centre);
            player_.knock(dir * c.props.explosion_power * f, 0.4f * c.props.explosion_power * f);
            player_.damage(c.props.damage * f, c.centre);
        }
    }
    for (std::size_t i = 0; i < robots_.robots().size(); ++i) {
        const Robot& r = robots_.robots()[i];
        if (!r.alive()) continue;
        const Vec3 centre = r.feet + Vec3(0, core_.settings.robot_height * 0.5f, 0);
        const float dist = glm::length(centre - c.centre);
        const float f = falloff(std::max(0.0f, dist - core_.settings.robot_radius));
        if (f <= 0.0f || sheltered(centre, dist)) continue;
        robots_.knock(i, push_dir(centre) * c.props.explosion_power * f);
        robots_.damage(i, c.props.damage * f, false);
    }
    for (Cylinder& other : cylinders_) {
        if (other.exploded || other.fuse >= 0.0f) continue;
        const float dist = glm::length(other.centre - c.centre);
        const float f = falloff(std::max(0.0f, dist - other.props.radius));
        if (f > 0.0f && !sheltered(other.centre, dist)) other.fuse = core_.settings.cylinder_fuse;
    }
}

void Explosives::touched(std::size_t index) {
    Cylinder& c = cylinders_[index];
    if (!c.exploded && c.fuse < 0.0f) c.fuse = 0.0f;
}

} // namespace ks::game
