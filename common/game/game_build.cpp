// Game construction: level entities become physics bodies and game entities.
#include "game/game.h"

#include "core/log.h"
#include "core/paths.h"
#include "game/robot_rig.h"

#include <algorithm>
#include <cmath>

namespace ks::game {
namespace {

using geometry::Transform;
using physics::BodyDesc;
using physics::Motion;
using physics::Shape;
namespace layer = physics::layer;

Shape physics_shape(const level::PlacedShape& shape) {
    switch (shape.kind) {
    case level::ShapeKind::Wedge:
        return Shape::wedge(shape.half);
    case level::ShapeKind::Cylinder:
        return Shape::cylinder(shape.half.x, shape.half.y);
    case level::ShapeKind::Box:
        break;
    }
    return Shape::box(shape.half);
}

Light make_light(const level::Entity& e) {
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
    return l;
}

std::string entity_label(const level::Entity& e) {
    return std::string(level::type_name(e.type())) + " " + std::to_string(e.id) +
           (e.name.empty() ? std::string() : " (\"" + e.name + "\")");
}

} // namespace

Vec3 PlayerState::view_direction() const {
    const float c = std::cos(pitch);
    return {-std::sin(yaw) * c, std::sin(pitch), -std::cos(yaw) * c};
}

Game::Game(GameOptions options)
    : settings_(options.settings), animations_(std::move(options.animations)), rng_(options.seed),
      world_(physics::WorldSettings{options.settings.step, 240}),
      navigation_source_(std::move(options.navigation)) {}

Result<std::unique_ptr<Game>> Game::create(const level::Level& level, GameOptions options) {
    if (!(options.settings.step > 0.0 && options.settings.step <= 0.1))
        return Error("game step must be in (0, 0.1] s", Location("GameSettings", 0, 0, "step"),
                     "use 1/120 (the default)");
    if (!options.animations) {
        // Loaded once per process: every game shares the immutable clips and rig.
        static const auto shared = load_robot_animations();
        if (!shared) return shared.error();
        options.animations = *shared;
    }
    std::unique_ptr<Game> game(new Game(std::move(options)));
    if (auto built = game->build(level); !built) return built.error();
    return game;
}

Result<void> Game::find_clips() {
    const anim::ClipSet& clips = animations_->clips;
    auto need = [&](const char* name, int& out) -> Result<void> {
        out = clips.find(name);
        if (out < 0)
            return Error(std::string("robot animations lack the clip \"") + name + "\"",
                         Location("assets/animations/robot.json"),
                         "the game needs idle, alert, shoot_pose, shooting, shoot_pose_reverse and death");
        return ok();
    };
    for (auto [name, slot] : {std::pair{"idle", &clips_.idle},
                              {"alert", &clips_.alert},
                              {"shoot_pose", &clips_.shoot_pose},
                              {"shooting", &clips_.shooting},
                              {"shoot_pose_reverse", &clips_.shoot_pose_reverse},
                              {"death", &clips_.death}})
        if (auto r = need(name, *slot); !r) return r;
    const auto& shooting_events = clips.clips[static_cast<std::size_t>(clips_.shooting)].events;
    shot_on_event_ = std::any_of(shooting_events.begin(), shooting_events.end(),
                                 [](const anim::ClipEvent& e) { return e.name == kMuzzleFlashEvent; });
    if (!shot_on_event_) // the robots still shoot, but the animator should know why the timing is off
        log::warn(paths::asset("animations/robot.json").string(),
                  ": the \"shooting\" clip has no \"muzzle_flash\" event, so robots fire as the clip starts; "
                  "add one where the shot should leave the hand, e.g. \"events\": [{\"time\": 0, \"name\": "
                  "\"muzzle_flash\", \"sound\": \"robot_shot\"}] (the editor's dojo panel adds events on its "
                  "timeline)");
    alert_length_ = static_cast<float>(clips.clips[clips_.alert].duration);
    aim_length_ = static_cast<float>(clips.clips[clips_.shoot_pose].duration);
    death_length_ = static_cast<float>(clips.clips[clips_.death].duration);
    hand_tip_node_ = animations_->rig.find("hand_r_tip");
    if (hand_tip_node_ < 0) hand_tip_node_ = animations_->rig.find("hand_r");
    if (hand_tip_node_ < 0)
        return Error("the robot rig has no hand_r_tip node", Location("assets/animations/robot.json"),
                     "robot shots start at the right hand's tip");
    return ok();
}

Result<void> Game::build(const level::Level& level) {
    if (auto found = find_clips(); !found) return found;
    // Room for the level's robots and a wave of each spawner's: bodies refer to robots by index, so growth
    // is safe, but the first wave then allocates nothing.
    std::size_t robot_count = 0;
    for (const auto& e : level.entities) {
        if (auto* r = e.try_as<level::RobotProps>(); r && !r->dummy) ++robot_count;
        if (auto* s = e.try_as<level::SpawnerProps>())
            robot_count += static_cast<std::size_t>(std::clamp(s->count, 0, 100));
    }
    robots_.reserve(robot_count);
    robot_anims_.reserve(robot_count);
    gravity_ = level.settings.gravity;
    for (const level::Entity& e : level.entities) {
        if (!is_finite(e.position) || !is_finite(e.rotation))
            return Error("non-finite position or rotation", Location("level", 0, 0, entity_label(e)),
                         "give the entity finite coordinates");
        if (auto added = add_entity(e); !added) return added;
    }
    if (auto added = add_player(level); !added) return added;
    build_navigation(level);
    build_logic(level);
    events_.reserve(64);
    world_.build_static();
    return ok();
}

Result<physics::BodyId> Game::add_body(const BodyDesc& desc, const level::Entity& e) {
    return world_.add(desc, entity_label(e));
}

// Walls, floors, stairs, lamp stands, cylinders and the panel: one static body each, shaped by the level's
// entity shapes; lights, cylinders and panels also get their game records.
Result<void> Game::add_entity(const level::Entity& e) {
    switch (e.type()) {
    case level::EntityType::Door:
        return add_door(e);
    case level::EntityType::Robot:
        return add_robot(e);
    case level::EntityType::Pickup:
        return add_pickup(e);
    default:
        break;
    }
    BodyKind kind = BodyKind::Scenery;
    std::uint32_t index = 0;
    std::uint32_t layers = layer::kDefault;
    if (e.type() == level::EntityType::FloorLight || e.type() == level::EntityType::TopLight)
        lights_.push_back(make_light(e));
    if (e.type() == level::EntityType::GasCylinder) {
        // Solid and shootable; it does not block sight (robots see and shoot past it).
        kind = BodyKind::Cylinder;
        index = static_cast<std::uint32_t>(cylinders_.size());
        layers = layer::kSolid | layer::kShootable;
    } else if (e.type() == level::EntityType::ControlPanel) {
        kind = BodyKind::Panel;
        index = static_cast<std::uint32_t>(panels_.size());
    }
    const auto shape = level::static_solid_shape(e);
    if (!shape) return ok();
    BodyDesc d;
    d.shape = physics_shape(*shape);
    d.transform = {shape->centre(), shape->rotation()};
    d.layers = layers;
    d.user_data = pack_user(kind, index);
    auto body = add_body(d, e);
    if (!body) return body.error();
    level_bounds_.grow(d.shape.bounds(d.transform));
    const float yaw = radians(e.rotation.x);
    if (kind == BodyKind::Cylinder) {
        Cylinder c;
        c.entity_id = e.id;
        c.props = e.as<level::GasCylinderProps>();
        c.centre = shape->centre();
        c.yaw = yaw;
        c.body = *body;
        cylinders_.push_back(c);
    } else if (kind == BodyKind::Panel) {
        Panel k;
        k.entity_id = e.id;
        k.size = e.as<level::ControlPanelProps>().size;
        k.centre = shape->centre();
        k.yaw = yaw;
        k.body = *body;
        panels_.push_back(k);
    }
    return ok();
}

Result<void> Game::add_door(const level::Entity& e) {
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
        leaf.motion = Motion::Kinematic;
        leaf.layers = layer::kDefault;
        leaf.user_data = pack_user(BodyKind::DoorLeaf, index);
        leaf.transform = d.leaf_transform(side);
        auto id = add_body(leaf, e);
        if (!id) return id.error();
        d.leaves[side] = *id;
    }
    BodyDesc sensor;
    sensor.shape = Shape::box(level::door_sensor_half(d.props));
    sensor.transform = {d.frame.to_world(level::door_sensor_centre(d.props)), d.frame.rotation};
    sensor.trigger = true;
    sensor.layers = layer::kTrigger;
    sensor.user_data = pack_user(BodyKind::DoorSensor, index);
    auto id = add_body(sensor, e);
    if (!id) return id.error();
    d.sensor = *id;
    doors_.push_back(d);
    return ok();
}

Result<void> Game::add_robot(const level::Entity& e) {
    const auto& rp = e.as<level::RobotProps>();
    if (rp.dummy) return ok(); // the dojo's animation dummy: no AI, not in physics
    const float yaw = radians(e.rotation.x);
    Robot r;
    r.entity_id = e.id;
    r.props = rp;
    r.feet = e.position;
    r.yaw = yaw;
    r.health = rp.health;
    r.wander_from = r.wander_to = yaw;
    r.wander_length = 0.0f; // first idle step draws a new wander
    r.dormant = rp.dormant;
    BodyDesc d;
    d.shape = Shape::capsule(settings_.robot_radius, settings_.robot_height * 0.5f - settings_.robot_radius);
    d.transform = {e.position + Vec3(0, settings_.robot_height * 0.5f + d.character.skin, 0),
                   Quat(1, 0, 0, 0)};
    d.motion = Motion::Character;
    d.layers = layer::kSolid | layer::kShootable | layer::kCharacter;
    d.user_data = pack_user(BodyKind::Robot, static_cast<std::uint32_t>(robots_.size()));
    d.movement.gravity = gravity_;
    d.movement.max_speed = 200.0f;
    auto id = add_body(d, e);
    if (!id) return id.error();
    r.body = *id;
    robots_.push_back(r);
    robot_anims_.emplace_back(animations_->clips, animations_->rig);
    robot_anims_.back().play(clips_.idle, 0.0f);
    return ok();
}

Result<void> Game::add_pickup(const level::Entity& e) {
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
    auto id = add_body(d, e);
    if (!id) return id.error();
    k.trigger = *id;
    pickups_.push_back(k);
    return ok();
}

Result<void> Game::add_player(const level::Level& level) {
    BodyDesc pd;
    pd.shape =
        Shape::capsule(settings_.player_radius, settings_.player_height * 0.5f - settings_.player_radius);
    pd.transform = {level.player_start.position +
                        Vec3(0, settings_.player_height * 0.5f + pd.character.skin, 0),
                    Quat(1, 0, 0, 0)};
    pd.motion = Motion::Character;
    pd.layers = layer::kSolid | layer::kShootable | layer::kCharacter;
    pd.user_data = pack_user(BodyKind::Player, 0);
    pd.movement.gravity = gravity_;
    pd.movement.max_speed = 200.0f;
    auto pid = world_.add(pd, "player");
    if (!pid) return pid.error();
    player_.body = *pid;
    player_.feet = level.player_start.position;
    player_start_ = level.player_start.position;
    player_.yaw = radians(level.player_start.yaw);
    player_.health = settings_.start_health;
    player_.shield = settings_.start_shield;
    player_.ammo = settings_.start_ammo;
    player_.recoil = 10.0f;
    return ok();
}

} // namespace ks::game
