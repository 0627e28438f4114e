// The live play-test's rebuild (game/live_update.h): an edited level replaces the running one while the
// player and the state of what still exists carry over; a moved wall blocks at its new place, a new robot
// plays, a changed link fires its new target, a moved spawner's next robot comes from its new place.
#include "game/live_update.h"
#include "game_test_levels.h"

#include <limits>
#include <optional>

using namespace ks;
using namespace ks::game;
using namespace ks::game_test;

namespace {

LiveRebuild rebuild(const Game& running, const level::Level& before, const level::Level& edited) {
    auto r = rebuild_for_edit(running, before, edited, GameOptions{});
    if (!r) FAIL(r.error().str());
    return std::move(*r);
}

// flat_level() on a 100 x 100 floor: the navigation mesh, most of each build, takes a quarter of the time.
level::Level small_level() {
    auto lv = flat_level();
    lv.entities.front().as<level::FloorProps>().size = Vec2(100.0f, 100.0f);
    return lv;
}

level::Entity& entity_named(level::Level& lv, const char* name) {
    for (auto& e : lv.entities)
        if (e.name == name) return e;
    FAIL("no entity " << name);
    return lv.entities.front();
}

} // namespace

TEST_CASE("a live edit keeps the player and moves a wall to where it now blocks") {
    auto lv = small_level();
    add_wall(lv, Vec3(0, 0, -10), Vec3(20, 4, 1)).name = "Wall";
    auto g = make_game(lv);
    run_for(*g, 0.2);
    g->teleport_player(Vec3(3, 0, 2), 0.5f, 0.1f);
    g->damage_player(30.0f);
    run_for(*g, 0.1);
    const PlayerState before = g->player();
    const std::int64_t steps = g->steps();
    CHECK(g->line_blocked(Vec3(0, 1.5f, -5), Vec3(0, 1.5f, -15)));

    auto edited = lv;
    entity_named(edited, "Wall").position = Vec3(0, 0, -20);
    LiveRebuild r = rebuild(*g, lv, edited);
    CHECK(r.kept == 0);
    CHECK(r.added == 0);
    CHECK(r.removed == 0);
    Game& now = *r.game;
    CHECK(now.steps() == steps);
    CHECK(glm::length(now.player().feet - before.feet) < 1e-4f);
    CHECK(now.player().yaw == before.yaw);
    CHECK(now.player().pitch == before.pitch);
    CHECK(now.player().health == before.health);
    CHECK(now.player().ammo == before.ammo);
    CHECK_FALSE(now.line_blocked(Vec3(0, 1.5f, -5), Vec3(0, 1.5f, -15)));
    CHECK(now.line_blocked(Vec3(0, 1.5f, -15), Vec3(0, 1.5f, -25)));
    // Walking at it for three seconds (45 units at full speed) ends in front of its new place.
    Input forward;
    forward.move_forward = 1.0f;
    now.teleport_player(Vec3(0, 0, 0), 0.0f);
    run_for(now, 3.0, forward);
    CHECK(now.player().feet.z > -20.0f);
    CHECK(now.player().feet.z < -17.0f);
}

TEST_CASE("a live edit adds a robot, keeps an open door and a hurt robot, and fires a changed link") {
    auto lv = small_level();
    add_robot(lv, Vec3(30, 0, 30)).name = "Guard";
    entity_named(lv, "Guard").as<level::RobotProps>().dormant = true;
    lv.add(level::EntityType::Door, Vec3(-30, 0, 0), "Gate");
    add_message(lv, "Hello", "hello");
    add_message(lv, "Bye", "bye");
    add_trigger(lv, "Zone", Vec3(0, 0, -20), Vec3(6, 4, 6));
    entity_named(lv, "Zone").links = {link("on_enter", "Hello", "show")};
    auto g = make_game(lv);
    run_for(*g, 0.1);
    const int gate = entity_named(lv, "Gate").id;
    REQUIRE(g->run_action(level::LinkAction::Open, gate));
    run_for(*g, 2.0);
    REQUIRE(g->doors()[0].progress == 1.0f);
    g->damage_robot(0, 40.0f, true);
    run_for(*g, 0.1);
    const float guard_health = g->robots()[0].health;
    REQUIRE(guard_health < 100.0f);

    auto edited = lv;
    entity_named(edited, "Zone").links = {link("on_enter", "Bye", "show")};
    add_robot(edited, Vec3(-30, 0, 30)).name = "Newcomer";
    LiveRebuild r = rebuild(*g, lv, edited);
    CHECK(r.added == 1);
    Game& now = *r.game;
    REQUIRE(now.robots().size() == 2);
    CHECK(now.robots()[0].health == guard_health);
    CHECK(now.robots()[1].entity_id == entity_named(edited, "Newcomer").id);
    CHECK(glm::length(now.robots()[1].feet - Vec3(-30, 0, 30)) < 0.5f);
    CHECK(now.doors()[0].progress == 1.0f);
    CHECK(now.doors()[0].opening);
    // The trigger's link now shows "bye".
    now.teleport_player(Vec3(0, 0, -20), 0.0f);
    run_for(now, 0.2);
    CHECK(on_screen(now) == "bye");
}

TEST_CASE("a moved spawner's next robot comes from its new place; the robots it made stay") {
    auto lv = small_level();
    auto& pen = lv.add(level::EntityType::Spawner, Vec3(0, 0, -40), "Pen").as<level::SpawnerProps>();
    pen.count = 3;
    pen.interval = 1.0f;
    pen.max_alive = 3;
    pen.robot.eye_radius_min = pen.robot.eye_radius_max = pen.robot.hearing_radius = 0.0f;
    pen.robot.dormant = true;
    lv.links = {link("on_start", "Pen", "spawn")};
    auto g = make_game(lv);
    run_for(*g, 0.5);
    REQUIRE(g->robots().size() == 1);
    const Vec3 first = g->robots()[0].feet;

    auto edited = lv;
    entity_named(edited, "Pen").position = Vec3(40, 0, 0);
    LiveRebuild r = rebuild(*g, lv, edited);
    Game& now = *r.game;
    REQUIRE(now.robots().size() == 1);
    CHECK(glm::length(now.robots()[0].feet - first) < 1e-3f);
    CHECK(now.logic().spawners()[0].left == 2);
    std::optional<Vec3> spawned;
    for (int i = 0; i < 120 && !spawned; ++i) {
        now.step({});
        for (const Event& e : now.events())
            if (e.type == EventType::RobotSpawned) spawned = e.position;
    }
    REQUIRE(spawned);
    CHECK(glm::length(Vec2(spawned->x - 40.0f, spawned->z)) < 5.5f);
    CHECK(now.robots().size() == 2);
    // The on_start link did not run again: the wave goes on with the one robot left to make.
    CHECK(now.logic().spawners()[0].left == 1);
}

TEST_CASE("a delayed spawn still waiting when the spawner is moved comes from its new place") {
    auto lv = small_level();
    auto& pen = lv.add(level::EntityType::Spawner, Vec3(0, 0, -40), "Pen").as<level::SpawnerProps>();
    pen.count = 1;
    pen.max_alive = 1;
    pen.robot.eye_radius_min = pen.robot.eye_radius_max = pen.robot.hearing_radius = 0.0f;
    pen.robot.dormant = true;
    lv.links = {link("on_start", "Pen", "spawn", 1.0f)};
    auto g = make_game(lv);
    run_for(*g, 0.3); // on_start has fired: the spawn waits until 1 s
    REQUIRE(g->robots().empty());
    REQUIRE(g->logic().pending().size() == 1);

    auto spawned_at = [](Game& now) {
        std::optional<Vec3> at;
        for (int i = 0; i < 240 && !at; ++i) {
            now.step({});
            for (const Event& e : now.events())
                if (e.type == EventType::RobotSpawned) at = e.position;
        }
        return at;
    };
    SUBCASE("the link kept: the spawn runs when it was due, at the new place") {
        auto edited = lv;
        entity_named(edited, "Pen").position = Vec3(40, 0, 0);
        LiveRebuild r = rebuild(*g, lv, edited);
        CHECK(r.game->logic().pending().size() == 1);
        const auto at = spawned_at(*r.game);
        REQUIRE(at);
        CHECK(glm::length(Vec2(at->x - 40.0f, at->z)) < 5.5f);
        CHECK(r.game->steps() < g->steps() + 100); // due 1 s after the start, not 1 s after the edit
    }
    SUBCASE("the link deleted: its waiting action goes with it") {
        auto edited = lv;
        edited.links.clear();
        LiveRebuild r = rebuild(*g, lv, edited);
        CHECK(r.game->logic().pending().empty());
        CHECK_FALSE(spawned_at(*r.game));
    }
}

TEST_CASE("an edit the game cannot build is refused and the running game plays on") {
    auto lv = small_level();
    add_wall(lv, Vec3(0, 0, -10), Vec3(20, 4, 1)).name = "Wall";
    auto g = make_game(lv);
    run_for(*g, 0.1);
    auto edited = lv;
    entity_named(edited, "Wall").position = Vec3(0, std::numeric_limits<float>::quiet_NaN(), 0);
    auto r = rebuild_for_edit(*g, lv, edited, GameOptions{});
    REQUIRE_FALSE(r);
    CHECK(r.error().str().find("Wall") != std::string::npos);
    const auto steps = g->steps();
    run_for(*g, 0.1);
    CHECK(g->steps() > steps);
}
