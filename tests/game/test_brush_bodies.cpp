// Brush entities in the game: each is a static Hull body made from its world brush (physics::brush_body),
// so the player walks up a brush ramp onto a brush platform, a robot chases up it over the navigation mesh,
// and a brush wall (turned by its entity's yaw) stops the player.
#include "../../bench/brush/solid_meshes.h"
#include "brush/brush_build.h"
#include "game_test_levels.h"
#include "level/entity_shapes.h"
#include "level_brushes.h"

using namespace ks;
using namespace ks::game;
using namespace ks::game_test;
using namespace ks::test;

TEST_CASE("a brush ramp is climbed onto a brush platform by the player and by a chasing robot") {
    auto lv = flat_level();
    place_brush(lv, Vec3(0, 0, -10), 0.0f, stair_ramp()); // foot at z = -4, top at z = -16
    place_brush(lv, Vec3(0, 0, -22), 0.0f, brush::make_box({-6, 0, -6}, {6, 6, 6}, {"concrete"}).value());
    check_climb_to_platform(lv);
}

TEST_CASE("a brush wall turned by its entity's yaw stops the player") {
    auto lv = flat_level();
    // Thin along local x, long along local z: yaw 90 lays it across the player's way at z = -10.
    place_brush(lv, Vec3(0, 0, -10), 90.0f,
                brush::make_box({-0.25, 0, -10}, {0.25, 8, 10}, {"concrete"}).value());
    auto g = make_game(lv);
    run_for(*g, 2.0, Input{1.0f});
    CHECK(g->player().feet.z > -9.75f); // the wall's face at z = -9.75, the body's radius in front of it
    CHECK(g->player().feet.z < -8.0f);  // it walked up to the wall
    CHECK(g->player().feet.y == doctest::Approx(0.0f).epsilon(0.01));
}

TEST_CASE("a brush's body is the hull of its world brush, where the level places it") {
    auto lv = flat_level();
    level::Entity& e = place_brush(lv, Vec3(20, 0, -20), 45.0f, level::default_brush());
    auto g = make_game(lv);
    const auto world = level::world_brush(e);
    REQUIRE(world.ok());
    const DVec3 centre = (world->bounds_min() + world->bounds_max()) * 0.5;
    // The ground is body 0, the brush body 1 (bodies follow the level's entity order).
    const physics::BodyId id{1, 1};
    REQUIRE(g->world().valid(id));
    CHECK(glm::length(g->world().transform(id).position - Vec3(centre)) < 1e-5f);
    CHECK(g->line_blocked(Vec3(20, 2, -30), Vec3(20, 2, -10)));
    CHECK_FALSE(g->line_blocked(Vec3(30, 2, -30), Vec3(30, 2, -10)));
}

TEST_CASE("a model with \"hulls\" collision is one body per hull: the player walks through its arch") {
    ScratchDataHome home;
    // bench/brush/solid_meshes.h's arch: 4 wide, 4 tall, 1 deep, the opening 2 wide and 3 tall
    write_file(home.models() / "arch.obj", brush::bench::obj_text(brush::bench::arch()));
    auto walk = [](const char* collision) {
        auto lv = flat_level();
        // Scaled 3: x in [-6, 6], z in [-10, -7], the opening x in [-3, 3] and 9 tall, across the player's
        // way.
        auto& model = lv.add(level::EntityType::Model, Vec3(-6, 0, -10), "Arch").as<level::ModelProps>();
        model.file = "arch.obj";
        model.scale = 3.0f;
        model.collision.value = collision;
        auto g = make_game(lv);
        run_for(*g, 3.0, Input{1.0f});
        return g->player().feet.z;
    };
    CHECK(walk("hull") > -7.0f);   // one hull fills the opening: stopped at its face
    CHECK(walk("hulls") < -11.0f); // two pillars and a lintel: through
}
