// Robot patrols: the route order (loop, ping-pong), the wait at each point, an alerted robot that chases and
// then goes back to its route, and the route's progress in the state hash (record -> replay stays exact).
#include "game/headless.h"
#include "game/patrol.h"
#include "game_test_levels.h"
#include "geometry/ground_plane.h"
#include "level/level_io.h"

#include <vector>

using namespace ks;
using namespace ks::game;
using namespace ks::game_test;

namespace {

level::Patrol route(std::vector<Vec3> points, const char* mode = "loop", float wait = 0.0f) {
    level::Patrol patrol;
    patrol.points = std::move(points);
    patrol.mode.value = mode;
    patrol.wait = wait;
    return patrol;
}

// A robot far from the player (who stands at the origin), walking `patrol`.
std::unique_ptr<Game> patrol_game(const level::Patrol& patrol, Vec3 feet = Vec3(30, 0, -60)) {
    auto lv = flat_level();
    add_robot(lv, feet).as<level::RobotProps>().patrol = patrol;
    return make_game(lv);
}

// The targets the robot heads for, in order, over `seconds`, each recorded when the robot takes it up.
std::vector<int> targets_over(Game& g, double seconds) {
    std::vector<int> targets{g.robots()[0].patrol.target};
    const auto steps = static_cast<int>(seconds * 120);
    for (int i = 0; i < steps; ++i) {
        g.step({});
        if (g.robots()[0].patrol.target != targets.back()) targets.push_back(g.robots()[0].patrol.target);
    }
    return targets;
}

} // namespace

TEST_CASE("advance_patrol: loops wrap, ping-pong routes turn round at either end, one point stays") {
    PatrolProgress p;
    const auto loop = route({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}});
    std::vector<int> seen;
    for (int i = 0; i < 5; ++i) advance_patrol(loop, p), seen.push_back(p.target);
    CHECK(seen == std::vector<int>{1, 2, 0, 1, 2});

    p = {};
    seen.clear();
    const auto ping_pong = route({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, "ping_pong");
    for (int i = 0; i < 6; ++i) advance_patrol(ping_pong, p), seen.push_back(p.target);
    CHECK(seen == std::vector<int>{1, 2, 1, 0, 1, 2});

    p = {};
    advance_patrol(route({{4, 0, 4}}), p);
    CHECK(p.target == 0);
}

TEST_CASE("a robot with a loop patrol walks its points in order, back to the first") {
    auto g = patrol_game(route({{30, 0, -60}, {40, 0, -60}, {40, 0, -70}}));
    std::vector<int> targets = targets_over(*g, 40.0);
    CAPTURE(targets.size());
    REQUIRE(targets.size() >= 7);
    targets.resize(7);
    CHECK(targets == std::vector<int>{0, 1, 2, 0, 1, 2, 0});
    CHECK(g->robots()[0].mode == RobotMode::Idle);
}

TEST_CASE("a ping-pong patrol goes back and forth, and the robot reaches every point it leaves") {
    const std::vector<Vec3> points{{30, 0, -60}, {40, 0, -60}, {40, 0, -70}};
    auto g = patrol_game(route(points, "ping_pong"));
    std::vector<int> targets{0};
    for (int i = 0; i < 40 * 120; ++i) {
        const int before = g->robots()[0].patrol.target;
        g->step({});
        const Robot& r = g->robots()[0];
        if (r.patrol.target == before) continue;
        // It left `before` only once it stood there.
        CHECK(geometry::ground_distance(r.feet, points[static_cast<size_t>(before)]) <=
              kPatrolArriveDistance + 0.05f);
        targets.push_back(r.patrol.target);
    }
    REQUIRE(targets.size() >= 6);
    targets.resize(6);
    CHECK(targets == std::vector<int>{0, 1, 2, 1, 0, 1});
}

TEST_CASE("a robot waits `wait` seconds at each point, standing still") {
    auto g = patrol_game(route({{30, 0, -60}, {36, 0, -60}}, "loop", 2.0f));
    g->step({}); // at its first point already: the wait starts
    CHECK(g->robots()[0].patrol.waiting > 1.9f);
    const Vec3 start = g->robots()[0].feet;
    run_for(*g, 1.9);
    CHECK(geometry::ground_distance(g->robots()[0].feet, start) < 0.05f);
    CHECK(g->robots()[0].patrol.target == 0);
    run_for(*g, 0.2);
    CHECK(g->robots()[0].patrol.target == 1);
    run_for(*g, 4.0);
    CHECK(geometry::ground_distance(g->robots()[0].feet, start) > 3.0f); // on its way to (36, 0, -60)
}

TEST_CASE("without a wait the robot walks straight on through each point") {
    auto g = patrol_game(route({{30, 0, -60}, {36, 0, -60}}));
    g->step({});
    CHECK(g->robots()[0].patrol.waiting == 0.0f);
    CHECK(g->robots()[0].patrol.target == 1);
}

TEST_CASE("an alerted robot on patrol still chases, and goes back to its route when it loses the player") {
    auto lv = flat_level();
    auto& robot = add_robot(lv, Vec3(0, 0, -40)).as<level::RobotProps>();
    robot.patrol = route({{0, 0, -40}, {0, 0, -15}});
    robot.hit_probability = 0.0f; // its shots never land: this test is about where it walks
    robot.search_time = 0.0f;     // back to the route at once (hunting is tested in test_robot_hunting.cpp)
    auto g = make_game(lv);

    bool alerted = false;
    float closest = 1e9f;
    for (int i = 0; i < 20 * 120; ++i) {
        g->step({});
        alerted |= count_events(*g, EventType::RobotAlerted) > 0;
        closest = std::min(closest, geometry::ground_distance(g->robots()[0].feet, g->player().feet));
    }
    CHECK(alerted);
    CHECK(g->robots()[0].mode != RobotMode::Idle);
    CHECK(closest < 12.0f); // closer than its route ever goes (15): it chased to shooting distance

    g->teleport_player(Vec3(90, 0, 90), 0.0f);
    run_for(*g, 0.5);
    CHECK(g->robots()[0].mode == RobotMode::Idle);
    // Back along the route: it reaches the far end of it again.
    float nearest_to_start = 1e9f;
    for (int i = 0; i < 30 * 120; ++i) {
        g->step({});
        nearest_to_start =
            std::min(nearest_to_start, geometry::ground_distance(g->robots()[0].feet, Vec3(0, 0, -40)));
    }
    CHECK(nearest_to_start <= kPatrolArriveDistance + 0.05f);
    CHECK(g->robots()[0].mode == RobotMode::Idle);
}

TEST_CASE("the state hash holds the patrol's progress; robots without a route hash as before") {
    // Two robots standing at their only point, differing only in how long they wait there.
    auto a = patrol_game(route({{30, 0, -60}}, "loop", 5.0f));
    auto b = patrol_game(route({{30, 0, -60}}, "loop", 6.0f));
    run_for(*a, 0.5);
    run_for(*b, 0.5);
    CHECK(a->robots()[0].feet == b->robots()[0].feet);
    CHECK(a->state_hash() != b->state_hash());
}

TEST_CASE("a recorded run on a level with patrols replays to the exact final state hash") {
    ks::test::ScratchDir dir;
    auto lv = level::load_level_file(ks::test::source_dir() / "levels" / "main.json");
    REQUIRE(lv.ok());
    for (level::Entity& e : lv->entities)
        if (auto* robot = e.try_as<level::RobotProps>())
            robot->patrol = route({e.position, e.position + Vec3(4, 0, 0), e.position + Vec3(4, 0, 4)},
                                  "ping_pong", 0.5f);
    REQUIRE(level::save_level_file(dir / "patrols.json", *lv).ok());

    const auto [recorded, replayed] = record_and_replay(dir / "patrols.json", 10.0, 3, dir.path());
    CHECK(replayed.state_hash == recorded.state_hash);
    CHECK(replayed.steps == recorded.steps);
}
