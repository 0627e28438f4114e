// Doors, gas cylinders, E interaction and the caption (a locked door's says "Locked").
#include "game/game.h"

#include <algorithm>
#include <cmath>

namespace ks::game {

void Game::update_doors(float dt) {
    for (Door& d : doors_) {
        const float target = d.opening ? 1.0f : 0.0f;
        if (d.progress == target) continue;
        const float rate = dt / d.props.open_time; // linear, as the reference's tween
        const float previous = d.progress;
        d.progress = d.opening ? std::min(1.0f, d.progress + rate) : std::max(0.0f, d.progress - rate);
        update_door_navigation(d, previous);
        for (int side = 0; side < 2; ++side) world_.set_transform(d.leaves[side], d.leaf_transform(side));
    }
}

void Game::update_cylinders(float dt) {
    // Fuses burn in index order; an explosion lights its neighbours' fuses, so chains go off one fuse apart.
    for (std::size_t i = 0; i < cylinders_.size(); ++i) {
        Cylinder& c = cylinders_[i];
        if (c.exploded || c.fuse < 0.0f) continue;
        c.fuse -= dt;
        if (c.fuse <= 0.0f) explode_cylinder(i);
    }
}

// Radial damage with linear falloff from the blast centre to the blast radius, measured to the nearest
// point of the target's body; walls and doors (sight blockers) shelter what is behind them. Everything
// with health takes it: the player (shield first), robots, and other cylinders, whose fuses it lights.
void Game::explode_cylinder(std::size_t index) {
    Cylinder& c = cylinders_[index];
    if (c.exploded) return;
    c.exploded = true;
    c.fuse = -1.0f;
    world_.set_enabled(c.body, false);
    const float radius = c.props.blast_radius;
    push(EventType::Explosion, c.centre, c.entity_id, radius);
    hear_sound(c.centre);
    if (!(radius > 0.0f)) return;
    physics::RayFilter filter;
    filter.layers = physics::layer::kBlocksSight;
    auto sheltered = [&](const Vec3& target, float distance) {
        const Vec3 d = target - c.centre;
        return distance > 1e-4f && world_.ray_any({c.centre, d / distance, distance}, filter);
    };
    auto falloff = [&](float surface_distance) {
        return std::clamp(1.0f - surface_distance / radius, 0.0f, 1.0f);
    };
    auto push_dir = [&](const Vec3& target) {
        Vec3 d(target.x - c.centre.x, 0, target.z - c.centre.z);
        const float len = glm::length(d);
        return len > 1e-4f ? d / len : Vec3(1, 0, 0);
    };

    if (phase_ == Phase::Playing) {
        const Vec3 centre = player_.feet + Vec3(0, settings_.player_height * 0.5f, 0);
        const float dist = glm::length(centre - c.centre);
        const float f = falloff(std::max(0.0f, dist - settings_.player_radius));
        if (f > 0.0f && !sheltered(centre, dist)) {
            const Vec3 dir = push_dir(centre);
            player_.knockback = dir * c.props.explosion_power * f;
            world_.character(player_.body).movement.velocity.y += 0.4f * c.props.explosion_power * f;
            damage_player(c.props.damage * f, c.centre);
        }
    }
    for (std::size_t i = 0; i < robots_.size(); ++i) {
        Robot& r = robots_[i];
        if (!r.alive()) continue;
        const Vec3 centre = r.feet + Vec3(0, settings_.robot_height * 0.5f, 0);
        const float dist = glm::length(centre - c.centre);
        const float f = falloff(std::max(0.0f, dist - settings_.robot_radius));
        if (f <= 0.0f || sheltered(centre, dist)) continue;
        r.knockback = push_dir(centre) * c.props.explosion_power * f;
        damage_robot(i, c.props.damage * f, false);
    }
    for (Cylinder& other : cylinders_) {
        if (other.exploded || other.fuse >= 0.0f) continue;
        const float dist = glm::length(other.centre - c.centre);
        const float f = falloff(std::max(0.0f, dist - other.props.radius));
        if (f > 0.0f && !sheltered(other.centre, dist)) other.fuse = settings_.cylinder_fuse;
    }
}

void Game::update_interaction(const Input& input) {
    // The nearest interactive object in reach and in view: doors when the player is inside their sensor,
    // floor lights and the panel within reach of the eye. "In view" is judged on the horizontal view
    // direction, so looking at the floor in front of a door still counts.
    const Vec3 eye = player_.eye();
    const Vec3 view(-std::sin(player_.yaw), 0, -std::cos(player_.yaw));
    auto in_view = [&](const Vec3& point, float distance) {
        Vec3 d(point.x - eye.x, 0, point.z - eye.z);
        const float len = glm::length(d);
        return len < 1.0f || glm::dot(d / len, view) >= settings_.interact_view_cos || distance < 1.5f;
    };
    int best = -1;
    float best_distance = 1e30f;
    const char* text = "";
    auto consider = [&](int id, const Vec3& point, float distance, const char* caption) {
        if (distance < best_distance && in_view(point, distance)) {
            best = id;
            best_distance = distance;
            text = caption;
        }
    };
    for (const Door& d : doors_) {
        if (!d.player_inside) continue;
        const Vec3 centre = d.frame.to_world({0, d.props.height * 0.5f, 0});
        consider(d.entity_id, centre, glm::length(centre - eye),
                 d.locked    ? "Locked"
                 : d.opening ? "Press E to close the door"
                             : "Press E to open the door");
    }
    for (const Light& l : lights_) {
        if (!l.floor) continue;
        const Vec3 lamp = l.position + Vec3(0, 2.0f, 0);
        const float dist = std::max(0.0f, glm::length(Vec3(lamp.x - eye.x, 0, lamp.z - eye.z)) - 0.5f);
        if (dist <= settings_.interact_reach)
            consider(l.entity_id, lamp, dist, "Press E to toggle the light");
    }
    for (const Panel& k : panels_) {
        // Distance from the eye to the console's box.
        const geometry::Transform xf{k.centre, glm::angleAxis(k.yaw, Vec3(0, 1, 0))};
        const Vec3 local = xf.to_local(eye);
        const Vec3 closest = glm::clamp(local, -k.size * 0.5f, k.size * 0.5f);
        const float dist = glm::length(local - closest);
        if (dist <= settings_.interact_reach)
            consider(k.entity_id, k.centre, dist, "Press E to shutdown the simulation");
    }
    // The owner rule: the previous target hides its caption when it stops being the target; the new one
    // shows its own (taking ownership).
    if (interact_target_ != best && interact_target_ >= 0 && caption_.hide(interact_target_))
        push(EventType::CaptionChanged, eye, interact_target_);
    interact_target_ = best;
    if (best >= 0 && caption_.show(text, best)) push(EventType::CaptionChanged, eye, best);
    if (input.interact && best >= 0) interact(best);
}

void Game::set_door_opening(Door& d, bool opening) {
    if (d.opening == opening) return;
    d.opening = opening;
    push(EventType::DoorToggled, d.frame.position, d.entity_id, opening ? 1.0f : 0.0f);
}

// What E does. The control panel does what its links say (the level logic's on_use): in a level from
// before the logic existed, complete the shutdown objective, which wins.
void Game::interact(int entity_id) {
    for (Door& d : doors_) {
        if (d.entity_id != entity_id) continue;
        if (d.locked) {
            push(EventType::LockedDoorUsed, d.frame.position, d.entity_id);
            return;
        }
        set_door_opening(d, !d.opening);
        push(EventType::Used, d.frame.position, d.entity_id);
        caption_.show(d.opening ? "Press E to close the door" : "Press E to open the door", d.entity_id);
        push(EventType::CaptionChanged, d.frame.position, d.entity_id);
        return;
    }
    for (Light& l : lights_) {
        if (l.entity_id != entity_id || !l.floor) continue;
        l.on = !l.on;
        push(EventType::LightToggled, l.position, l.entity_id, l.on ? 1.0f : 0.0f);
        push(EventType::Used, l.position, l.entity_id);
        return;
    }
    for (const Panel& k : panels_) {
        if (k.entity_id != entity_id) continue;
        push(EventType::Used, k.centre, k.entity_id);
        return;
    }
}

} // namespace ks::game
