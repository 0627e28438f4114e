// The autoplay bot wins the shipped main level and the logic example level headless, for several seeds,
// within a simulated time limit.
#include "game/autoplay.h"
#include "game/bot_profiles.h"
#include "game/headless.h"
#include "game/playtest_analysis.h"
#include "level/level_io.h"
#include "level/shutdown_objective.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdio>

using namespace ks;
using namespace ks::game;

namespace {
// The headless bot on a shipped or test level (relative to the source tree), 60 s simulated.
HeadlessStats autoplay_run(const char* level, std::uint64_t seed) {
    HeadlessOptions o;
    o.level = ks::test::source_dir() / level;
    o.seconds = 60.0;
    o.seed = seed;
    o.autoplay = true;
    auto stats = run_headless(o);
    if (!stats) FAIL(stats.error().str());
    MESSAGE("seed " << seed << ": " << stats->summary());
    return *stats;
}
} // namespace

TEST_CASE("autoplay wins levels/main.json for several seeds") {
    for (std::uint64_t seed : {1ull, 2ull, 3ull, 4ull, 5ull, 6ull}) {
        const auto stats = autoplay_run("levels/main.json", seed);
        CHECK(stats.outcome == "win");
        CHECK(stats.shots > 0);
        CHECK(stats.sim_time_s < 60.0);
        CHECK(stats.robots_killed >= 4);
    }
}

TEST_CASE("autoplay wins the logic example level (trigger, spawner, locked exit, panel) for seeds 1-6") {
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
        const auto stats = autoplay_run("tests/data/levels/logic_hall.json", seed);
        CHECK(stats.outcome == "win");
        CHECK(stats.robots_killed == 3); // the spawner's three, before the exit opens
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
    level::add_shutdown_objective(lv);
    for (int start_ammo : {0, 150}) {
        CAPTURE(start_ammo);
        GameOptions options;
        options.settings.start_ammo = start_ammo;
        auto g = Game::create(lv, options);
        REQUIRE(g);
        auto bot = Autoplay::create(lv, **g, 7);
        REQUIRE_MESSAGE(bot.ok(), (bot.ok() ? "" : bot.error().str()));
        for (int i = 0; i < 120 * 30 && (*g)->phase() == Phase::Playing; ++i) (*g)->step(bot->decide(**g));
        CHECK((*g)->phase() == Phase::Won);
        if (start_ammo == 0) CHECK((*g)->player().shots == 0);
        if (start_ammo > 0) CHECK((*g)->robots_killed() == 1); // with ammo it still fights first
    }
}

TEST_CASE("the bot's mesh: doors open, paths through them keep the player's body off every gas cylinder") {
    auto lv = level::load_level_file(ks::test::source_dir() / "levels/main.json");
    REQUIRE_MESSAGE(lv.ok(), (lv.ok() ? "" : lv.error().str()));
    const float keep_out = AutoplaySettings{}.cylinder_keep_out;
    auto mesh = build_autoplay_mesh(*lv, keep_out);
    REQUIRE_MESSAGE(mesh.ok(), (mesh.ok() ? "" : mesh.error().str()));
    std::vector<const level::Entity*> cylinders;
    const level::Entity* panel = nullptr;
    for (const level::Entity& e : lv->entities) {
        if (e.type() == level::EntityType::Door) CHECK((*mesh)->door_open(e.id)); // the level has them shut
        if (e.type() == level::EntityType::GasCylinder) cylinders.push_back(&e);
        if (e.type() == level::EntityType::ControlPanel) panel = &e;
    }
    REQUIRE(cylinders.size() == 6);
    REQUIRE(panel != nullptr);
    const float half_x = 0.5f * panel->as<level::ControlPanelProps>().size.x;
    const Vec3 beside_panel = panel->position - Vec3(half_x + level::kPlayerRadius + 0.5f, 0, 0);
    std::vector<Vec3> path;
    REQUIRE((*mesh)->find_path(lv->player_start.position, beside_panel, path) == nav::PathStatus::Found);
    CHECK(glm::length(path.back() - beside_panel) < 0.3f);
    // Touching a cylinder sets it off: the body (radius 1) must pass each cylinder with room to spare. On
    // a mesh without the keep-out this path passes three of them about 0.05 from touching.
    for (std::size_t i = 1; i < path.size(); ++i)
        for (const level::Entity* c : cylinders) {
            const Vec2 a(path[i - 1].x, path[i - 1].z), b(path[i].x, path[i].z),
                p(c->position.x, c->position.z);
            const float t = std::clamp(glm::dot(p - a, b - a) / glm::dot(b - a, b - a), 0.0f, 1.0f);
            const float clearance =
                glm::length(p - (a + t * (b - a))) - c->as<level::GasCylinderProps>().radius;
            CHECK(clearance > level::kPlayerRadius + 0.5f * keep_out);
        }
}

// The main level's fights, as each profile plays them (seeds 1-4, the play-test analysis): the perfect bot
// shoots first and is rarely hit; a new player, slower to see, turn and aim, is hit in more runs and takes
// more damage. (Its first robot falls before any robot fires in every one of these runs: the fights that
// hurt come later, at the doors.)
TEST_CASE("the new-player bot loses the main level's fights more often than the perfect bot") {
    auto lv = level::load_level_file(ks::test::source_dir() / "levels/main.json");
    REQUIRE(lv);
    auto play = [&](std::string_view profile) {
        AnalysisOptions o;
        o.runs = 4;
        o.threads = 2;
        o.seconds = 60.0;
        o.bot_profile = std::string(profile);
        auto report = analyze_level(*lv, o);
        REQUIRE_MESSAGE(report, (report ? "" : report.error().str()));
        MESSAGE(report->summary());
        int hurt = 0;
        for (const RunRecord& run : report->runs) hurt += run.damage_taken > 0.0f ? 1 : 0;
        return std::pair{hurt, report->damage_taken.mean};
    };
    const auto person = play(kNewPlayerProfile), perfect = play(kPerfectProfile);
    CHECK(person.first > perfect.first);
    CHECK(person.second > perfect.second);
}

TEST_CASE("bot profiles: perfect is the bot's defaults; a new player reacts, aims and turns like a person; "
          "an unknown name is an error listing them") {
    auto perfect = bot_profile(kPerfectProfile, {});
    REQUIRE(perfect);
    CHECK(perfect->reaction_time == 0.0f);
    CHECK(perfect->aim_error == 0.0f);
    CHECK(perfect->turn_rate == AutoplaySettings{}.turn_rate);
    auto person = bot_profile(kNewPlayerProfile, {});
    REQUIRE(person);
    CHECK(person->reaction_time >= 0.25f); // at least a simple visual reaction
    CHECK(person->aim_error > 0.0f);
    CHECK(person->turn_rate < perfect->turn_rate);
    CHECK(person->view_half_angle < kPi);
    CHECK(bot_profile_names().front() == kPerfectProfile);
    auto bad = bot_profile("aimbot", Location("command line", 0, 0, "--bot-profile"));
    REQUIRE_FALSE(bad);
    CHECK(bad.error().str().find("aimbot") != std::string::npos);
    CHECK(bad.error().hint.find("new-player") != std::string::npos);
}
