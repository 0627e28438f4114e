// NavMesh::rebuild (the live play-test's moved wall): a mesh made from the running one, building again
// only the tiles whose input the edit changed, answers every query as a fresh build of the edited level, with
// its doors as the level starts them whatever the running mesh's doors were doing; a change of the level's
// bounds builds every tile.
#include "nav/nav_levels.h"
#include "test_support.h"

#include <doctest/doctest.h>

using namespace ks;
using namespace ks::test;

namespace {

void same_answers(nav::NavMesh& a, nav::NavMesh& b) {
    CHECK(a.stats().polygons == b.stats().polygons);
    CHECK(a.stats().door_polygons == b.stats().door_polygons);
    CHECK(a.stats().tiles_with_polygons == b.stats().tiles_with_polygons);
    const auto ta = a.triangles(), tb = b.triangles();
    REQUIRE(ta.size() == tb.size());
    for (size_t i = 0; i < ta.size(); ++i) {
        CHECK(ta[i].a == tb[i].a);
        CHECK(ta[i].c == tb[i].c);
        CHECK(ta[i].flags == tb[i].flags);
        CHECK(ta[i].door_id == tb[i].door_id);
    }
    const Vec3 points[] = {Vec3(-35, 0, 35), Vec3(30, 0, 28), Vec3(0, 0, 3),  Vec3(-30, 0, -25),
                           Vec3(33, 0, -34), Vec3(-6, 0, 12), Vec3(7, 0, -2), Vec3(20, 0, -10)};
    std::vector<Vec3> pa, pb;
    for (const Vec3& from : points)
        for (const Vec3& to : points) {
            CHECK(a.find_path(from, to, pa) == b.find_path(from, to, pb));
            CHECK(pa == pb);
            CHECK(a.island(from, Vec3(2, 4, 2)) == b.island(from, Vec3(2, 4, 2)));
        }
}

} // namespace

TEST_CASE("a rebuilt navigation mesh builds only the tiles an edit touched and answers as a fresh build") {
    level::Level before;
    before.name = "rooms for a live edit";
    add_floor(before, Vec3(0), Vec2(80, 80));
    add_wall_with_gap(before, Vec3(-40, 0, 0), Vec3(40, 0, 0), 5.0f, 5.0f);
    const int door = add_door(before, Vec3(7.5f, 0, 0), 5.0f, false).id;
    const int moving = add_wall(before, Vec3(-30, 0, -10), Vec3(-30, 0, -30)).id;
    add_cylinder(before, Vec3(20, 0, 20), 1.0f);
    auto running = nav::NavMesh::build(before, robot_settings());
    REQUIRE_MESSAGE(running.ok(), (running.ok() ? "" : running.error().str()));
    REQUIRE((*running)->set_door_open(door, true)); // the running game opened it
    const int tiles = (*running)->stats().tile_columns * (*running)->stats().tile_rows;
    REQUIRE(tiles > 4);

    SUBCASE("a moved wall: its tiles are built, the rest copied") {
        level::Level edited = before;
        edited.find(moving)->position.x = -26.0f;
        int built = -1;
        auto rebuilt = nav::NavMesh::rebuild(**running, before, edited, &built);
        REQUIRE_MESSAGE(rebuilt.ok(), (rebuilt.ok() ? "" : rebuilt.error().str()));
        auto fresh = nav::NavMesh::build(edited, robot_settings());
        REQUIRE(fresh.ok());
        CHECK(built > 0);
        CHECK(built < tiles / 2);
        CHECK_FALSE((*rebuilt)->door_open(door)); // as the level starts it
        same_answers(**rebuilt, **fresh);
        REQUIRE((*rebuilt)->set_door_open(door, true));
        REQUIRE((*fresh)->set_door_open(door, true));
        same_answers(**rebuilt, **fresh);
    }
    SUBCASE("nothing changed: every tile is copied") {
        int built = -1;
        auto rebuilt = nav::NavMesh::rebuild(**running, before, before, &built);
        REQUIRE(rebuilt.ok());
        CHECK(built == 0);
        auto fresh = nav::NavMesh::build(before, robot_settings());
        REQUIRE(fresh.ok());
        same_answers(**rebuilt, **fresh);
    }
    SUBCASE("a floor grown past the level's bounds: every tile is built") {
        level::Level edited = before;
        add_floor(edited, Vec3(60, 0, 0), Vec2(40, 20));
        int built = -1;
        auto rebuilt = nav::NavMesh::rebuild(**running, before, edited, &built);
        REQUIRE(rebuilt.ok());
        CHECK(built == (*rebuilt)->stats().tile_columns * (*rebuilt)->stats().tile_rows);
        auto fresh = nav::NavMesh::build(edited, robot_settings());
        REQUIRE(fresh.ok());
        same_answers(**rebuilt, **fresh);
    }
}
