// Brush entities in the navigation mesh: their faces are Recast input, walkable where their slope allows
// (a ramp, a platform's top) and never on their undersides; a brush wall blocks like a wall entity.
// Model entities come in through the same convex solids (their collision brush).
#include "../../bench/brush/solid_meshes.h"
#include "brush/brush_build.h"
#include "level_brushes.h"
#include "nav/nav_levels.h"
#include "test_support.h"

#include <doctest/doctest.h>

using namespace ks;
using namespace ks::test;

namespace {

brush::Brush box(DVec3 min, DVec3 max) {
    return brush::make_box(min, max, {"concrete"}).value();
}

// A 40 x 40 ground, a brush platform 6 high over z in [-20, -8], and (optionally) a brush ramp up to it
// from z = 4.
level::Level brush_platform_level(bool with_ramp) {
    level::Level lv;
    lv.name = "brush platform";
    add_floor(lv, Vec3(0), Vec2(40, 40));
    place_brush(lv, Vec3(0, 0, -14), 0.0f, box({-6, 0, -6}, {6, 6, 6}));
    if (with_ramp) place_brush(lv, Vec3(0, 0, -2), 0.0f, stair_ramp());
    return lv;
}

} // namespace

TEST_CASE("a robot's path goes up a brush ramp onto a brush platform") {
    auto mesh = build_robot_mesh(brush_platform_level(true));
    const Vec3 on_platform(0, 6, -16);
    std::vector<Vec3> path;
    REQUIRE(mesh->find_path(Vec3(10, 0, 12), on_platform, path) == nav::PathStatus::Found);
    CHECK(path.back().y == doctest::Approx(6.0f).epsilon(0.05));
    bool on_ramp = false; // between the ramp's foot (z = 4) and top (z = -8), part way up
    for (size_t i = 1; i < path.size(); ++i) {
        const Vec3 mid = (path[i - 1] + path[i]) * 0.5f;
        if (std::abs(mid.x) < 6.0f && mid.z < 4.0f && mid.z > -8.0f && mid.y > 0.5f && mid.y < 5.5f)
            on_ramp = true;
    }
    CHECK(on_ramp);
    // Standing on the ramp half way up: the mesh is on its slope, 3 above the ground.
    const auto half_way = mesh->nearest_point(Vec3(0, 3.5f, -2), Vec3(1, 1, 1));
    REQUIRE(half_way.has_value());
    CHECK(half_way->y == doctest::Approx(3.0f).epsilon(0.1));

    auto without = build_robot_mesh(brush_platform_level(false));
    CHECK_FALSE(without->reachable(Vec3(10, 0, 12), on_platform));
}

TEST_CASE("a brush wall blocks, turned by its entity's yaw, and a gap between two lets the path through") {
    level::Level closed;
    closed.name = "brush wall";
    add_floor(closed, Vec3(0), Vec2(30, 30));
    // Thin along local x, long along local z; yaw 90 lays it along world x, across the room at z = 0.
    place_brush(closed, Vec3(0), 90.0f, box({-0.25, 0, -15}, {0.25, 4, 15}));
    CHECK_FALSE(build_robot_mesh(closed)->reachable(Vec3(0, 0, 8), Vec3(0, 0, -8)));

    level::Level gap;
    gap.name = "brush wall with a gap";
    add_floor(gap, Vec3(0), Vec2(30, 30));
    place_brush(gap, Vec3(-5, 0, 0), 0.0f, box({-10, 0, -0.25}, {10, 4, 0.25}));      // x in [-15, 5]
    place_brush(gap, Vec3(12.5f, 0, 0), 0.0f, box({-2.5, 0, -0.25}, {2.5, 4, 0.25})); // x in [10, 15]
    auto mesh = build_robot_mesh(gap);
    std::vector<Vec3> path;
    REQUIRE(mesh->find_path(Vec3(0, 0, 8), Vec3(0, 0, -8), path) == nav::PathStatus::Found);
    const auto x = crossing_x(path, 0.0f);
    REQUIRE(x.has_value());
    CHECK(*x >= 5.0f + level::kRobotRadius - 0.3f); // brushes are not drawn in: up to a cell narrower
    CHECK(*x <= 10.0f - level::kRobotRadius + 0.3f);
}

TEST_CASE("a brush's underside is never walked on; its top and the floor under it are") {
    level::Level lv;
    lv.name = "brush slab";
    add_floor(lv, Vec3(0), Vec2(30, 30));
    place_brush(lv, Vec3(0, 5, 0), 0.0f, box({-5, 0, -5}, {5, 0.5, 5})); // a slab from y = 5 to 5.5
    auto mesh = build_robot_mesh(lv);
    const auto under = mesh->nearest_point(Vec3(0, 4.9f, 0), Vec3(1, 0.3f, 1));
    CHECK_FALSE(under.has_value()); // nothing walkable at the slab's underside
    const auto top = mesh->nearest_point(Vec3(0, 5.8f, 0), Vec3(1, 0.5f, 1));
    REQUIRE(top.has_value());
    CHECK(top->y == doctest::Approx(5.5f).epsilon(0.05));
    const auto floor = mesh->nearest_point(Vec3(0, 0.5f, 0), Vec3(1, 1, 1));
    REQUIRE(floor.has_value());
    CHECK(floor->y == doctest::Approx(0.0f).epsilon(0.05));
}

TEST_CASE("a model entity's collision is in the mesh: its box, hull and triangles block, none lets the path "
          "through") {
    auto room = [](const char* collision) {
        level::Level lv;
        lv.name = "model wall";
        add_floor(lv, Vec3(0), Vec2(30, 30));
        // The shipped door model (about 11 wide, 0.7 deep) scaled 4: a wall across the room at z = 0.
        auto& model = lv.add(level::EntityType::Model, Vec3(0), "Wall model").as<level::ModelProps>();
        model.file = "door.gltf";
        model.scale = 4.0f;
        model.collision.value = collision;
        return lv;
    };
    CHECK_FALSE(build_robot_mesh(room("box"))->reachable(Vec3(0, 0, 8), Vec3(0, 0, -8)));
    CHECK_FALSE(build_robot_mesh(room("hull"))->reachable(Vec3(0, 0, 8), Vec3(0, 0, -8)));
    CHECK_FALSE(build_robot_mesh(room("mesh"))->reachable(Vec3(0, 0, 8), Vec3(0, 0, -8))); // by its triangles
    CHECK(build_robot_mesh(room("none"))->reachable(Vec3(0, 0, 8), Vec3(0, 0, -8)));
}

TEST_CASE("a model's \"hulls\" collision opens the arch that its single hull fills") {
    test::ScratchDataHome home;
    // bench/brush/solid_meshes.h's arch: 4 wide, 4 tall, 1 deep, the opening 2 wide and 3 tall
    test::write_file(home.models() / "arch.obj", brush::bench::obj_text(brush::bench::arch()));
    auto corridor = [](const char* collision) {
        level::Level lv;
        lv.name = "arch";
        add_floor(lv, Vec3(0), Vec2(12, 30)); // x in [-6, 6]: the arch, scaled 3, spans it
        auto& model = lv.add(level::EntityType::Model, Vec3(-6, 0, -1.5f), "Arch").as<level::ModelProps>();
        model.file = "arch.obj";
        model.scale = 3.0f;
        model.collision.value = collision;
        return lv;
    };
    CHECK_FALSE(build_robot_mesh(corridor("hull"))->reachable(Vec3(0, 0, 8), Vec3(0, 0, -8)));
    CHECK(build_robot_mesh(corridor("hulls"))->reachable(Vec3(0, 0, 8), Vec3(0, 0, -8)));
}
