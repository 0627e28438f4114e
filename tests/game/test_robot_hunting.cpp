// Robots on the navigation mesh: they walk round walls through doorways, climb stairs, wait at closed doors,
// hunt a lost player for their search time, come to a shot they hear, and stand guard on a level without a
// mesh.
#include "game_test_levels.h"
#include "geometry/ground_plane.h"
#include "level/level_io.h"

#include <algorithm>
#include <array>
#include <cmath>

using namespace ks;
using namespace ks::game;
using namespace ks::game_test;

namespace {

// A wall across the whole 200-wide test floor at z = -10, with a 6-wide doorway centred at x = `door_x`.
void add_wall_with_doorway(level::Level& lv, float door_x, float height = 16.0f) {
    const float left_end = -100.0f, right_end = 100.0f, half_gap = 3.0f;
    const float left_width = (door_x - half_gap) - left_end, right_width = right_end - (door_x + half_gap);
    add_wall(lv, Vec3(left_end + left_width / 2, 0, -10), Vec3(left_width, height, 0.5f));
    add_wall(lv, Vec3(right_end - right_width / 2, 0, -10), Vec3(right_width, height, 0.5f));
}

} // namespace

TEST_CASE("the main level has a navigation mesh") {
    auto level = level::load_level_file(ks::test::source_dir() / "levels/main.json");
    REQUIRE(level);
    auto g = make_game(*level);
    REQUIRE(g->navigation() != nullptr);
    CHECK(g->navigation_error().empty());
}

TEST_CASE("a robot that saw an idle player through a window walks round through the door and shoots") {
    // The wall in front of the robot has a window between heights 2 and 4: the robot's eye (2.7) sees the
    // player through it, but its shots (from the chest) would hit the sill, and it cannot step over it.
    auto lv = flat_level();
    add_wall(lv, Vec3(-9, 0, -10), Vec3(42, 2, 0.5f));  // the sill, x -30..12
    add_wall(lv, Vec3(-9, 4, -10), Vec3(42, 12, 0.5f)); // above the window
    add_wall(lv, Vec3(24, 0, -10), Vec3(12, 16, 0.5f)); // x 18..30; the doorway is x 12..18
    auto& robot = add_robot(lv, Vec3(0, 0, -17)).as<level::RobotProps>();
    robot.hit_probability = 1.0f;
    auto g = make_game(lv);
    float widest_x = 0.0f;
    for (int i = 0; i < 25 * 120 && g->player().damage_taken == 0.0f; ++i) {
        g->step({});
        widest_x = std::max(widest_x, g->robots()[0].feet.x);
    }
    CHECK(widest_x > 12.0f); // it went through the doorway
    CHECK(g->player().damage_taken > 0.0f);
}

TEST_CASE("an angry robot climbs the stairs to the player on a platform") {
    auto lv = flat_level();
    auto& platform = lv.add(level::EntityType::Floor, Vec3(0, 6, -30), "platform");
    platform.as<level::FloorProps>().size = Vec2(20, 20);
    // Rises toward its local -z: from z = -8 at the ground to z = -20 at the platform's edge.
    auto& stair = lv.add(level::EntityType::Stair, Vec3(0, 0, -14), "stair");
    stair.as<level::StairProps>().size = Vec3(6, 6, 12);
    auto& robot = add_robot(lv, Vec3(12, 0, 0)).as<level::RobotProps>();
    robot.hit_probability = 0.0f;
    robot.shooting_distance = 2.0f; // keeps walking up to the player
    lv.player_start.position = Vec3(0, 6, -32);
    auto g = make_game(lv);
    g->damage_robot(0, 1.0f, true); // angry: follows regardless of distance and level
    float highest = 0.0f;
    for (int i = 0; i < 15 * 120; ++i) {
        g->step({});
        highest = std::max(highest, g->robots()[0].feet.y);
    }
    CHECK(highest > 5.5f);
    CHECK(geometry::ground_distance(g->robots()[0].feet, g->player().feet) < 8.0f);
}

TEST_CASE("a closed door stops a hunting robot; an open one lets it through") {
    for (bool open : {false, true}) {
        CAPTURE(open);
        auto lv = flat_level();
        add_wall_with_doorway(lv, 0.0f);
        auto& door = lv.add(level::EntityType::Door, Vec3(0, 0, -10), "door");
        door.as<level::DoorProps>().width = 6.0f;
        door.as<level::DoorProps>().open = open;
        add_robot(lv, Vec3(0, 0, -30));
        lv.player_start.position = Vec3(0, 0, 20);
        auto g = make_game(lv);
        g->damage_robot(0, 1.0f, true); // angry: it wants to reach the player
        for (int i = 0; i < 12 * 120; ++i) g->step({});
        const bool through = g->robots()[0].feet.z > -9.0f;
        CHECK(through == open);
    }
}

TEST_CASE("a shot heard behind a wall brings an idle robot round to look") {
    auto lv = flat_level();
    add_wall_with_doorway(lv, 20.0f); // the way round is through x = 20
    auto& robot = add_robot(lv, Vec3(0, 0, -18)).as<level::RobotProps>();
    robot.hearing_radius = 60.0f;
    robot.hit_probability = 0.0f;
    auto g = make_game(lv);
    run_for(*g, 0.5);
    REQUIRE(g->robots()[0].mode == RobotMode::Idle); // the wall hides the player
    Input fire;
    fire.fire = true;
    fire.look_pitch = -0.3f; // into the floor: the sound, not the bullet, reaches the robot
    g->step(fire);
    g->step({});
    CHECK(g->robots()[0].mode == RobotMode::Hunt);
    CHECK(geometry::ground_distance(g->robots()[0].last_known, g->player().feet) < 0.5f);
    float nearest = 1e9f;
    for (int i = 0; i < 10 * 120; ++i) {
        g->step({});
        nearest = std::min(nearest, geometry::ground_distance(g->robots()[0].feet, Vec3(0, 0, 0)));
    }
    CHECK(nearest < 12.0f); // it came round the wall toward the shot
}

TEST_CASE("a shot beyond the hearing radius along the mesh is not heard, however close in a straight line") {
    auto lv = flat_level();
    add_wall_with_doorway(lv, 27.0f); // a wall between them: the way round through x = 27 is over 55 long
    auto& robot = add_robot(lv, Vec3(0, 0, -14)).as<level::RobotProps>();
    robot.hearing_radius = 30.0f; // 14 in a straight line, > 55 round the wall
    auto g = make_game(lv);
    run_for(*g, 0.2);
    Input fire;
    fire.fire = true;
    g->step(fire);
    g->step({});
    CHECK(g->robots()[0].mode == RobotMode::Idle);
}

TEST_CASE("a robot that lost the player hunts to where it was, searches, then goes back to idle") {
    auto lv = flat_level();
    auto& robot = add_robot(lv, Vec3(0, 0, -15)).as<level::RobotProps>();
    robot.hit_probability = 0.0f;
    robot.search_time = 4.0f;
    auto g = make_game(lv);
    run_for(*g, 1.0);
    REQUIRE(g->robots()[0].mode != RobotMode::Idle);
    const Vec3 seen_at = g->player().feet;
    g->teleport_player(Vec3(0, 0, 90), 0.0f); // far beyond the eye radii
    run_for(*g, 0.2);
    CHECK(g->robots()[0].mode == RobotMode::Hunt);
    CHECK(geometry::ground_distance(g->robots()[0].last_known, seen_at) < 0.5f);
    bool searched = false;
    for (int i = 0; i < 3 * 120; ++i) {
        g->step({});
        searched |= g->robots()[0].mode == RobotMode::Search;
    }
    CHECK(searched);
    CHECK(geometry::ground_distance(g->robots()[0].feet, seen_at) < 8.0f); // it went to look
    run_for(*g, 2.0);
    CHECK(g->robots()[0].mode == RobotMode::Idle);
}

TEST_CASE("a level with no floor still starts: one clear message, robots stand guard") {
    level::Level lv;
    lv.name = "no floor";
    add_wall(lv, Vec3(0, 0, -20), Vec3(10, 16, 0.5f));
    add_robot(lv, Vec3(0, 0, -10));
    auto g = make_game(lv);
    CHECK(g->navigation() == nullptr);
    CHECK(g->navigation_error().find("floor") != std::string::npos);
    g->damage_robot(0, 1.0f, true); // angry, but nothing to walk on
    const Vec3 before = g->robots()[0].feet;
    run_for(*g, 2.0);
    CHECK(geometry::ground_distance(g->robots()[0].feet, before) < 0.5f);
}

TEST_CASE("three robots meeting in one doorway all get through, none stuck for long") {
    auto lv = flat_level();
    add_wall_with_doorway(lv, 0.0f);
    for (float x : {-4.0f, 0.0f, 4.0f}) {
        auto& robot = add_robot(lv, Vec3(x, 0, -22)).as<level::RobotProps>();
        robot.hit_probability = 0.0f;
        robot.shooting_distance = 3.0f; // keep walking toward the player
    }
    lv.player_start.position = Vec3(0, 0, 12);
    auto g = make_game(lv);
    for (std::size_t i = 0; i < 3; ++i) g->damage_robot(i, 1.0f, true); // all angry at once
    std::array<float, 3> stuck_for{}, longest_stuck{};
    std::array<Vec3, 3> last{};
    for (std::size_t i = 0; i < 3; ++i) last[i] = g->robots()[i].feet;
    for (int step = 0; step < 10 * 120; ++step) {
        g->step({});
        for (std::size_t i = 0; i < 3; ++i) {
            const Vec3 now = g->robots()[i].feet;
            const bool done = now.z > -6.0f; // through the doorway
            const float moved = geometry::ground_distance(now, last[i]);
            last[i] = now;
            stuck_for[i] =
                done || moved > 0.02f ? 0.0f : stuck_for[i] + static_cast<float>(g->settings().step);
            longest_stuck[i] = std::max(longest_stuck[i], stuck_for[i]);
        }
    }
    for (std::size_t i = 0; i < 3; ++i) {
        CAPTURE(i);
        CHECK(g->robots()[i].feet.z > -6.0f);
        CHECK(longest_stuck[i] < 2.0f);
    }
}

TEST_CASE("a thousand angry robots plan and walk without trouble") {
    auto lv = flat_level();
    for (int i = 0; i < 1000; ++i) {
        const float x = -90.0f + static_cast<float>(i % 40) * 4.5f,
                    z = -90.0f + static_cast<float>(i / 40) * 4.5f;
        add_robot(lv, Vec3(x, 0, z)).as<level::RobotProps>().hit_probability = 0.0f;
    }
    lv.player_start.position = Vec3(0, 0, 95);
    auto g = make_game(lv);
    REQUIRE(g->robots().size() == 1000);
    for (std::size_t i = 0; i < 1000; ++i) g->damage_robot(i, 1.0f, true);
    float before = 0.0f;
    for (const Robot& r : g->robots()) before += geometry::ground_distance(r.feet, g->player().feet);
    run_for(*g, 1.0);
    float after = 0.0f;
    for (const Robot& r : g->robots()) {
        CHECK(is_finite(r.feet));
        after += geometry::ground_distance(r.feet, g->player().feet);
    }
    CHECK(after < before - 1000.0f); // on average each came at least a unit closer
}

TEST_CASE("a patrol between two points with a wall between them walks round through the doorway") {
    auto lv = flat_level();
    add_wall_with_doorway(lv, 15.0f);
    auto& robot = add_robot(lv, Vec3(0, 0, -20)).as<level::RobotProps>();
    robot.patrol.points = {Vec3(0, 0, -20), Vec3(0, 0, 0)};
    robot.patrol.wait = 0.0f;
    lv.player_start.position = Vec3(0, 0, 90); // out of sight: this is about the route
    auto g = make_game(lv);
    float nearest_far_point = 1e9f, widest_x = 0.0f;
    for (int i = 0; i < 30 * 120; ++i) {
        g->step({});
        nearest_far_point =
            std::min(nearest_far_point, geometry::ground_distance(g->robots()[0].feet, Vec3(0, 0, 0)));
        widest_x = std::max(widest_x, g->robots()[0].feet.x);
    }
    CHECK(nearest_far_point < 1.0f); // it reached the point behind the wall
    CHECK(widest_x > 12.0f);         // by way of the doorway
}

TEST_CASE("robots walking the mesh side by side spread apart instead of marching shoulder to shoulder") {
    auto lv = flat_level();
    for (float x : {-0.9f, 0.9f}) { // 1.8 apart: their 0.8 capsules do not touch
        auto& robot = add_robot(lv, Vec3(x, 0, -40)).as<level::RobotProps>();
        robot.hit_probability = 0.0f;
    }
    lv.player_start.position = Vec3(0, 0, 60);
    auto g = make_game(lv);
    g->damage_robot(0, 1.0f, true);
    g->damage_robot(1, 1.0f, true);
    run_for(*g, 3.0);
    const float apart = geometry::ground_distance(g->robots()[0].feet, g->robots()[1].feet);
    CHECK(apart > 2.2f);                   // pushed out to about three robot radii
    CHECK(g->robots()[0].feet.z > -35.0f); // and still on their way
    CHECK(g->robots()[1].feet.z > -35.0f);
}
