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
ViewCamera picking_axis_view(ViewMode mode, Vec3 centre = Vec3(0.0f), float extent = 60.0f) {
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
    const ViewCamera top = picking_axis_view(ViewMode::Top);
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
    const ViewCamera front = picking_axis_view(ViewMode::Front); // looks along -z: +z is nearer
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
    const ViewCamera top = picking_axis_view(ViewMode::Top);
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
    const ViewCamera front = picking_axis_view(ViewMode::Front);
    REQUIRE(front.project(Vec3(-30.2f, 7.3f, 4.0f), p));
    const Vec3 in_plane = place_point(editor.doc(), front.ray(p), all_shown, Vec3(0, 0, 4));
    CHECK(in_plane.x == doctest::Approx(-30.0f));
    CHECK(in_plane.y == doctest::Approx(7.3f).epsilon(1e-3));
    CHECK(in_plane.z == doctest::Approx(4.0f));
}

TEST_CASE(
    "palette placement heights: a top light under the ceiling, a sound above the floor, the rest on it") {
    Editor editor;
    editor.grid().step = 1.0f;
    REQUIRE(place(editor, level::EntityType::Floor, Vec3(0, 0, 0)).ok()); // 20 x 20 at y = 0
    const int ceiling = *place(editor, level::EntityType::Floor, Vec3(0, 12, 0));
    REQUIRE(set_field(editor, "ceiling", FieldValue(true)).ok());
    REQUIRE(set_field(editor, "size", FieldValue(Vec2(8, 8))).ok()); // over x, z in -4 .. 4 only
    const Document& doc = editor.doc();
    const Vec3 under(2, 0, 1), open_sky(8, 0, 8);
    using level::EntityType;

    // Under the ceiling the fixture sits on its underside; elsewhere a default wall's height up.
    REQUIRE(overhead_height(doc, under));
    CHECK(*overhead_height(doc, under) == doctest::Approx(12.0f));
    CHECK_FALSE(overhead_height(doc, open_sky));
    CHECK(placement_for(doc, EntityType::TopLight, under) == Vec3(2, 12, 1));
    CHECK(placement_for(doc, EntityType::TopLight, open_sky) == Vec3(8, kTopLightPlaceHeight, 8));
    // A ceiling hidden in the editor (the default) is still where the lamp hangs in the game.
    REQUIRE(set_hidden(editor, ceiling, true).ok());
    CHECK(placement_for(doc, EntityType::TopLight, under) == Vec3(2, 12, 1));
    // A lintel over a doorway is overhead too.
    REQUIRE(place(editor, EntityType::Wall, Vec3(8, 10, 8)).ok());
    CHECK(placement_for(doc, EntityType::TopLight, open_sky).y == doctest::Approx(10.0f));

    CHECK(placement_for(doc, EntityType::Sound, under) == under + Vec3(0, kSoundPlaceHeight, 0));
    for (EntityType type : level::all_types()) // every other type stands on the surface (its bottom centre)
        if (type != EntityType::TopLight && type != EntityType::Sound)
            CHECK_MESSAGE(placement_for(doc, type, under) == under, std::string(level::type_name(type)));
}
