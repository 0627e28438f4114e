// The logic debugger's model (runtime/model/logic_debugger.h) on the game itself, without a window: the
// break halts the game after the step in which the chosen event fired, nothing runs while halted, one step
// runs exactly one game step, resume runs on; --logic-break's text and its errors.
#include "game/autoplay.h"
#include "level/level_io.h"
#include "runtime/model/logic_debugger.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <algorithm>

using namespace ks;
using namespace ks::runtime;

TEST_CASE("--logic-break takes an entity id, an event or both; anything else is an error with the fix") {
    auto both = parse_logic_break("68:on_enter");
    REQUIRE(both.ok());
    CHECK(both->entity == 68);
    CHECK(both->event == level::LinkEvent::OnEnter);
    CHECK(both->text() == "68:on_enter");
    auto event = parse_logic_break("on_death");
    REQUIRE(event.ok());
    CHECK(event->entity < 0);
    CHECK(event->event == level::LinkEvent::OnDeath);
    auto id = parse_logic_break("12");
    REQUIRE(id.ok());
    CHECK(id->entity == 12);
    CHECK_FALSE(id->event);
    for (const char* bad : {"", "x12", "12:on_fly", "0", "-3", "12:", ":on_enter", "1.5"}) {
        auto refused = parse_logic_break(bad);
        REQUIRE_MESSAGE(!refused.ok(), std::string(bad));
        CHECK(ks::test::contains_text(refused.error().str(), "--logic-break"));
        CHECK(ks::test::contains_text(refused.error().str(), "--logic-break 68:on_enter")); // the fix
    }
    CHECK(ks::test::contains_text(parse_logic_break("12:on_fly").error().str(), "on_enter"));
}

TEST_CASE("the logic debugger halts at the chosen event, steps exactly one step, and resumes") {
    auto level = level::load_level_file(ks::test::source_dir() / "levels" / "lockdown.json");
    REQUIRE(level.ok());
    const auto hall = std::find_if(level->entities.begin(), level->entities.end(),
                                   [](const level::Entity& e) { return e.name == "Hall entry"; });
    REQUIRE(hall != level->entities.end());
    auto game = game::Game::create(*level, {});
    REQUIRE(game.ok());
    game::Game& g = **game;
    auto bot = game::Autoplay::create(*level, g, 1);
    REQUIRE(bot.ok());

    LogicDebugger debugger;
    debugger.reset(*level, g.settings().step);
    debugger.set_break(LogicBreak{level::LinkEvent::OnEnter, hall->id});
    auto frame = [&] { // what the app does per fixed step
        if (!debugger.may_step()) return;
        g.step(bot->decide(g));
        debugger.after_step(g);
    };
    for (int i = 0; i < 120 * 30 && !debugger.halted(); ++i) frame();
    REQUIRE(debugger.halted());
    REQUIRE(debugger.hit());
    const game::LogicRecord hit = debugger.hit()->record;
    CHECK_FALSE(hit.is_action);
    CHECK(hit.event == level::LinkEvent::OnEnter);
    CHECK(hit.source == game::LogicEnd{game::LogicEnd::Kind::Entity, hall->id});
    CHECK(hit.step == g.steps()); // halted after the very step it fired in
    const auto records = g.logic().records();
    CHECK(std::any_of(records.begin(), records.end(), [&](const game::LogicRecord& r) {
        return !r.is_action && r.event == hit.event && r.source == hit.source;
    }));
    CHECK(debugger.hit()->line.find(" event on_enter trigger:") != std::string::npos);
    // The trigger's line starts at the trigger.
    const Vec3 at = debugger.place(hit.source, g);
    CHECK(at.x == doctest::Approx(hall->position.x));
    CHECK(at.z == doctest::Approx(hall->position.z));

    const std::int64_t halted_at = g.steps();
    for (int i = 0; i < 10; ++i) frame();
    CHECK(g.steps() == halted_at); // nothing runs while halted
    debugger.step_once();
    for (int i = 0; i < 10; ++i) frame();
    CHECK(g.steps() == halted_at + 1); // one step, however many frames follow
    CHECK(debugger.halted());
    debugger.step_once();
    frame();
    CHECK(g.steps() == halted_at + 2);

    debugger.resume();
    for (int i = 0; i < 120 * 30 && g.phase() == game::Phase::Playing; ++i) frame();
    CHECK(g.phase() == game::Phase::Won); // the halted run plays on to the bot's win
    CHECK_FALSE(debugger.halted());
    CHECK(debugger.entries().size() <= LogicDebugger::kMaxEntries);
}
