// What the game tells the runtime's visual feedback: where damage came from (PlayerDamaged's position is
// the robot's hand tip or the blast centre, its end the player's eye), how long a hit robot flashes, and
// where a robot's shot struck a wall.
#include "game_test_levels.h"

#include <cmath>
#include <optional>

using namespace ks;
using namespace ks::game;
using namespace ks::game_test;

namespace {
std::optional<Event> first_event(const Game& g, EventType type) {
    for (const Event& e : g.events())
        if (e.type == type) return e;
    return std::nullopt;
}
} // namespace

TEST_CASE("a robot's hit on the player comes from the robot's hand tip") {
    auto lv = flat_level();
    auto& r = add_robot(lv, Vec3(0, 0, -8));
    r.as<level::RobotProps>().hit_probability = 1.0f;
    auto g = make_game(lv);
    std::optional<Event> shot, damaged;
    for (int i = 0; i < 4 * 120 && !damaged; ++i) {
        g->step({});
        shot = first_event(*g, EventType::RobotShot);
        damaged = first_event(*g, EventType::PlayerDamaged);
    }
    REQUIRE(damaged);
    REQUIRE(shot); // the same step
    CHECK(damaged->position.x == doctest::Approx(shot->position.x));
    CHECK(damaged->position.y == doctest::Approx(shot->position.y));
    CHECK(damaged->position.z == doctest::Approx(shot->position.z));
    CHECK(damaged->position.z < -6.0f); // in front of the player, at the robot
    const Vec3 eye = g->player().eye();
    CHECK(glm::length(damaged->end - eye) < 0.01f);
    CHECK(damaged->amount == doctest::Approx(10.0f));
}

TEST_CASE("a blast hurts the player from the cylinder's centre; a fall points nowhere") {
    auto lv = flat_level();
    lv.add(level::EntityType::GasCylinder, Vec3(-3, 0, 0), "gas"); // to the player's left (yaw 0 faces -z)
    auto g = make_game(lv);
    g->step({});
    g->explode_cylinder(0);
    const auto damaged = first_event(*g, EventType::PlayerDamaged);
    REQUIRE(damaged);
    const Vec3 centre = g->cylinders()[0].centre;
    CHECK(glm::length(damaged->position - centre) < 1e-4f);
    CHECK(damaged->position.x < -2.0f);
    CHECK(glm::length(damaged->end - g->player().eye()) < 0.01f);

    g->step({});
    g->damage_player(5.0f); // no source: the event's two points are the same
    const auto sourceless = first_event(*g, EventType::PlayerDamaged);
    REQUIRE(sourceless);
    CHECK(glm::length(sourceless->position - sourceless->end) < 1e-6f);
}

TEST_CASE("a hit robot flashes for the reference's 1 s, then not") {
    CHECK(kRobotHitFlashSeconds == 1.0f);
    auto lv = flat_level();
    add_robot(lv, Vec3(0, 0, -60));
    auto g = make_game(lv);
    g->step({});
    g->damage_robot(0, 20.0f, true);
    CHECK(g->robots()[0].hit_flash == doctest::Approx(1.0f));
    run_for(*g, 0.5);
    CHECK(g->robots()[0].hit_flash == doctest::Approx(0.5f).epsilon(0.02));
    run_for(*g, 0.5);
    CHECK(g->robots()[0].hit_flash < 1e-4f); // 120 steps of 1/120 s, give or take float rounding
    g->step({});
    CHECK(g->robots()[0].hit_flash == 0.0f);
}

TEST_CASE("a robot's shot that strikes a wall says where (sparks), with no damage") {
    // A waist-high wall: the robot sees the player over it (eye and chest lines pass), but the shot from
    // its lower hand tip meets the wall.
    auto lv = flat_level();
    auto& r = add_robot(lv, Vec3(0, 0, -8));
    r.as<level::RobotProps>().hit_probability = 1.0f;
    add_wall(lv, Vec3(0, 0, -4.0f), Vec3(4.0f, 1.45f, 0.3f));
    auto g = make_game(lv);
    int shots = 0, wall_hits = 0;
    for (int i = 0; i < 4 * 120; ++i) {
        g->step({});
        shots += count_events(*g, EventType::RobotShot);
        for (const Event& e : g->events())
            if (e.type == EventType::Hit) {
                ++wall_hits;
                CHECK(e.entity == -1);
                CHECK(e.amount == 0.0f);
                CHECK(e.position.z == doctest::Approx(-4.15f).epsilon(0.01)); // the wall's far face
                CHECK(e.end.z < -0.9f);                                       // its normal faces the robot
            }
    }
    CHECK(shots >= 2);
    CHECK(wall_hits == shots);
    CHECK(g->player().health == 100.0f);
}

TEST_CASE("the hit marker shows only when a shot hits a robot: not a wall, not a gas cylinder") {
    Input fire;
    fire.fire = true;
    const float aim = std::atan2(-1.5f, 10.0f); // the eye at y 3, a target's middle at y 1.5, 10 ahead
    {
        auto lv = flat_level();
        add_wall(lv, Vec3(0, 0, -10), Vec3(10, 8, 0.5f));
        auto g = make_game(lv);
        g->teleport_player(Vec3(0.0f), 0.0f, aim);
        g->step(fire);
        CHECK(count_events(*g, EventType::Hit) == 1);
        CHECK(g->player().hit_marker == 0.0f);
        CHECK(g->player().hits == 0);
    }
    {
        auto lv = flat_level();
        lv.add(level::EntityType::GasCylinder, Vec3(0, 0, -10), "gas");
        auto g = make_game(lv);
        g->teleport_player(Vec3(0.0f), 0.0f, std::atan2(-2.0f, 10.0f));
        g->step(fire);
        CHECK(g->cylinders()[0].exploded);
        CHECK(g->player().hit_marker == 0.0f);
        CHECK(g->player().hits == 0);
    }
    {
        auto lv = flat_level();
        add_robot(lv, Vec3(0, 0, -10));
        auto g = make_game(lv);
        g->teleport_player(Vec3(0.0f), 0.0f, aim);
        g->step(fire);
        CHECK(g->robots()[0].health < 100.0f);
        CHECK(g->player().hit_marker > 0.0f);
        CHECK(g->player().hits == 1);
        CHECK(g->player().shots == 1);
    }
}

TEST_CASE("hits count the shots that hit a live robot: accuracy is hits / shots") {
    Input fire;
    fire.fire = true;
    auto lv = flat_level();
    add_robot(lv, Vec3(0, 0, -10));
    auto g = make_game(lv);
    g->teleport_player(Vec3(0.0f), 0.0f, std::atan2(-1.5f, 10.0f));
    // Five hits of 20 kill the 100 hp robot; shots into its dying body or past it are misses.
    for (int i = 0; i < 8; ++i) {
        g->step(fire);
        for (int k = 0; k < 40; ++k) g->step({});
    }
    CHECK(g->player().shots == 8);
    CHECK(g->player().hits == 5);
}
