// Picking and placing with the viewport's rays, without a window: parallel rays of the axis views pick what
// is under the cursor anywhere in the picture, the nearest entity along the view wins, hidden and locked
// entities are skipped, and a palette click lands on the surface under the cursor, snapped.
#include "editor_test_util.h"
#include "model/edit_entities.h"
#include "model/edit_layers.h"
#include "view/picking.h"

using namespace ks;
using namespace ks::editor;

using editor_test::all_shown;

using editor_test::kViewport;

namespace {
ViewCamera axis_view(ViewMode mode, Vec3 centre = Vec3(0.0f), float extent = 60.0f) {
    ViewCamera v;
    v.set_viewport(kViewport);
    v.set_view(mode, centre, extent);
    return v;
}
} // namespace

TEST_CASE("top view picks with parallel rays anywhere in the picture") {
    Editor editor;
    editor.grid().step = 1.0f;
    const int robot = *place(editor, level::EntityType::Robot, Vec3(-50, 0, 14));
    const int pickup = *place(editor, level::EntityType::Pickup, Vec3(20, 0, -20));
    const ViewCamera top = axis_view(ViewMode::Top);
    Vec2 at_robot, at_pickup;
    REQUIRE(top.project(Vec3(-50, 1, 14), at_robot));
    REQUIRE(top.project(Vec3(20, 0.5f, -20), at_pickup));
    CHECK(at_robot.x < 120.0f); // near the left edge: a perspective ray there would be slanted
    CHECK(pick_entity(editor.doc(), top.ray(at_robot), all_shown).id == robot);
    CHECK(pick_entity(editor.doc(), top.ray(at_pickup), all_shown).id == pickup);
    CHECK(pick_entity(editor.doc(), top.ray(at_robot + Vec2(40, 0)), all_shown).id == 0);
    // Locked and hidden entities are not picked.
    REQUIRE(set_locked(editor, robot, true).ok());
    CHECK(pick_entity(editor.doc(), top.ray(at_robot), all_shown).id == 0);
    REQUIRE(set_locked(editor, robot, false).ok());
    CHECK(pick_entity(editor.doc(), top.ray(at_robot), [&](const level::Entity& e) {
              return e.id != robot;
          }).id == 0);
}

TEST_CASE("front view picks the nearest of entities in line along the view") {
    Editor editor;
    editor.grid().step = 1.0f;
    const int back = *place(editor, level::EntityType::Robot, Vec3(0, 0, -10));
    const int front_robot = *place(editor, level::EntityType::Robot, Vec3(0, 0, 10));
    const ViewCamera front = axis_view(ViewMode::Front); // looks along -z: +z is nearer
    Vec2 p;
    REQUIRE(front.project(Vec3(0, 1, 0), p));
    const PickHit hit = pick_entity(editor.doc(), front.ray(p), all_shown);
    CHECK(hit.id == front_robot);
    REQUIRE(set_hidden(editor, front_robot, true).ok());
    CHECK(pick_entity(editor.doc(), front.ray(p), [&](const level::Entity& e) {
              return !editor.doc().hidden.contains(e.id);
          }).id == back);
}

TEST_CASE("placing lands on the surface under the cursor, snapped; else the ground or the view plane") {
    Editor editor;
    editor.grid().step = 0.5f;
    REQUIRE(place(editor, level::EntityType::Floor, Vec3(0, 2, 0)).ok()); // a floor slab at height 2
    const ViewCamera top = axis_view(ViewMode::Top);
    Vec2 p;
    REQUIRE(top.project(Vec3(1.3f, 2, -2.2f), p));
    const Vec3 on_floor = place_point(editor.doc(), top.ray(p), all_shown, Vec3(0.0f));
    CHECK(on_floor.y == doctest::Approx(2.0f));
    CHECK(on_floor.x == doctest::Approx(1.5f));
    CHECK(on_floor.z == doctest::Approx(-2.0f));
    // Off the slab: the ground plane y = 0.
    REQUIRE(top.project(Vec3(40.2f, 0, 20.1f), p));
    const Vec3 ground = place_point(editor.doc(), top.ray(p), all_shown, Vec3(0.0f));
    CHECK(ground.y == doctest::Approx(0.0f));
    CHECK(ground.x == doctest::Approx(40.0f));
    CHECK(ground.z == doctest::Approx(20.0f));
    // A level ray of the front view that meets nothing: the plane through the fallback point.
    const ViewCamera front = axis_view(ViewMode::Front);
    REQUIRE(front.project(Vec3(-30.2f, 7.3f, 4.0f), p));
    const Vec3 in_plane = place_point(editor.doc(), front.ray(p), all_shown, Vec3(0, 0, 4));
    CHECK(in_plane.x == doctest::Approx(-30.0f));
    CHECK(in_plane.y == doctest::Approx(7.3f).epsilon(1e-3));
    CHECK(in_plane.z == doctest::Approx(4.0f));
}
