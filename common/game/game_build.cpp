// Game construction: level entities become physics bodies and game entities.
#include "game/game.h"

#include "game/robot_rig.h"

#include <algorithm>
#include <cmath>

namespace ks::game {
namespace {

using physics::BodyDesc;
using physics::Motion;
using physics::Shape;
using physics::Transform;
namespace layer = physics::layer;

Quat yaw_rotation(float yaw) {
    return glm::angleAxis(yaw, Vec3(0, 1, 0));
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
      world_(physics::WorldSettings{options.settings.step, 240}) {}

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

Result<void> Game::build(const level::Level& level) {
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
    alert_length_ = static_cast<float>(clips.clips[clips_.alert].duration);
    aim_length_ = static_cast<float>(clips.clips[clips_.shoot_pose].duration);
    death_length_ = static_cast<float>(clips.clips[clips_.death].duration);
    hand_tip_node_ = animations_->rig.find("hand_r_tip");
    if (hand_tip_node_ < 0) hand_tip_node_ = animations_->rig.find("hand_r");
    if (hand_tip_node_ < 0)
        return Error("the robot rig has no hand_r_tip node", Location("assets/animations/robot.json"),
                     "robot shots start at the right hand's tip");

    auto add = [&](BodyDesc desc, const level::Entity& e) -> Result<physics::BodyId> {
        auto id = world_.add(desc, entity_label(e));
        if (!id) return id.error();
        return *id;
    };
    auto add_static = [&](const level::Entity& e, Shape shape, Vec3 centre, Quat rotation, BodyKind kind,
                          std::uint32_t index, std::uint32_t layers) -> Result<physics::BodyId> {
        BodyDesc d;
        d.shape = std::move(shape);
        d.transform = {centre, rotation};
        d.layers = layers;
        d.user_data = pack_user(kind, index);
        auto id = add(d, e);
        if (id) level_bounds_.grow(d.shape.bounds(d.transform));
        return id;
    };
    const float gravity = level.settings.gravity;

    // Count first so the arrays never reallocate while bodies refer to indices.
    std::size_t robot_count = 0;
    for (const auto& e : level.entities)
        if (auto* r = e.try_as<level::RobotProps>(); r && !r->dummy) ++robot_count;
    robots_.reserve(robot_count);
    robot_anims_.reserve(robot_count);

    for (const level::Entity& e : level.entities) {
        if (!is_finite(e.position) || !is_finite(e.rotation))
            return Error("non-finite position or rotation", Location("level", 0, 0, entity_label(e)),
                         "give the entity finite coordinates");
        const float yaw = radians(e.rotation.x);
        const Quat rot = e.orientation();
        const Vec3 p = e.position;
        Result<physics::BodyId> body = physics::BodyId{};
        switch (e.type()) {
        case level::EntityType::Wall: {
            const auto& w = e.as<level::WallProps>();
            body = add_static(e, Shape::box(w.size * 0.5f), p + rot * Vec3(0, w.size.y * 0.5f, 0), rot,
                              BodyKind::Scenery, 0, layer::kDefault);
            break;
        }
        case level::EntityType::Floor: {
            const auto& f = e.as<level::FloorProps>();
            const float half_t = f.thickness * 0.5f;
            const Vec3 centre = p + rot * Vec3(0, f.ceiling ? half_t : -half_t, 0);
            body = add_static(e, Shape::box({f.size.x * 0.5f, half_t, f.size.y * 0.5f}), centre, rot,
                              BodyKind::Scenery, 0, layer::kDefault);
            break;
        }
        case level::EntityType::Stair: {
            const auto& s = e.as<level::StairProps>();
            body = add_static(e, Shape::wedge(s.size * 0.5f), p + rot * Vec3(0, s.size.y * 0.5f, 0), rot,
                              BodyKind::Scenery, 0, layer::kDefault);
            break;
        }
        case level::EntityType::Door: {
            Door d;
            d.entity_id = e.id;
            d.props = e.as<level::DoorProps>();
            d.frame = {p, yaw_rotation(yaw)};
            d.opening = d.props.open;
            d.progress = d.props.open ? 1.0f : 0.0f;
            const auto index = static_cast<std::uint32_t>(doors_.size());
            for (int side = 0; side < 2; ++side) {
                BodyDesc leaf;
                leaf.shape = Shape::box({d.props.width * 0.25f, d.props.height * 0.5f, 0.07f});
                leaf.motion = Motion::Kinematic;
                leaf.layers = layer::kDefault;
                leaf.user_data = pack_user(BodyKind::DoorLeaf, index);
                const float sign = side == 0 ? -1.0f : 1.0f;
                leaf.transform = {d.frame.to_world({sign * (d.props.width * 0.25f + d.leaf_offset()),
                                                    d.props.height * 0.5f, 0}),
                                  d.frame.rotation};
                auto id = add(leaf, e);
                if (!id) return id.error();
                d.leaves[side] = *id;
            }
            BodyDesc sensor; // the reference's 5 x 5 x 14 interaction box (z ±7 around the door)
            sensor.shape = Shape::box({d.props.width * 0.5f, d.props.height * 0.5f, 7.0f});
            sensor.transform = {d.frame.to_world({0, d.props.height * 0.5f, 0}), d.frame.rotation};
            sensor.trigger = true;
            sensor.layers = layer::kTrigger;
            sensor.user_data = pack_user(BodyKind::DoorSensor, index);
            auto id = add(sensor, e);
            if (!id) return id.error();
            d.sensor = *id;
            doors_.push_back(d);
            break;
        }
        case level::EntityType::FloorLight:
        case level::EntityType::TopLight: {
            Light l;
            l.entity_id = e.id;
            l.position = p;
            l.yaw = yaw;
            if (auto* f = e.try_as<level::FloorLightProps>()) {
                l.floor = true;
                l.props = f->light;
                l.cone_angle = f->cone_angle;
                // The lamp stand: solid and shootable, as in the reference (a 0.5-radius post).
                body =
                    add_static(e, Shape::cylinder(0.5f, f->height * 0.5f), p + Vec3(0, f->height * 0.5f, 0),
                               Quat(1, 0, 0, 0), BodyKind::Scenery, 0, layer::kDefault);
            } else {
                l.props = e.as<level::TopLightProps>().light;
            }
            l.on = l.props.on;
            lights_.push_back(l);
            break;
        }
        case level::EntityType::Robot: {
            const auto& rp = e.as<level::RobotProps>();
            if (rp.dummy) break; // the dojo's animation dummy: no AI, not in physics
            Robot r;
            r.entity_id = e.id;
            r.props = rp;
            r.feet = p;
            r.yaw = yaw;
            r.health = rp.health;
            r.wander_from = r.wander_to = yaw;
            r.wander_length = 0.0f; // first idle step draws a new wander
            BodyDesc d;
            d.shape = Shape::capsule(settings_.robot_radius,
                                     settings_.robot_height * 0.5f - settings_.robot_radius);
            d.transform = {p + Vec3(0, settings_.robot_height * 0.5f + d.character.skin, 0),
                           Quat(1, 0, 0, 0)};
            d.motion = Motion::Character;
            d.layers = layer::kSolid | layer::kShootable | layer::kCharacter;
            d.user_data = pack_user(BodyKind::Robot, static_cast<std::uint32_t>(robots_.size()));
            d.movement.gravity = gravity;
            d.movement.max_speed = 200.0f;
            auto id = add(d, e);
            if (!id) return id.error();
            r.body = *id;
            robots_.push_back(r);
            robot_anims_.emplace_back(clips, animations_->rig);
            robot_anims_.back().play(clips_.idle, 0.0f);
            break;
        }
        case level::EntityType::Pickup: {
            const auto& pp = e.as<level::PickupProps>();
            Pickup k;
            k.entity_id = e.id;
            k.kind = pp.kind.value == "ammo"     ? PickupKind::Ammo
                     : pp.kind.value == "shield" ? PickupKind::Shield
                                                 : PickupKind::Health;
            k.amount = pp.amount;
            k.centre = p + Vec3(0, 0.8f, 0);
            BodyDesc d;
            d.shape = Shape::box(Vec3(0.4f));
            d.transform = {k.centre, Quat(1, 0, 0, 0)};
            d.trigger = true;
            d.layers = layer::kTrigger;
            d.user_data = pack_user(BodyKind::Pickup, static_cast<std::uint32_t>(pickups_.size()));
            auto id = add(d, e);
            if (!id) return id.error();
            k.trigger = *id;
            pickups_.push_back(k);
            break;
        }
        case level::EntityType::GasCylinder: {
            Cylinder c;
            c.entity_id = e.id;
            c.props = e.as<level::GasCylinderProps>();
            c.centre = p + Vec3(0, c.props.height * 0.5f, 0);
            c.yaw = yaw;
            // Solid and shootable; it does not block sight (robots see and shoot past it).
            auto id =
                add_static(e, Shape::cylinder(c.props.radius, c.props.height * 0.5f), c.centre,
                           Quat(1, 0, 0, 0), BodyKind::Cylinder,
                           static_cast<std::uint32_t>(cylinders_.size()), layer::kSolid | layer::kShootable);
            if (!id) return id.error();
            c.body = *id;
            cylinders_.push_back(c);
            break;
        }
        case level::EntityType::ControlPanel: {
            Panel k;
            k.entity_id = e.id;
            k.size = e.as<level::ControlPanelProps>().size;
            k.centre = p + rot * Vec3(0, k.size.y * 0.5f, 0);
            k.yaw = yaw;
            auto id = add_static(e, Shape::box(k.size * 0.5f), k.centre, rot, BodyKind::Panel,
                                 static_cast<std::uint32_t>(panels_.size()), layer::kDefault);
            if (!id) return id.error();
            k.body = *id;
            panels_.push_back(k);
            break;
        }
        case level::EntityType::Count:
            break;
        }
        if (!body) return body.error();
    }

    BodyDesc pd;
    pd.shape =
        Shape::capsule(settings_.player_radius, settings_.player_height * 0.5f - settings_.player_radius);
    pd.transform = {level.player_start.position +
                        Vec3(0, settings_.player_height * 0.5f + pd.character.skin, 0),
                    Quat(1, 0, 0, 0)};
    pd.motion = Motion::Character;
    pd.layers = layer::kSolid | layer::kShootable | layer::kCharacter;
    pd.user_data = pack_user(BodyKind::Player, 0);
    pd.movement.gravity = gravity;
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
    events_.reserve(64);
    world_.build_static();
    return ok();
}

} // namespace ks::game
