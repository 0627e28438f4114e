// The entity shapes (level/entity_shapes.h): one formula per entity for its boxes, wedges, door leaves,
// cylinder centre, pickup lift and model facing, which the game, the editor and the renderer all read.
#include "level/entity_shapes.h"

#include <doctest/doctest.h>
#include <glm/gtc/matrix_transform.hpp>

using namespace ks;
using namespace ks::level;

namespace {

void check_vec(const Vec3& a, const Vec3& b, float eps = 1e-5f) {
    CHECK(a.x == doctest::Approx(b.x).epsilon(eps));
    CHECK(a.y == doctest::Approx(b.y).epsilon(eps));
    CHECK(a.z == doctest::Approx(b.z).epsilon(eps));
}

Entity make(EntityType type, Vec3 position, Vec3 rotation = Vec3(0.0f)) {
    Entity e;
    e.id = 1;
    e.props = default_props(type);
    e.position = position;
    e.rotation = rotation;
    return e;
}

} // namespace

TEST_CASE("walls, floors, ceilings and stairs stand on their position") {
    Entity wall = make(EntityType::Wall, Vec3(1, 2, 3));
    wall.as<WallProps>().size = Vec3(10, 16, 0.5f);
    const auto w = static_solid_shape(wall);
    REQUIRE(w);
    CHECK(w->kind == ShapeKind::Box);
    check_vec(w->centre(), Vec3(1, 10, 3));
    check_vec(w->half, Vec3(5, 8, 0.25f));

    Entity floor = make(EntityType::Floor, Vec3(0, 4, 0));
    floor.as<FloorProps>().thickness = 1.0f;
    const auto f = static_solid_shape(floor);
    REQUIRE(f);
    CHECK(f->centre().y == doctest::Approx(3.5f)); // the walking surface is the top
    floor.as<FloorProps>().ceiling = true;
    CHECK(static_solid_shape(floor)->centre().y == doctest::Approx(4.5f)); // a ceiling's underside

    Entity stair = make(EntityType::Stair, Vec3(0.0f), Vec3(90, 0, 0));
    const auto s = static_solid_shape(stair);
    REQUIRE(s);
    CHECK(s->kind == ShapeKind::Wedge);
    CHECK(bounding_shape(stair).kind == ShapeKind::Box); // the editor boxes the whole wedge
    check_vec(bounding_shape(stair).centre(), s->centre());
}

TEST_CASE("a yawed wall's box turns with it; pitch and roll turn walls but not lamp stands") {
    Entity wall = make(EntityType::Wall, Vec3(0.0f), Vec3(90, 0, 0));
    wall.as<WallProps>().size = Vec3(10, 16, 0.5f);
    const auto w = static_solid_shape(wall);
    // Local +x (the wall's width) points along world -z after a 90° yaw.
    check_vec(w->rotation() * Vec3(1, 0, 0), Vec3(0, 0, -1));

    Entity lamp = make(EntityType::FloorLight, Vec3(2, 0, 2), Vec3(30, 20, 10));
    const auto stand = static_solid_shape(lamp);
    REQUIRE(stand);
    CHECK(stand->kind == ShapeKind::Cylinder);
    check_vec(stand->rotation() * Vec3(0, 1, 0), Vec3(0, 1, 0)); // upright whatever the entity's rotation
    CHECK(stand->half.x == doctest::Approx(kLampStandRadius));
}

TEST_CASE("things without a static body get none, and the editor still boxes them") {
    for (EntityType t : {EntityType::Door, EntityType::TopLight, EntityType::Robot, EntityType::Pickup}) {
        const Entity e = make(t, Vec3(0, 5, 0));
        CHECK_FALSE(static_solid_shape(e));
        const PlacedShape box = bounding_shape(e);
        CHECK(box.half.x > 0.0f);
        CHECK(box.half.y > 0.0f);
        CHECK(box.half.z > 0.0f);
    }
    const Entity robot = make(EntityType::Robot, Vec3(0.0f));
    CHECK(bounding_shape(robot).half.x == doctest::Approx(kRobotRadius));
    CHECK(bounding_shape(robot).centre().y == doctest::Approx(kRobotHeight / 2));
    const Entity pickup = make(EntityType::Pickup, Vec3(0.0f));
    check_vec(bounding_shape(pickup).centre(), pickup_centre(Vec3(0.0f)));
    const Entity top = make(EntityType::TopLight, Vec3(0, 10, 0));
    CHECK(bounding_shape(top).centre().y < 10.0f); // hangs below its fixture
}

TEST_CASE("door leaves slide outward by open_offset and stay inside the doorway when closed") {
    DoorProps d;
    d.width = 6.0f;
    d.height = 5.0f;
    d.open_offset = 2.0f;
    check_vec(door_leaf_centre(d, 0, 0.0f), Vec3(-1.5f, 2.5f, 0));
    check_vec(door_leaf_centre(d, 1, 0.0f), Vec3(1.5f, 2.5f, 0));
    check_vec(door_leaf_centre(d, 0, 1.0f), Vec3(-3.5f, 2.5f, 0));
    check_vec(door_leaf_centre(d, 1, 0.5f), Vec3(2.5f, 2.5f, 0));
    check_vec(door_leaf_half(d), Vec3(1.5f, 2.5f, kDoorLeafHalfThickness));
    CHECK(door_leaf_slide(d, 0.25f) == doctest::Approx(0.5f));
    // Closed leaves meet in the middle and fill the doorway.
    CHECK(door_leaf_centre(d, 1, 0.0f).x - door_leaf_half(d).x == doctest::Approx(0.0f));
    CHECK(door_leaf_centre(d, 1, 0.0f).x + door_leaf_half(d).x == doctest::Approx(d.width / 2));
}

TEST_CASE("the drawn door leaf moves exactly as far as the physics leaf") {
    Entity door = make(EntityType::Door, Vec3(3, 0, -2), Vec3(90, 0, 0));
    DoorProps& d = door.as<DoorProps>();
    d.width = 7.0f;
    d.open_offset = 2.5f;
    const Mat4 model = door_model_matrix(door);
    const geometry::Transform frame = upright_frame(door);
    for (float open : {0.0f, 0.3f, 1.0f}) {
        // The model's +x leaf origin moved by the shift in model units, then placed by the model matrix...
        const Vec3 drawn_shift = Vec3(model * Vec4(door_model_leaf_shift(d, open), 0, 0, 0));
        // ...matches the physics leaf's movement in the world.
        const Vec3 physics_shift =
            frame.to_world(door_leaf_centre(d, 1, open)) - frame.to_world(door_leaf_centre(d, 1, 0.0f));
        check_vec(drawn_shift, physics_shift, 1e-4f);
    }
}

TEST_CASE("the robot model turns a quarter more than the entity so it faces the entity's forward") {
    for (float yaw : {0.0f, 0.7f, -2.0f, 3.1f}) {
        const Mat4 m = robot_model_matrix(Vec3(1, 2, 3), yaw);
        const Vec3 model_forward = glm::normalize(Vec3(m * Vec4(1, 0, 0, 0))); // the model faces +x
        check_vec(model_forward, Vec3(-std::sin(yaw), 0, -std::cos(yaw)), 1e-4f);
        check_vec(Vec3(m[3]), Vec3(1, 2, 3));
    }
}

TEST_CASE("cylinder and pickup models sit where the bodies are") {
    GasCylinderProps g;
    g.radius = 1.0f;
    g.height = 3.0f;
    const Vec3 centre = gas_cylinder_centre(Vec3(4, 1, 0), g);
    check_vec(centre, Vec3(4, 2.5f, 0));
    const Mat4 m = gas_cylinder_model_matrix(centre, 0.0f, g);
    check_vec(Vec3(m * Vec4(0, 0, 0, 1)), Vec3(4, 1, 0));    // model origin at the bottom
    check_vec(Vec3(m * Vec4(0, 2, 0, 1)), Vec3(4, 4, 0));    // model height 2 reaches the top
    check_vec(Vec3(m * Vec4(0.5f, 0, 0, 1)), Vec3(5, 1, 0)); // model radius 0.5 reaches the radius

    const Vec3 pc = pickup_centre(Vec3(0, 2, 0));
    CHECK(pc.y == doctest::Approx(2.0f + kPickupCentreHeight));
    const Mat4 p = pickup_model_matrix(pc, Quat(1, 0, 0, 0));
    CHECK(p[3].y == doctest::Approx(2.0f + kPickupModelLift));
}

TEST_CASE("ceilings: a floor or a brush with the ceiling flag, nothing else") {
    Level lv;
    lv.add(EntityType::Floor);
    lv.add(EntityType::Brush);
    lv.add(EntityType::Wall);
    for (const Entity& e : lv.entities) CHECK_FALSE(is_ceiling(e));
    lv.entities[0].as<FloorProps>().ceiling = true;
    lv.entities[1].as<BrushProps>().ceiling = true;
    CHECK(is_ceiling(lv.entities[0]));
    CHECK(is_ceiling(lv.entities[1]));
    CHECK_FALSE(is_ceiling(lv.entities[2]));
}
