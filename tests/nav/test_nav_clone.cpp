// NavMesh::clone: a copy answers every query as the original (the same paths, corner for corner, the same
// islands and door states), and opening or closing a door in one leaves the other as it was.
#include "nav/nav_cache.h"
#include "nav/nav_levels.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <filesystem>

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

// The disk cache (nav/nav_cache.h): a hit gives the built mesh's answers; a changed level misses; a
// truncated, corrupt or foreign entry is ignored and written again; an unwritable folder just means no
// caching.
TEST_CASE("a navigation mesh read from the disk cache answers as the built one, and a bad entry is rebuilt") {
    level::Level lv;
    lv.name = "cached rooms";
    add_floor(lv, Vec3(0), Vec2(30, 30));
    add_wall_with_gap(lv, Vec3(-15, 0, 0), Vec3(15, 0, 0), 5.0f, 5.0f);
    const int door = add_door(lv, Vec3(7.5f, 0, 0), 5.0f, false).id;
    ScratchDir dir;
    const disk_cache::Store store(dir / "cache");
    auto key = nav::nav_cache_key(lv, robot_settings());
    REQUIRE(key.ok());
    const auto entry = store.file("navmesh", *key);

    auto built = nav::build_cached(lv, robot_settings(), store);
    REQUIRE(built.ok());
    REQUIRE(std::filesystem::exists(entry));
    auto cached = nav::build_cached(lv, robot_settings(), store);
    REQUIRE(cached.ok());
    auto& a = **built;
    auto& b = **cached;
    CHECK(b.stats().polygons == a.stats().polygons);
    CHECK(b.stats().door_polygons == a.stats().door_polygons);
    CHECK(b.door_open(door) == a.door_open(door));
    std::vector<Vec3> pa, pb;
    for (const Vec3& from : {Vec3(-12, 0, 12), Vec3(12, 0, -12), Vec3(0, 0, 5)})
        for (const Vec3& to : {Vec3(12, 0, 10), Vec3(-10, 0, -12)}) {
            CHECK(a.find_path(from, to, pa) == b.find_path(from, to, pb));
            CHECK(pa == pb);
        }
    REQUIRE(b.set_door_open(door, true));
    REQUIRE(a.set_door_open(door, true));
    CHECK(a.find_path(Vec3(0, 0, 8), Vec3(0, 0, -8), pa) == b.find_path(Vec3(0, 0, 8), Vec3(0, 0, -8), pb));
    CHECK(pa == pb);

    // Another level (a wall moved) is another key.
    level::Level moved = lv;
    add_wall(moved, Vec3(-10, 0, 8), Vec3(-10, 0, 14));
    auto moved_key = nav::nav_cache_key(moved, robot_settings());
    REQUIRE(moved_key.ok());
    CHECK(*moved_key != *key);
    nav::NavSettings wider = robot_settings();
    wider.agent_radius += 0.1f;
    CHECK(*nav::nav_cache_key(lv, wider) != *key);

    // Truncated, one byte flipped, another program's file: ignored, the mesh built and the entry rewritten.
    const std::string good = read_file(entry);
    std::string flipped = good;
    flipped[flipped.size() / 2] = static_cast<char>(flipped[flipped.size() / 2] ^ 0x40);
    for (const std::string& bad : {good.substr(0, good.size() / 2), good.substr(0, 10), flipped,
                                   std::string("PNG and not a cache at all")}) {
        write_file(entry, bad);
        auto again = nav::build_cached(lv, robot_settings(), store);
        REQUIRE(again.ok());
        CHECK((*again)->stats().polygons == a.stats().polygons);
        CHECK(read_file(entry) == good);
    }

    // A folder that cannot be made (a file stands in its place): built every time, no error.
    write_file(dir / "blocked", "x");
    const disk_cache::Store blocked(dir / "blocked" / "cache");
    auto unwritable = nav::build_cached(lv, robot_settings(), blocked);
    REQUIRE(unwritable.ok());
    CHECK((*unwritable)->stats().polygons == a.stats().polygons);
}
