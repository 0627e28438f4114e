// Game construction: the systems are built from the level in a fixed order (the physics bodies are made in
// the level's entity order, then the player's), then the navigation mesh, the spawners and the logic.
#include "game/game.h"

#include "game/robot_rig.h"
#include "level/model_entity.h"
#include "physics/brush_shape.h"
#include "physics/triangle_mesh.h"

#include <algorithm>

namespace ks::game {
namespace {

using physics::BodyDesc;
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

// Every static solid's collision shape and placement, through this one function: walls, floors, stairs,
// lamp stands, cylinders and the panel as the level's boxes, wedges and cylinders (their bodies, and so the
// bot's state hashes, are as they always were); a brush as a Hull from its world brush; a model as its
// triangles (a Mesh) or the Hulls of the collision it chose (level::model_collision: one, or several for
// "hulls"; none where its file cannot be read: the level's validation warned, and the game plays on with the
// marker drawn in its place). Empty: no body.
Result<std::vector<physics::BrushBody>> static_bodies(const level::Entity& e) {
    using Bodies = std::vector<physics::BrushBody>;
    if (e.type() == level::EntityType::Model) {
        Result<std::optional<level::CollisionMesh>> mesh = level::model_mesh_collision(e);
        if (mesh && mesh->has_value()) { // "mesh": its triangles (physics/triangle_mesh.h)
            Result<physics::MeshBody> body =
                physics::mesh_body((*mesh)->vertices, (*mesh)->triangles, "model " + std::to_string(e.id));
            if (!body) return Bodies();
            return Bodies{physics::BrushBody{body->shape, body->transform}};
        }
        Result<std::vector<brush::Brush>> collision = level::model_collision(e);
        Bodies bodies;
        if (collision)
            for (const brush::Brush& hull : *collision) bodies.push_back(physics::brush_body(hull));
        return bodies;
    }
    if (e.type() == level::EntityType::Brush) {
        Result<brush::Brush> world = level::world_brush(e);
        if (!world)
            return Error(world.error().message, Location("level", 0, 0, entity_label(e)), world.error().hint);
        return Bodies{physics::brush_body(*world)};
    }
    const auto shape = level::static_solid_shape(e);
    if (!shape) return Bodies();
    return Bodies{physics::BrushBody{physics_shape(*shape), {shape->centre(), shape->rotation()}}};
}

} // namespace

Game::Game(GameOptions options)
    : core_(options.settings, options.seed), player_(core_, robots_, explosives_),
      robots_(core_, player_, explosives_, std::move(options.animations)), interactables_(core_, player_),
      explosives_(core_, player_, robots_), spawners_(core_, player_, robots_),
      logic_(core_, player_, robots_, interactables_, spawners_),
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

Result<void> Game::build(const level::Level& level) {
    if (auto found = robots_.find_clips(); !found) return found;
    // Room for the level's robots and a wave of each spawner's: bodies refer to robots by index, so growth
    // is safe, but the first wave then allocates nothing.
    std::size_t robot_count = 0;
    for (const auto& e : level.entities) {
        if (auto* r = e.try_as<level::RobotProps>(); r && !r->dummy) ++robot_count;
        if (auto* s = e.try_as<level::SpawnerProps>())
            robot_count += static_cast<std::size_t>(std::clamp(s->count, 0, 100));
    }
    robots_.prepare(robot_count, level.settings.gravity);
    for (const level::Entity& e : level.entities) {
        if (!is_finite(e.position) || !is_finite(e.rotation))
            return Error("non-finite position or rotation", Location("level", 0, 0, entity_label(e)),
                         "give the entity finite coordinates");
        if (auto added = add_entity(e); !added) return added;
    }
    if (auto added = player_.add(level, level.settings.gravity); !added) return added;
    robots_.build_navigation(level, std::move(navigation_source_), interactables_.doors());
    spawners_.build(level);
    logic_.build(level);
    spawners_.check_ground(logic_);
    core_.events.reserve(64);
    core_.world.build_static();
    return ok();
}

// Walls, floors, stairs, brushes, lamp stands, cylinders and the panel: one static body each, shaped by the
// level's entity shapes (static_body); lights, cylinders and panels also get their game records.
Result<void> Game::add_entity(const level::Entity& e) {
    switch (e.type()) {
    case level::EntityType::Door:
        return interactables_.add_door(e);
    case level::EntityType::Robot:
        return robots_.add(e);
    case level::EntityType::Pickup:
        return interactables_.add_pickup(e);
    default:
        break;
    }
    BodyKind kind = BodyKind::Scenery;
    std::uint32_t index = 0;
    std::uint32_t layers = layer::kDefault;
    if (e.type() == level::EntityType::FloorLight || e.type() == level::EntityType::TopLight)
        interactables_.add_light(e);
    if (e.type() == level::EntityType::GasCylinder) {
        // Solid and shootable; it does not block sight (robots see and shoot past it).
        kind = BodyKind::Cylinder;
        index = explosives_.next_index();
        layers = layer::kSolid | layer::kShootable;
    } else if (e.type() == level::EntityType::ControlPanel) {
        kind = BodyKind::Panel;
        index = interactables_.next_panel();
    }
    Result<std::vector<physics::BrushBody>> solids = static_bodies(e);
    if (!solids) return solids.error();
    if (solids->empty()) return ok();
    // A cylinder and a panel have one body; a model's several hulls are one body each.
    std::optional<physics::BodyId> body;
    const geometry::Transform first_transform = solids->front().transform;
    for (physics::BrushBody& solid : *solids) {
        BodyDesc d;
        d.shape = std::move(solid.shape);
        d.transform = solid.transform;
        d.layers = layers;
        d.user_data = pack_user(kind, index);
        auto added = core_.world.add(d, entity_label(e));
        if (!added) return added.error();
        if (!body) body = *added;
        level_bounds_.grow(d.shape.bounds(d.transform));
    }
    const float yaw = radians(e.rotation.x);
    if (kind == BodyKind::Cylinder) {
        Cylinder c;
        c.entity_id = e.id;
        c.props = e.as<level::GasCylinderProps>();
        c.centre = first_transform.position;
        c.yaw = yaw;
        c.body = *body;
        explosives_.add(c);
    } else if (kind == BodyKind::Panel) {
        Panel k;
        k.entity_id = e.id;
        k.size = e.as<level::ControlPanelProps>().size;
        k.centre = first_transform.position;
        k.yaw = yaw;
        k.body = *body;
        interactables_.add_panel(k);
    }
    return ok();
}

} // namespace ks::game
