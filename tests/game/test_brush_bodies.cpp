// Brush entities in the game: each is a static Hull body made from its world brush (physics::brush_body),
// so the player walks up a brush ramp onto a brush platform, a robot chases up it over the navigation mesh,
// and a brush wall (turned by its entity's yaw) stops the player.
#include "brush/brush_build.h"
#include "game_test_levels.h"
#include "level/entity_shapes.h"

using namespace ks;
using namespace ks::game;
using namespace ks::game_test;

namespace {

level::Entity& add_brush(level::Level& lv, Vec3 position, float yaw, const brush::Brush& b) {
    level::Entity& e = lv.add(level::EntityType::Brush, position, "brush");
    e.rotation.x = yaw;
    e.as<level::BrushProps>().brush = b;
    return e;
}

// 12 wide and 12 long, rising from y = 0 at local z = 6 to y = 6 at local z = -6 (the shipped stair's size).
brush::Brush ramp() {
    std::vector<brush::Face> faces;
    for (const auto& [n, d] : std::vector<std::pair<DVec3, double>>{
             {{-1, 0, 0}, 6}, {{1, 0, 0}, 6}, {{0, -1, 0}, 0}, {{0, 0, -1}, 6}})
        faces.push_back({{n, d}, {"concrete"}});
    const DVec3 slope = glm::normalize(DVec3(0, 2, 1));
    faces.push_back({{slope, 3.0 * slope.y}, {"tiles"}}); // 2y + z = 6
    return brush::Brush::from_faces(faces).value();
}

} // namespace

TEST_CASE("a brush ramp is climbed onto a brush platform by the player and by a chasing robot") {
    auto lv = flat_level();
    add_brush(lv, Vec3(0, 0, -10), 0.0f, ramp()); // foot at z = -4, top at z = -16
    add_brush(lv, Vec3(0, 0, -22), 0.0f, brush::make_box({-6, 0, -6}, {6, 6, 6}, {"concrete"}).value());
    check_climb_to_platform(lv);
}

TEST_CASE("a brush wall turned by its entity's yaw stops the player") {
    auto lv = flat_level();
    // Thin along local x, long along local z: yaw 90 lays it across the player's way at z = -10.
    add_brush(lv, Vec3(0, 0, -10), 90.0f,
              brush::make_box({-0.25, 0, -10}, {0.25, 8, 10}, {"concrete"}).value());
    auto g = make_game(lv);
    run_for(*g, 2.0, Input{1.0f});
    CHECK(g->player().feet.z > -9.75f); // the wall's face at z = -9.75, the body's radius in front of it
    CHECK(g->player().feet.z < -8.0f);  // it walked up to the wall
    CHECK(g->player().feet.y == doctest::Approx(0.0f).epsilon(0.01));
}

TEST_CASE("a brush's body is the hull of its world brush, where the level places it") {
    auto lv = flat_level();
    level::Entity& e = add_brush(lv, Vec3(20, 0, -20), 45.0f, level::default_brush());
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
