// Spawners: count, interval and max alive; robots only on the navigation mesh (and not on top of another
// robot or the player); robots made during play are whole robots (shot, killed, counted by objectives); the
// robot arrays grow without harm.
#include "game_test_levels.h"

using namespace ks;
using namespace ks::game;
using namespace ks::game_test;

namespace {

// A spawner that makes robots which never notice the player (so they stand and wander where they appear).
level::SpawnerProps& add_spawner(level::Level& lv, const char* name, Vec3 at, int count, float interval,
                                 int max_alive) {
    auto& s = lv.add(level::EntityType::Spawner, at, name).as<level::SpawnerProps>();
    s.count = count;
    s.interval = interval;
    s.max_alive = max_alive;
    s.robot.eye_radius_min = s.robot.eye_radius_max = s.robot.hearing_radius = 0.0f;
    s.robot.dormant = true; // they stand where they appear
    return s;
}

int spawned_events(const Game& g) {
    return count_events(g, EventType::RobotSpawned);
}

} // namespace

TEST_CASE("a spawner makes count robots, one per interval, on a spawn link") {
    auto lv = flat_level();
    add_spawner(lv, "Pen", Vec3(0, 0, -40), 3, 1.0f, 3).robot.health = 55.0f;
    lv.links = {link("on_start", "Pen", "spawn")};
    auto g = make_game(lv);
    std::vector<std::int64_t> spawned_at;
    for (int i = 0; i < 120 * 5; ++i) {
        g->step({});
        if (spawned_events(*g) > 0) spawned_at.push_back(g->steps());
    }
    REQUIRE(spawned_at.size() == 3);
    CHECK(spawned_at[0] == 1);
    CHECK(spawned_at[1] == 121);
    CHECK(spawned_at[2] == 241);
    REQUIRE(g->robots().size() == 3);
    const auto& spawner = g->logic().spawners()[0];
    CHECK(spawner.left == 0);
    CHECK(spawner.robots.size() == 3);
    std::vector<int> ids;
    for (const Robot& r : g->robots()) {
        CHECK(r.props.health == 55.0f);
        CHECK(r.health == 55.0f);
        CHECK(r.entity_id >= lv.next_id); // fresh ids after the level's
        ids.push_back(r.entity_id);
        // On the floor (y 0), near the spawner, apart from each other.
        CHECK(std::abs(r.feet.y) < 0.3f);
        CHECK(glm::length(Vec2(r.feet.x, r.feet.z + 40.0f)) <= 5.5f);
    }
    std::sort(ids.begin(), ids.end());
    CHECK(std::unique(ids.begin(), ids.end()) == ids.end());
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t k = i + 1; k < 3; ++k)
            CHECK(glm::length(g->robots()[i].feet - g->robots()[k].feet) > 1.6f);
}

TEST_CASE("a spawner waits while max_alive of its robots live, and goes on when one dies") {
    auto lv = flat_level();
    add_spawner(lv, "Pen", Vec3(0, 0, -40), 4, 0.0f, 2);
    lv.links = {link("on_start", "Pen", "spawn")};
    auto g = make_game(lv);
    run_for(*g, 2.0);
    CHECK(g->robots().size() == 2);
    CHECK(g->logic().spawners()[0].left == 2);
    g->damage_robot(0, 1000.0f, true);
    g->step({});
    CHECK(g->robots().size() == 3);
    run_for(*g, 2.0);
    CHECK(g->robots().size() == 3);
    g->damage_robot(1, 1000.0f, true);
    g->damage_robot(2, 1000.0f, true);
    run_for(*g, 0.5);
    CHECK(g->robots().size() == 4);
    CHECK(g->logic().spawners()[0].left == 0);
    // A second spawn link starts another wave; one during a wave changes nothing.
    const int pen = lv.entities[1].id;
    REQUIRE(g->run_action(level::LinkAction::Spawn, pen));
    REQUIRE(g->run_action(level::LinkAction::Spawn, pen));
    CHECK(g->logic().spawners()[0].left == 4);
    g->step({});
    CHECK(g->logic().spawners()[0].left == 3);
    CHECK(g->robots().size() == 5);
}

TEST_CASE("a spawner over no walkable ground makes nothing and says so; one with a robot on its spot uses "
          "the ring") {
    auto lv = flat_level();
    add_spawner(lv, "Void", Vec3(500, 0, 500), 2, 0.0f, 2);
    add_spawner(lv, "Crowded", Vec3(0, 0, -40), 1, 0.0f, 1);
    auto& sitter = add_robot(lv, Vec3(0, 0, -40));
    sitter.as<level::RobotProps>().dormant = true;
    lv.links = {link("on_start", "Void", "spawn"), link("on_start", "Crowded", "spawn")};
    auto g = make_game(lv);
    run_for(*g, 1.0);
    REQUIRE(g->robots().size() == 2); // the sitter and the crowded spawner's robot
    CHECK(g->logic().spawners()[0].robots.empty());
    CHECK(g->logic().spawners()[0].stuck);
    REQUIRE_FALSE(g->logic().problems().empty());
    CHECK(g->logic().problems().front().find("spawner \"Void\": no walkable ground") != std::string::npos);
    const Vec3 made = g->robots()[1].feet;
    CHECK(glm::length(Vec2(made.x, made.z + 40.0f)) == doctest::Approx(2.5f).epsilon(0.15));
}

TEST_CASE("a spawner over no walkable ground is named when the game is made, before anything starts it") {
    // Issue 30: the game said so only when a link first started the spawner, perhaps minutes into play.
    auto lv = flat_level();
    add_spawner(lv, "Void", Vec3(500, 0, 500), 2, 0.0f, 2);
    add_spawner(lv, "Pen", Vec3(0, 0, -12), 1, 0.0f, 1);
    auto g = make_game(lv); // no link starts either
    REQUIRE(g->logic().problems().size() == 1);
    CHECK(g->logic().problems().front().find("spawner \"Void\": no walkable ground") != std::string::npos);
    CHECK(g->logic().problems().front().find("move it over a floor") != std::string::npos);
    CHECK(g->logic().spawners()[0].stuck);
    CHECK_FALSE(g->logic().spawners()[1].stuck);
    run_for(*g, 0.5);
    CHECK(g->logic().problems().size() == 1); // said once
}

TEST_CASE(
    "robots made during play are whole robots: shot through their bodies, killed, counted by objectives") {
    auto lv = flat_level();
    add_spawner(lv, "Pen", Vec3(0, 0, -12), 2, 0.5f, 2).robot.health = 20.0f;
    lv.links = {link("on_start", "Pen", "spawn")};
    add_message(lv, "Clear", "clear");
    lv.objectives = {{"pen", "Empty the pen", {"Pen"}, {link("on_complete", "Clear", "show")}}};
    auto g = make_game(lv);
    g->step({});
    REQUIRE(g->robots().size() == 1);
    // The player faces -z; the robot stands 12 ahead: one shot (20 damage) kills it.
    Input fire;
    fire.look_pitch = -0.05f;
    fire.fire = true;
    g->step(fire);
    CHECK(count_events(*g, EventType::RobotHurt) == 1);
    CHECK_FALSE(g->robots()[0].alive());
    CHECK_FALSE(g->logic().objectives()[0].completed); // the second robot is still to come
    run_for(*g, 1.0);
    REQUIRE(g->robots().size() == 2);
    g->damage_robot(1, 100.0f, true);
    g->step({});
    CHECK(g->logic().objectives()[0].completed);
    CHECK(shown(*g, "clear") == 1);
    run_for(*g, 3.0);
    CHECK(g->robots_killed() == 2);
}

TEST_CASE("many waves grow the robot arrays while robots fight, shoot and die") {
    auto lv = flat_level();
    auto& s = add_spawner(lv, "Pen", Vec3(0, 0, -30), 8, 0.0f, 8);
    s.robot.dormant = false;
    s.robot.eye_radius_min = 40.0f;
    s.robot.eye_radius_max = 60.0f;
    s.robot.hit_probability = 1.0f;
    s.robot.damage = 0.0f;
    auto& gate = lv.add(level::EntityType::Trigger, Vec3(0, 0, 0), "Gate");
    gate.as<level::TriggerProps>().size = Vec3(200, 10, 200);
    gate.links = {link("on_enter", "Pen", "spawn")};
    auto g = make_game(lv, 5);
    for (int wave = 0; wave < 6; ++wave) {
        run_for(*g, 3.0);
        for (std::size_t i = 0; i < g->robots().size(); ++i) g->damage_robot(i, 1000.0f, true);
        g->teleport_player(Vec3(0, 0, 150), 0.0f); // out of the gate and back: a new wave
        g->step({});
        g->teleport_player(Vec3(0, 0, 0), 0.0f);
    }
    run_for(*g, 3.0);
    CHECK(g->robots().size() == 7 * 8); // the first entry and six more
    for (const Robot& r : g->robots()) CHECK(is_finite(r.feet));
    for (std::size_t i = 0; i < g->robots().size(); ++i) CHECK(g->robot_pose(i).size() > 0);
}
