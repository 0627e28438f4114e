// tests/data/levels/logic_hall.json played through by a script: walking into the hall shows a message and
// starts a spawner; when its robots are dead the first objective completes, which unlocks and opens the exit;
// the control panel completes the second and wins. The same script twice ends in the same state hash.
#include "game_test_levels.h"
#include "level/level_io.h"

using namespace ks;
using namespace ks::game;
using namespace ks::game_test;

namespace {

level::Level hall_level() {
    level::LoadReport report;
    auto lv = level::load_level_file(ks::test::data_dir() / "levels" / "logic_hall.json", &report);
    REQUIRE_MESSAGE(lv.ok(), report.str());
    CHECK_MESSAGE(report.diagnostics.empty(), report.str());
    return std::move(lv).value();
}

Input forward() {
    return Input{1.0f};
}

struct Run {
    std::uint64_t hash = 0;
    std::int64_t steps = 0;
};

Run play_through(const level::Level& lv, std::uint64_t seed) {
    auto g = make_game(lv, seed);
    g->step({});
    CHECK(on_screen(*g) == "Find the control panel");
    REQUIRE(g->logic().objectives().size() == 2);
    CHECK(g->logic().current_objective() == 0);
    CHECK(g->logic().objectives()[0].text == "Clear the hall");

    // The exit is locked: at it, the caption says so and E does nothing.
    g->teleport_player(Vec3(0, 0, -25), 0.0f);
    g->step({});
    REQUIRE(g->doors()[0].player_inside);
    CHECK(g->caption().text() == "Locked");
    g->step(press_e());
    CHECK(count_events(*g, EventType::LockedDoorUsed) == 1);
    run_for(*g, 0.5);
    CHECK(g->doors()[0].progress == 0.0f);
    g->teleport_player(Vec3(0, 0, 20), 0.0f);
    run_for(*g, 0.2);
    CHECK(g->robots().empty()); // nothing spawned yet: nobody entered the hall

    // Walk north through the doorway into the hall trigger.
    bool intruders = false;
    for (int i = 0; i < 240 && !intruders; ++i) {
        g->step(forward());
        intruders = shown(*g, "Intruders in the hall: clear it") == 1;
    }
    REQUIRE(intruders);
    CHECK(g->player().feet.z < -2.9f);

    // The spawner's robots come (0.25 s later, one a second, two at a time) and are shot down now and then.
    int most_alive = 0;
    for (int i = 0; i < 120 * 10 && !g->logic().objectives()[0].completed; ++i) {
        g->step({});
        int alive = 0;
        for (const Robot& r : g->robots()) alive += r.alive() ? 1 : 0;
        most_alive = std::max(most_alive, alive);
        if (g->steps() % 300 == 0) // every 2.5 s: two are up by then, the third waits
            for (std::size_t k = 0; k < g->robots().size(); ++k)
                if (g->robots()[k].alive()) g->damage_robot(k, 1000.0f, true);
    }
    REQUIRE(g->logic().objectives()[0].completed);
    CHECK(g->robots().size() == 3);
    CHECK(most_alive == 2);
    CHECK(g->phase() == Phase::Playing);
    CHECK(g->logic().current_objective() == 1);
    CHECK(on_screen(*g) == "The exit is open");
    CHECK_FALSE(g->doors()[0].locked);
    run_for(*g, 1.1); // opens 0.5 s after the objective, in 0.5 s
    CHECK(g->doors()[0].progress == 1.0f);

    // Through the exit to the panel, and E.
    g->teleport_player(Vec3(0, 0, -25), 0.0f);
    run_for(*g, 1.2, forward());
    CHECK(g->player().feet.z < -40.0f);
    run_for(*g, 0.1);
    REQUIRE(g->interact_target() == 18);
    g->step(press_e());
    CHECK(count_events(*g, EventType::ObjectiveCompleted) == 1);
    CHECK(g->phase() == Phase::Won);
    return {g->state_hash(), g->steps()};
}

} // namespace

TEST_CASE("the hall level plays through: trigger, spawner, objective, locked exit, panel; the same twice") {
    const level::Level lv = hall_level();
    const Run first = play_through(lv, 4);
    const Run again = play_through(lv, 4);
    CHECK(again.hash == first.hash);
    CHECK(again.steps == first.steps);
    MESSAGE("hall level: won after " << first.steps << " steps, state " << first.hash);
}

TEST_CASE("the hall level saves and loads back byte for byte") {
    const level::Level lv = hall_level();
    const std::string saved = level::save_level_string(lv);
    auto back = level::load_level_string(saved, "hall.json");
    REQUIRE(back.ok());
    CHECK(*back == lv);
    CHECK(level::save_level_string(*back) == saved);
}
