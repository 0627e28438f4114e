// The autoplay bot wins the shipped main level headless, for several seeds, within a simulated time limit.
#include "game/autoplay.h"
#include "game/headless.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <cstdio>

using namespace ks;
using namespace ks::game;

TEST_CASE("autoplay wins levels/main.json for several seeds") {
    for (std::uint64_t seed : {1ull, 2ull, 3ull, 4ull, 5ull, 6ull}) {
        HeadlessOptions o;
        o.level = test::source_dir() / "levels/main.json";
        o.seconds = 60.0;
        o.seed = seed;
        o.autoplay = true;
        auto stats = run_headless(o);
        if (!stats) FAIL(stats.error().str());
        MESSAGE("seed " << seed << ": " << stats->summary());
        CHECK(stats->outcome == "win");
        CHECK(stats->shots > 0);
        CHECK(stats->sim_time_s < 60.0);
        CHECK(stats->robots_killed >= 4);
    }
}

TEST_CASE("autoplay without ammo ignores the robots it sees and walks to the panel") {
    // Found by the soak (docs/reliability.md): with an empty rifle the bot kept aiming at a visible robot
    // and never moved again. Here a harmless robot stands in plain sight between the start and the panel.
    level::Level lv;
    lv.name = "no ammo";
    auto& floor = lv.add(level::EntityType::Floor, Vec3(0.0f), "ground");
    floor.as<level::FloorProps>().size = Vec2(80.0f, 80.0f);
    lv.player_start.position = Vec3(0.0f, 0.0f, 20.0f);
    auto& robot = lv.add(level::EntityType::Robot, Vec3(6.0f, 0.0f, 0.0f), "watcher");
    auto& props = robot.as<level::RobotProps>();
    props.eye_radius_min = 0.0f; // never notices the player
    props.eye_radius_max = 0.0f;
    props.hit_probability = 0.0f;
    lv.add(level::EntityType::ControlPanel, Vec3(0.0f, 0.0f, -20.0f), "panel");
    for (int start_ammo : {0, 150}) {
        CAPTURE(start_ammo);
        GameOptions options;
        options.settings.start_ammo = start_ammo;
        auto g = Game::create(lv, options);
        REQUIRE(g);
        Autoplay bot(**g, 7);
        for (int i = 0; i < 120 * 30 && (*g)->phase() == Phase::Playing; ++i) (*g)->step(bot.decide(**g));
        CHECK((*g)->phase() == Phase::Won);
        if (start_ammo == 0) CHECK((*g)->player().shots == 0);
        if (start_ammo > 0) CHECK((*g)->robots_killed() == 1); // with ammo it still fights first
    }
}
