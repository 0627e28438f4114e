// The game's end of the live play-test (runtime/model/live_edits.h): a level document from the editor's
// socket rebuilds the running game and is answered Applied; a document that is not JSON, or not a valid
// level, is refused with the loader's message on both sides and the game keeps its level.
#include "game/autoplay.h"
#include "game/game_test_levels.h"
#include "level/level_io.h"
#include "runtime/model/live_edits.h"
#include "runtime/model/logic_debugger.h"
#include "test_support.h"

#include <algorithm>

#include <doctest/doctest.h>

using namespace ks;
using namespace ks::game_test;

namespace {

struct Running {
    level::Level level = flat_level();
    std::unique_ptr<game::Game> game;
    Running() {
        level.entities.front().as<level::FloorProps>().size = Vec2(60.0f, 60.0f); // a quick navigation mesh
        add_wall(level, Vec3(0, 0, -10), Vec3(20, 4, 1)).name = "Wall";
        game = make_game(level);
        run_for(*game, 0.1);
    }
};

} // namespace

TEST_CASE("a live level document is read with the loader; bad ones are refused with its message") {
    Running r;
    auto moved = r.level;
    moved.entities.back().position = Vec3(0, 0, -20);
    auto edit = runtime::apply_live_level(level::save_level_string(moved), *r.game, r.level, {});
    REQUIRE(edit);
    CHECK(edit->level.entities.back().position.z == -20.0f);
    CHECK(edit->rebuild.game->steps() == r.game->steps());

    auto garbage = runtime::apply_live_level("{\"version\": 3, \"entities\": [", *r.game, r.level, {});
    REQUIRE_FALSE(garbage);
    CHECK(garbage.error().str().find("live update") != std::string::npos);

    std::string text = level::save_level_string(moved);
    text.replace(text.find("\"wall\""), 6, "\"wal\"");
    auto invalid = runtime::apply_live_level(text, *r.game, r.level, {});
    REQUIRE_FALSE(invalid);
    CHECK(invalid.error().str().find("wal") != std::string::npos);
}

TEST_CASE("an edit sent by the editor's end reaches the game's end and is answered; garbage is refused") {
    test::ScratchDir dir;
    const auto path = dir / "live.sock";
    auto server = live::LiveServer::listen(path, "tok");
    REQUIRE(server);
    runtime::LiveEdits edits(live::LiveClient(path, "tok"));
    Running r;
    std::vector<live::Frame> answers;
    std::vector<live::LiveNote> notes, game_notes;
    auto pump = [&](double now) {
        std::optional<runtime::LiveEdit> got;
        for (int i = 0; i < 4; ++i) {
            server->poll(answers, notes);
            if (auto e = edits.poll(now, *r.game, r.level, {})) got = std::move(e);
            game_notes.insert(game_notes.end(), edits.notes().begin(), edits.notes().end());
        }
        return got;
    };
    CHECK_FALSE(pump(0.0));
    REQUIRE(edits.connected());

    server->send(live::FrameType::Level, "not json at all");
    CHECK_FALSE(pump(0.1));
    REQUIRE(answers.size() == 1);
    CHECK(answers[0].type == live::FrameType::Refused);
    CHECK(answers[0].payload.find("live update") != std::string::npos);
    REQUIRE_FALSE(game_notes.empty());
    CHECK(game_notes.back().error);
    CHECK(game_notes.back().text.find("live edit refused") == 0);
    CHECK(edits.refused() == 1);

    auto moved = r.level;
    moved.entities.back().position = Vec3(0, 0, -20);
    server->send(live::FrameType::Level, level::save_level_string(moved));
    auto edit = pump(0.2);
    REQUIRE(edit);
    CHECK(edit->level.entities.back().position.z == -20.0f);
    REQUIRE(answers.size() == 2);
    CHECK(answers[1].type == live::FrameType::Applied);
    CHECK(answers[1].payload.find("kept their state") != std::string::npos);
    CHECK(edits.applied() == 1);
}

TEST_CASE("a live edit that leaves the scenery alone keeps the view's scene; a moved wall builds it again") {
    Running r;
    add_robot(r.level, Vec3(10, 0, 10)).name = "Robot";
    r.level.add(level::EntityType::TopLight, Vec3(0, 8, 0), "Lamp");
    r.game = make_game(r.level);
    run_for(*r.game, 0.1);
    auto apply = [&](const level::Level& edited) {
        auto edit = runtime::apply_live_level(level::save_level_string(edited), *r.game, r.level, {});
        REQUIRE(edit);
        return edit->scenery_changed;
    };
    auto find = [](level::Level& lv, const char* name) -> level::Entity& {
        for (auto& e : lv.entities)
            if (e.name == name) return e;
        FAIL("no entity " << name);
        return lv.entities.front();
    };
    SUBCASE("a moved robot, a renamed wall, a new link, a switched light, gravity: the scene is kept") {
        auto edited = r.level;
        find(edited, "Robot").position = Vec3(-12, 0, 4);
        CHECK_FALSE(apply(edited));
        find(edited, "Wall").name = "North wall";
        edited.links.push_back(game_test::link("on_start", "Lamp", "off"));
        find(edited, "Lamp").as<level::TopLightProps>().light.on = false;
        edited.settings.gravity = -30.0f;
        add_robot(edited, Vec3(5, 0, 5));
        CHECK_FALSE(apply(edited));
    }
    SUBCASE("a moved wall, a moved or brighter light, the sun: the scene is built again") {
        auto wall = r.level;
        find(wall, "Wall").position.z = -14.0f;
        CHECK(apply(wall));
        auto moved_lamp = r.level;
        find(moved_lamp, "Lamp").position.x = 3.0f;
        CHECK(apply(moved_lamp));
        auto brighter = r.level;
        find(brighter, "Lamp").as<level::TopLightProps>().light.intensity = 2.0f;
        CHECK(apply(brighter));
        auto sun = r.level;
        sun.settings.sun_intensity = 0.5f;
        CHECK(apply(sun));
        auto removed = r.level;
        std::erase_if(removed.entities, [](const level::Entity& e) { return e.name == "Wall"; });
        CHECK(apply(removed));
    }
}

// The walkthrough, scripted: play lockdown.json (the bot), break when the hall trigger fires, move
// the west pen's spawner in the level, resume: the trigger's waiting spawns still run, the west pen's wave
// comes from its new place and the east pen's from where it was.
TEST_CASE("lockdown walkthrough: break at the hall trigger, move a spawner, the wave comes from there") {
    auto level = level::load_level_file(test::source_dir() / "levels" / "lockdown.json");
    REQUIRE(level.ok());
    auto id_of = [&](const char* name) {
        for (const auto& e : level->entities)
            if (e.name == name) return e.id;
        FAIL("no entity " << name);
        return 0;
    };
    const int hall = id_of("Hall entry"), west = id_of("West_pen");
    auto created = game::Game::create(*level, {});
    REQUIRE(created.ok());
    std::unique_ptr<game::Game> g = std::move(*created);
    auto bot = game::Autoplay::create(*level, *g, 1);
    REQUIRE(bot.ok());
    runtime::LogicDebugger debugger;
    debugger.reset(*level, g->settings().step);
    debugger.set_break(runtime::LogicBreak{level::LinkEvent::OnEnter, hall});
    for (int i = 0; i < 120 * 60 && !debugger.halted(); ++i) {
        if (!debugger.may_step()) break;
        g->step(bot->decide(*g));
        debugger.after_step(*g);
    }
    REQUIRE(debugger.halted());
    REQUIRE(g->logic().pending().size() >= 2); // the pens' spawns wait (1 s and 2 s)

    auto edited = *level;
    const Vec3 new_place(-18.0f, 0.0f, 10.0f);
    edited.find(west)->position = new_place;
    const Vec3 east_place = edited.find(id_of("East_pen"))->position;
    auto edit = runtime::apply_live_level(level::save_level_string(edited), *g, *level, {});
    REQUIRE(edit);
    CHECK_FALSE(edit->scenery_changed);
    g = std::move(edit->rebuild.game);
    debugger.reset(edit->level, g->settings().step);
    debugger.resume();

    std::vector<Vec3> spawned;
    for (int i = 0; i < 120 * 4; ++i) {
        REQUIRE(debugger.may_step());
        g->step({});
        debugger.after_step(*g);
        for (const game::Event& e : g->events())
            if (e.type == game::EventType::RobotSpawned) spawned.push_back(e.position);
    }
    REQUIRE(spawned.size() >= 2);
    auto near = [](Vec3 a, Vec3 b) { return glm::length(Vec2(a.x - b.x, a.z - b.z)) < 5.5f; };
    CHECK(near(spawned[0], new_place)); // West_pen's spawn is due 1 s after the trigger, East_pen's 2 s
    CHECK(std::any_of(spawned.begin(), spawned.end(), [&](Vec3 p) { return near(p, east_place); }));
    CHECK(std::none_of(spawned.begin(), spawned.end(),
                       [&](Vec3 p) { return near(p, Vec3(-18.0f, 0.0f, -16.0f)); }));
}
