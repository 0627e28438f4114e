// One fixed step, the one list of the systems' order (which the state hashes depend on): input, player,
// robots, doors, fuses, physics, what the physics reported, the bodies read back, falls, E, then the level
// logic (which reads what all of that did) and the spawners.
#include "game/game.h"

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

} // namespace

void Game::step(const Input& raw) {
    core_.events.clear();
    logic_.clear_records();
    const Input input = sanitised(raw);
    if (input.pause && core_.playing()) {
        core_.paused = !core_.paused;
        core_.push(EventType::Paused, player_.state().feet, -1, core_.paused ? 1.0f : 0.0f);
    }
    if (core_.paused) return;
    const float dt = static_cast<float>(core_.settings.step);
    ++core_.steps;
    core_.phase_time += dt;

    player_.update(input, dt);
    robots_.update(dt);
    interactables_.update_doors(dt, robots_.navigation());
    explosives_.update(dt);
    core_.world.step(dt);
    handle_physics_events();

    player_.read_back(dt);
    robots_.read_back(dt);
    if (core_.playing() && player_.state().feet.y < core_.settings.fall_limit) player_.damage(1e9f);
    if (core_.playing()) interactables_.update_interaction(input);
    if (!core_.playing()) return; // won or lost: nothing more happens
    logic_.step(dt);
    spawners_.update(logic_);
    logic_.check_won();
}

void Game::handle_physics_events() {
    using Kind = physics::TriggerEvent::Kind;
    const physics::World& world = core_.world;
    for (const physics::TriggerEvent& t : world.trigger_events()) {
        if (!world.valid(t.trigger) || !world.valid(t.other)) continue;
        if (user_kind(world.user_data(t.other)) != BodyKind::Player) continue;
        const std::uint64_t user = world.user_data(t.trigger);
        switch (user_kind(user)) {
        case BodyKind::DoorSensor:
            interactables_.player_in_doorway(user_index(user), t.kind != Kind::Exit);
            break;
        case BodyKind::Pickup:
            if (t.kind != Kind::Exit) interactables_.take_pickup(user_index(user));
            break;
        default:
            break;
        }
    }
    // A character touching a gas cylinder sets it off (the reference's onCollision).
    for (const physics::Collision& c : world.collisions()) {
        if (!world.valid(c.self) || !world.valid(c.other)) continue;
        const std::uint64_t user = world.user_data(c.self);
        const BodyKind other = user_kind(world.user_data(c.other));
        if (user_kind(user) == BodyKind::Cylinder && (other == BodyKind::Player || other == BodyKind::Robot))
            explosives_.touched(user_index(user));
        if (user_kind(user) == BodyKind::Robot && std::abs(c.normal.y) < 0.5f)
            robots_.bumped(user_index(user));
    }
}

} // namespace ks::game
