// Moving, nudging, turning and scaling the selection (edit_transforms.h): grid snapping, the pivot, exact
// quarter turns, stability over many turns, size fields per type.
#include "editor_test_util.h"
#include "model/edit_entities.h"
#include "model/edit_selection.h"
#include "model/edit_transforms.h"

#include <cmath>

using namespace ks;
using namespace ks::editor;
using level::EntityType;

TEST_CASE("transforms: snapping, nudge, pivot rotation exact at quarter turns, 15° turns stay stable") {
    Editor ed;
    ed.grid().step = 0.5f;
    int a = *place(ed, EntityType::Robot, {1.26f, 0, 0.74f}, 8.0f);
    CHECK(ed.level().find(a)->position == Vec3(1.5f, 0, 0.5f));
    CHECK(ed.level().find(a)->rotation.x == 15.0f);

    REQUIRE(nudge(ed, 0, 1).ok());
    REQUIRE(nudge(ed, 2, -1).ok());
    CHECK(ed.level().find(a)->position == Vec3(2.0f, 0, 0.0f));
    CHECK_FALSE(nudge(ed, 3, 1).ok());

    // Snapped move: the primary lands on the grid; others keep their offset to it.
    int b = *place(ed, EntityType::Robot, {4.0f, 0, 0.0f});
    REQUIRE(select(ed, {a, b}).ok());
    REQUIRE(move_selection(ed, {0.3f, 0, 0.1f}, true).ok());
    CHECK(ed.level().find(a)->position == Vec3(2.5f, 0, 0.0f));
    CHECK(ed.level().find(b)->position == Vec3(4.5f, 0, 0.0f));

    // Two entities turn about the centre of their positions: exact at 90°.
    REQUIRE(rotate_selection(ed, 90).ok());
    CHECK(ed.level().find(a)->position == Vec3(3.5f, 0, 1.0f));
    CHECK(ed.level().find(b)->position == Vec3(3.5f, 0, -1.0f));
    CHECK(ed.level().find(a)->rotation.x == 105.0f);
    for (int i = 0; i < 3; ++i) REQUIRE(rotate_selection(ed, 90).ok());
    CHECK(ed.level().find(a)->position == Vec3(2.5f, 0, 0.0f));
    CHECK(ed.level().find(a)->rotation.x == 15.0f);

    // Yaw stays in (-180, 180] and 24 turns of 15° come back (positions to float round-off).
    ed.grid().snap = true;
    for (int i = 0; i < 24; ++i) REQUIRE(rotate_selection(ed, 15).ok());
    CHECK(ed.level().find(a)->rotation.x == 15.0f);
    CHECK(ed.level().find(a)->position.x == doctest::Approx(2.5).epsilon(1e-5));
    CHECK(std::abs(ed.level().find(a)->position.z) < 1e-5f);
    CHECK(ed.level().find(b)->position.x == doctest::Approx(4.5).epsilon(1e-5));
    // With snapping on, a 20° request turns 15° (the rotation step).
    REQUIRE(select(ed, {a}).ok());
    REQUIRE(rotate_selection(ed, 20).ok());
    CHECK(ed.level().find(a)->rotation.x == 30.0f);
    REQUIRE(rotate_selection(ed, 170).ok());
    CHECK(ed.level().find(a)->rotation.x == -165.0f);
}

TEST_CASE("scale: changes only size fields, per type; types without sizes are reported") {
    Editor ed;
    int wall = *place(ed, EntityType::Wall, {0, 0, 0});
    int floor = *place(ed, EntityType::Floor, {0, 0, 0});
    int door = *place(ed, EntityType::Door, {0, 0, 0});
    int gas = *place(ed, EntityType::GasCylinder, {0, 0, 0});
    int robot = *place(ed, EntityType::Robot, {0, 0, 0});
    REQUIRE(select(ed, {wall, floor, door, gas, robot}).ok());
    REQUIRE(scale_selection(ed, {2, 0.5f, 3}).ok());
    CHECK(ed.level().find(wall)->as<level::WallProps>().size == Vec3(20, 8, 1.5f));
    CHECK(ed.level().find(floor)->as<level::FloorProps>().size == Vec2(40, 60));
    CHECK(ed.level().find(door)->as<level::DoorProps>().width == 10.0f);
    CHECK(ed.level().find(door)->as<level::DoorProps>().height == 2.5f);
    CHECK(ed.level().find(gas)->as<level::GasCylinderProps>().radius == 1.0f);
    CHECK(ed.level().find(robot)->as<level::RobotProps>() == level::RobotProps{});
    REQUIRE(select(ed, {robot}).ok());
    CHECK_FALSE(scale_selection(ed, {2, 2, 2}).ok());
    REQUIRE(select(ed, {door}).ok());
    CHECK_FALSE(scale_selection(ed, {1000, 1, 1}).ok()); // width beyond its range: nothing changes
    CHECK(ed.level().find(door)->as<level::DoorProps>().width == 10.0f);
}

TEST_CASE(
    "transforms: turning a pair 2400 times by 15° far from the origin does not drift beyond a few ulps") {
    Editor ed;
    ed.grid().snap = false;
    const Vec3 start_a(1000, 0, 1000), start_b(1010, 0, 993);
    int a = *place(ed, EntityType::Robot, start_a);
    int b = *place(ed, EntityType::Robot, start_b);
    REQUIRE(select(ed, {a, b}).ok());
    const float ulp = std::nextafter(1010.0f, 2000.0f) - 1010.0f; // 6.1e-5
    int turned = 0;
    for (int i = 0; i < 2400; ++i) turned += rotate_selection(ed, 15).ok();
    CHECK(turned == 2400);
    CHECK(glm::length(ed.level().find(a)->position - start_a) < 8 * ulp);
    CHECK(glm::length(ed.level().find(b)->position - start_b) < 8 * ulp);
    CHECK(ed.level().find(a)->rotation.x == 0.0f);
}
