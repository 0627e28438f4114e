// Doors, lights, pickups and control panels: built from the level, doors sliding, E interaction and the
// caption (a locked door's says "Locked").
#include "game/interactables.h"

#include "nav/nav_mesh.h"

#include <algorithm>
#include <cmath>

namespace ks::game {

namespace {

using physics::BodyDesc;
using physics::Shape;
namespace layer = physics::layer;

} // namespace

Interactables::Interactables(GameCore& core, PlayerSystem& player) : core_(core), player_(player) {}

Result<void> Interactables::add_door(const level::Entity& e) {
    Door d;
    d.entity_id = e.id;
    d.props = e.as<level::DoorProps>();
    d.frame = level::upright_frame(e);
    d.opening = d.props.open;
    d.progress = d.props.open ? 1.0f : 0.0f;
    d.locked = d.props.locked;
    const auto index = static_cast<std::uint32_t>(doors_.size());
    for (int side = 0; side < 2; ++side) {
        BodyDesc leaf;
        leaf.shape = Shape::box(level::door_leaf_half(d.props));
        leaf.motion = physics::Motion::Kinematic;
        leaf.layers = layer::kDefault;
        leaf.user_data = pack_user(BodyKind::DoorLeaf, index);
        leaf.transform = d.leaf_transform(side);
        auto id = core_.world.add(leaf, entity_label(e));
        if (!id) return id.error();
        d.leaves[side] = *id;
    }
    BodyDesc sensor;
    sensor.shape = Shape::box(level::door_sensor_half(d.props));
    sensor.transform = {d.frame.to_world(level::door_sensor_centre(d.props)), d.frame.rotation};
    sensor.trigger = true;
    sensor.layers = layer::kTrigger;
    sensor.user_data = pack_user(BodyKind::DoorSensor, index);
    auto id = core_.world.add(sensor, entity_label(e));
    if (!id) return id.error();
    d.sensor = *id;
    doors_.push_back(d);
    return ok();
}

Result<void> Interactables::add_pickup(const level::Entity& e) {
    const auto& pp = e.as<level::PickupProps>();
    Pickup k;
    k.entity_id = e.id;
    k.kind = pp.kind.value == "ammo"     ? PickupKind::Ammo
             : pp.kind.value == "shield" ? PickupKind::Shield
                                         : PickupKind::Health;
    k.amount = pp.amount;
    k.centre = level::pickup_centre(e.position);
    BodyDesc d;
    d.shape = Shape::box(Vec3(level::kPickupHalfSize));
    d.transform = {k.centre, Quat(1, 0, 0, 0)};
    d.trigger = true;
    d.layers = layer::kTrigger;
    d.user_data = pack_user(BodyKind::Pickup, static_cast<std::uint32_t>(pickups_.size()));
    auto id = core_.world.add(d, entity_label(e));
    if (!id) return id.error();
    k.trigger = *id;
    pickups_.push_back(k);
    return ok();
}

void Interactables::add_light(const level::Entity& e) {
    Light l;
    l.entity_id = e.id;
    l.position = e.position;
    l.yaw = radians(e.rotation.x);
    if (auto* f = e.try_as<level::FloorLightProps>()) {
        l.floor = true;
        l.props = f->light;
        l.cone_angle = f->cone_angle;
    } else {
        l.props = e.as<level::TopLightProps>().light;
    }
    l.on = l.props.on;
    lights_.push_back(l);
}

void Interactables::update_doors(float dt, nav::NavMesh* navigation) {
    for (Door& d : doors_) {
        const float target = d.opening ? 1.0f : 0.0f;
        if (d.progress == target) continue;
        const float rate = dt / d.props.open_time; // linear, as the reference's tween
        const float previous = d.progress;
        d.progress = d.opening ? std::min(1.0f, d.progress + rate) : std::max(0.0f, d.progress - rate);
        // Passable from the moment the door starts to open until it is shut again.
        const bool was_open = previous > 0.0f, is_open = d.progress > 0.0f;
        if (navigation && was_open != is_open) navigation->set_door_open(d.entity_id, is_open);
        for (int side = 0; side < 2; ++side)
            core_.world.set_transform(d.leaves[side], d.leaf_transform(side));
    }
}

void Interactables::take_pickup(std::size_t index) {
    Pickup& k = pickups_[index];
    if (k.taken || !core_.playing()) return;
    const auto added = player_.take(k.kind, k.amount);
    if (!added) return;
    k.taken = true;
    core_.world.set_enabled(k.trigger, false);
    core_.push(EventType::PickupTaken, k.centre, k.entity_id, *added);
}

void Interactables::set_light(std::size_t light, bool on) {
    Light& l = lights_[light];
    if (l.on == on) return;
    l.on = on;
    core_.push(EventType::LightToggled, l.position, l.entity_id, on ? 1.0f : 0.0f);
}

void Interactables::update_interaction(const Input& input) {
    // The nearest interactive object in reach and in view: doors when the player is inside their sensor,
    // floor lights and the panel within reach of the eye. "In view" is judged on the horizontal view
    // direction, so looking at the floor in front of a door still counts.
    const Vec3 eye = player_.state().eye();
    const Vec3 view(-std::sin(player_.state().yaw), 0, -std::cos(player_.state().yaw));
    auto in_view = [&](const Vec3& point, float distance) {
        Vec3 d(point.x - eye.x, 0, point.z - eye.z);
        const float len = glm::length(d);
        return len < 1.0f || glm::dot(d / len, view) >= core_.settings.interact_view_cos || distance < 1.5f;
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
        if (dist <= core_.settings.interact_reach)
            consider(l.entity_id, lamp, dist, "Press E to toggle the light");
    }
    for (const Panel& k : panels_) {
        // Distance from the eye to the console's box.
        const geometry::Transform xf{k.centre, glm::angleAxis(k.yaw, Vec3(0, 1, 0))};
        const Vec3 local = xf.to_local(eye);
        const Vec3 closest = glm::clamp(local, -k.size * 0.5f, k.size * 0.5f);
        const float dist = glm::length(local - closest);
        if (dist <= core_.settings.interact_reach)
            consider(k.entity_id, k.centre, dist, "Press E to shutdown the simulation");
    }
    // The owner rule: the previous target hides its caption when it stops being the target; the new one
    // shows its own (taking ownership).
    if (interact_target_ != best && interact_target_ >= 0 && caption_.hide(interact_target_))
        core_.push(EventType::CaptionChanged, eye, interact_target_);
    interact_target_ = best;
    if (best >= 0 && caption_.show(text, best)) core_.push(EventType::CaptionChanged, eye, best);
    if (input.interact && best >= 0) interact(best);
}

void Interactables::set_door_opening(std::size_t door, bool opening) {
    Door& d = doors_[door];
    if (d.opening == opening) return;
    d.opening = opening;
    core_.push(EventType::DoorToggled, d.frame.position, d.entity_id, opening ? 1.0f : 0.0f);
}

// What E does. The control panel does what its links say (the level logic's on_use): in a level from
// before the logic existed, complete the shutdown objective, which wins.
void Interactables::interact(int entity_id) {
    for (std::size_t i = 0; i < doors_.size(); ++i) {
        const Door& d = doors_[i];
        if (d.entity_id != entity_id) continue;
        if (d.locked) {
            core_.push(EventType::LockedDoorUsed, d.frame.position, d.entity_id);
            return;
        }
        set_door_opening(i, !d.opening);
        core_.push(EventType::Used, d.frame.position, d.entity_id);
        caption_.show(d.opening ? "Press E to close the door" : "Press E to open the door", d.entity_id);
        core_.push(EventType::CaptionChanged, d.frame.position, d.entity_id);
        return;
    }
    for (Light& l : lights_) {
        if (l.entity_id != entity_id || !l.floor) continue;
        l.on = !l.on;
        core_.push(EventType::LightToggled, l.position, l.entity_id, l.on ? 1.0f : 0.0f);
        core_.push(EventType::Used, l.position, l.entity_id);
        return;
    }
    for (const Panel& k : panels_) {
        if (k.entity_id != entity_id) continue;
        core_.push(EventType::Used, k.centre, k.entity_id);
        return;
    }
}

} // namespace ks::game
