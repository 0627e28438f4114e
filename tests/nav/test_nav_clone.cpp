// NavMesh::clone: a copy answers every query as the original (the same paths, corner for corner, the same
// islands and door states), and opening or closing a door in one leaves the other as it was.
#include "nav/nav_levels.h"

#include <doctest/doctest.h>

using namespace ks;
using namespace ks::test;

TEST_CASE("a navigation mesh's copy gives the original's paths, and its doors are its own") {
    level::Level lv;
    lv.name = "two rooms and a platform";
    add_floor(lv, Vec3(0), Vec2(40, 40));
    add_wall_with_gap(lv, Vec3(-20, 0, 0), Vec3(20, 0, 0), 5.0f, 5.0f);
    const int door = add_door(lv, Vec3(7.5f, 0, 0), 5.0f, false).id;
    add_cylinder(lv, Vec3(-6, 0, 8), 1.0f);
    add_wall(lv, Vec3(-12, 0, -6), Vec3(-12, 0, -16));
    auto built = nav::NavMesh::build(lv, robot_settings());
    REQUIRE_MESSAGE(built.ok(), (built.ok() ? "" : built.error().str()));
    auto& original = **built;
    REQUIRE(original.set_door_open(door, true));
    auto copied = original.clone();
    REQUIRE_MESSAGE(copied.ok(), (copied.ok() ? "" : copied.error().str()));
    auto& copy = **copied;
    CHECK(copy.door_open(door));
    CHECK(copy.stats().polygons == original.stats().polygons);
    CHECK(copy.triangles().size() == original.triangles().size());

    const Vec3 points[] = {Vec3(-15, 0, 15), Vec3(15, 0, 12), Vec3(0, 0, 3),  Vec3(-16, 0, -12),
                           Vec3(16, 0, -17), Vec3(-6, 0, 12), Vec3(7, 0, -2), Vec3(0, 0, -10)};
    auto same_answers = [&](nav::NavMesh& a, nav::NavMesh& b) {
        std::vector<Vec3> path_a, path_b;
        for (const Vec3& from : points)
            for (const Vec3& to : points) {
                CAPTURE(from.x);
                CAPTURE(to.x);
                CHECK(a.find_path(from, to, path_a) == b.find_path(from, to, path_b));
                CHECK(path_a == path_b);
                CHECK(a.island(from, Vec3(2, 4, 2)) == b.island(from, Vec3(2, 4, 2)));
                CHECK(a.walkable_line(from, to) == b.walkable_line(from, to));
            }
    };
    same_answers(original, copy);

    // A door closed in the copy blocks the copy's paths only.
    REQUIRE(copy.set_door_open(door, false));
    CHECK(original.door_open(door));
    CHECK_FALSE(copy.reachable(Vec3(0, 0, 8), Vec3(0, 0, -8)));
    CHECK(original.reachable(Vec3(0, 0, 8), Vec3(0, 0, -8)));
    REQUIRE(original.set_door_open(door, false));
    same_answers(original, copy);
}
