// The game's end of the live play-test (runtime/model/live_edits.h): a level document from the editor's
// socket rebuilds the running game and is answered Applied; a document that is not JSON, or not a valid
// level, is refused with the loader's message on both sides and the game keeps its level.
#include "game/game_test_levels.h"
#include "level/level_io.h"
#include "runtime/model/live_edits.h"

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
