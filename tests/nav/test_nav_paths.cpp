// Paths on small levels built in code: around a wall through a doorway, through doors as they open and
// close (no rebuild), up stairs onto a platform, past gas cylinders.
#include "nav/nav_levels.h"

#include <doctest/doctest.h>

using namespace ks;
using namespace ks::test;

namespace {

// A 30 x 30 room split along z = 0 by a wall with a 5-wide opening at x in [5, 10].
level::Level split_room() {
    level::Level lv;
    lv.name = "split room";
    add_floor(lv, Vec3(0), Vec2(30, 30));
    add_wall_with_gap(lv, Vec3(-15, 0, 0), Vec3(15, 0, 0), 5.0f, 5.0f);
    return lv;
}

float polyline_length(const std::vector<Vec3>& path) {
    float length = 0.0f;
    for (size_t i = 1; i < path.size(); ++i) length += glm::length(path[i] - path[i - 1]);
    return length;
}

} // namespace

TEST_CASE("a path detours around a wall through the doorway") {
    const auto mesh = build_robot_mesh(split_room());
    std::vector<Vec3> path;
    REQUIRE(mesh->find_path(Vec3(0, 0, 8), Vec3(0, 0, -8), path) == nav::PathStatus::Found);
    const auto x = crossing_x(path, 0.0f);
    REQUIRE(x.has_value());
    // It crosses the wall's line inside the opening, at least a robot radius from either jamb.
    CHECK(*x >= 5.0f + level::kRobotRadius - 0.05f);
    CHECK(*x <= 10.0f - level::kRobotRadius + 0.05f);
    CHECK(polyline_length(path) > 16.0f + 1.0f);
    CHECK(path.back().z == doctest::Approx(-8.0f).epsilon(0.01));
    CHECK_FALSE(mesh->walkable_line(Vec3(0, 0, 8), Vec3(0, 0, -8)));
    CHECK(mesh->walkable_line(Vec3(0, 0, 8), Vec3(4, 0, 4)));
    const auto length = mesh->path_length(Vec3(0, 0, 8), Vec3(0, 0, -8));
    REQUIRE(length.has_value());
    CHECK(*length == doctest::Approx(polyline_length(path)));
}

TEST_CASE("a closed door blocks the path and opening it lets the path through without a rebuild") {
    level::Level lv = split_room();
    const int door = add_door(lv, Vec3(7.5f, 0, 0), 5.0f, false).id;
    auto mesh = build_robot_mesh(lv);
    CHECK(mesh->stats().door_polygons > 0);
    CHECK_FALSE(mesh->door_open(door));
    const Vec3 a(0, 0, 8), b(0, 0, -8);
    std::vector<Vec3> path;
    CHECK(mesh->find_path(a, b, path) == nav::PathStatus::Partial);
    CHECK(path.back().z > 0.0f); // it stops on the near side
    CHECK_FALSE(mesh->reachable(a, b));
    CHECK_FALSE(mesh->path_length(a, b).has_value());

    REQUIRE(mesh->set_door_open(door, true));
    CHECK(mesh->door_open(door));
    REQUIRE(mesh->find_path(a, b, path) == nav::PathStatus::Found);
    const auto x = crossing_x(path, 0.0f);
    REQUIRE(x.has_value());
    CHECK(*x > 5.0f);
    CHECK(*x < 10.0f);

    REQUIRE(mesh->set_door_open(door, false));
    CHECK_FALSE(mesh->reachable(a, b));
    CHECK_FALSE(mesh->set_door_open(door + 100, true)); // no such door
}

TEST_CASE("a door that starts open in the level starts open in the mesh") {
    level::Level lv = split_room();
    const int door = add_door(lv, Vec3(7.5f, 0, 0), 5.0f, true).id;
    auto mesh = build_robot_mesh(lv);
    CHECK(mesh->door_open(door));
    CHECK(mesh->reachable(Vec3(0, 0, 8), Vec3(0, 0, -8)));
}

namespace {

// Ground 40 x 40 and a platform 6 up (z in [-20, -8]); with_stair adds the stair rising to it from z = 4.
level::Level platform_level(bool with_stair) {
    level::Level lv;
    lv.name = "platform";
    add_floor(lv, Vec3(0), Vec2(40, 40));
    add_floor(lv, Vec3(0, 6, -14), Vec2(12, 12));
    if (with_stair) lv.add(level::EntityType::Stair, Vec3(0, 0, -2), "stair"); // 12 x 6 x 12, rises toward -z
    return lv;
}

} // namespace

TEST_CASE("stairs lead onto a platform and the path climbs them") {
    auto mesh = build_robot_mesh(platform_level(true));
    const Vec3 on_platform(0, 6, -16);
    std::vector<Vec3> path;
    REQUIRE(mesh->find_path(Vec3(10, 0, 12), on_platform, path) == nav::PathStatus::Found);
    CHECK(path.back().y == doctest::Approx(6.0f).epsilon(0.05));
    // It goes up the stair (x within its 12 width, between its foot at z = 4 and its top at z = -8).
    bool on_stair = false;
    for (size_t i = 1; i < path.size(); ++i) {
        const Vec3 mid = (path[i - 1] + path[i]) * 0.5f;
        if (std::abs(mid.x) < 6.0f && mid.z < 4.0f && mid.z > -8.0f && mid.y > 0.5f && mid.y < 5.5f)
            on_stair = true;
    }
    CHECK(on_stair);

    auto without = build_robot_mesh(platform_level(false));
    CHECK_FALSE(without->reachable(Vec3(10, 0, 12), on_platform));
}

TEST_CASE("floors at two heights are separate layers joined only by the stair") {
    auto mesh = build_robot_mesh(platform_level(true));
    const auto low = mesh->nearest_point(Vec3(0, 0.5f, -14), Vec3(1, 1, 1));
    const auto high = mesh->nearest_point(Vec3(0, 6.5f, -14), Vec3(1, 1, 1));
    REQUIRE(low.has_value());
    REQUIRE(high.has_value());
    CHECK(low->y == doctest::Approx(0.0f).epsilon(0.05));
    CHECK(high->y == doctest::Approx(6.0f).epsilon(0.05));
    // From under the platform to the spot right above: round the stair's 6-high back, up from its foot.
    std::vector<Vec3> path;
    REQUIRE(mesh->find_path(*low, *high, path) == nav::PathStatus::Found);
    CHECK(polyline_length(path) > 30.0f);
    bool past_foot = false;
    for (const Vec3& p : path) past_foot = past_foot || p.z > 2.0f;
    CHECK(past_foot);
    CHECK_FALSE(mesh->walkable_line(*low, *high));
}

TEST_CASE("gas cylinders in a corridor are walked around") {
    level::Level lv;
    lv.name = "cylinder corridor";
    add_floor(lv, Vec3(0), Vec2(40, 8));
    add_wall(lv, Vec3(-20, 0, -3), Vec3(20, 0, -3));
    add_wall(lv, Vec3(-20, 0, 3), Vec3(20, 0, 3));
    const Vec3 cylinders[] = {{-6, 0, 0}, {0, 0, 0.5f}, {6, 0, -0.5f}};
    for (const Vec3& c : cylinders) add_cylinder(lv, c, 0.5f);
    auto mesh = build_robot_mesh(lv);
    std::vector<Vec3> path;
    REQUIRE(mesh->find_path(Vec3(-15, 0, 0), Vec3(15, 0, 0), path) == nav::PathStatus::Found);
    for (const Vec3& c : cylinders) {
        CAPTURE(c.x);
        // Clearance: the cylinder's radius plus the robot's, less a cell for the voxel rounding.
        CHECK(closest_approach(path, c) >= 0.5f + level::kRobotRadius - robot_settings().cell_size);
    }
    CHECK(path.size() > 2);
}

TEST_CASE("islands: points are on the same island exactly when a path joins them, doors as they are now") {
    level::Level lv = split_room();
    const int door = add_door(lv, Vec3(7.5f, 0, 0), 5.0f, false).id;
    add_floor(lv, Vec3(60, 0, 0), Vec2(10, 10)); // apart from the room
    auto mesh = build_robot_mesh(lv);
    const Vec3 extents(1, 1, 1), near(0, 0, 8), far(0, 0, -8), apart(60, 0, 0);
    const int near_island = mesh->island(near, extents);
    CHECK(near_island != 0);
    CHECK(mesh->island(Vec3(-10, 0, 10), extents) == near_island);
    CHECK(mesh->island(far, extents) != near_island); // the door is closed
    CHECK(mesh->island(apart, extents) != 0);
    CHECK(mesh->island(apart, extents) != near_island);
    CHECK(mesh->island(apart, extents) != mesh->island(far, extents));
    CHECK(mesh->island(Vec3(200, 0, 0), extents) == 0); // no mesh there
    REQUIRE(mesh->set_door_open(door, true));
    CHECK(mesh->island(far, extents) == mesh->island(near, extents));
    CHECK(mesh->reachable(near, far));
    CHECK(mesh->island(apart, extents) != mesh->island(near, extents));
    CHECK_FALSE(mesh->reachable(near, apart));
}
