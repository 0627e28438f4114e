// The level logic's machinery: delays counted in whole steps, once links, objectives and the win, a
// zero-delay loop cut off without a hang, links an unvalidated level cannot resolve, and the logic's state
// in the state hash (the same run twice is the same hash); the logic's records and the stored trace of
// levels/lockdown.json.
#include "game/autoplay.h"
#include "game/headless.h"
#include "game/logic_trace.h"
#include "game_test_levels.h"
#include "level/level_io.h"
#include "test_support.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <sstream>

using namespace ks;
using namespace ks::game;
using namespace ks::game_test;

TEST_CASE("a delay is counted in whole steps from the event") {
    auto lv = flat_level();
    add_message(lv, "Later", "later");
    lv.links = {link("on_start", "Later", "show", 0.5f)}; // 60 steps of 1/120 s
    auto g = make_game(lv);
    g->step({}); // step 1: on_start
    for (int i = 2; i <= 60; ++i) {
        g->step({});
        REQUIRE_MESSAGE(on_screen(*g).empty(), "step ", i);
    }
    CHECK(g->logic().pending().size() == 1);
    g->step({}); // step 61
    CHECK(shown(*g, "later") == 1);
    CHECK(g->logic().pending().empty());
}

TEST_CASE("a once link fires the first time only; the others every time") {
    auto lv = flat_level();
    add_message(lv, "First", "first");
    add_message(lv, "Every", "every");
    auto& door = lv.add(level::EntityType::Door, Vec3(0, 0, -30), "Door");
    door.links = {link("on_open", "First", "show", 0.0f, true), link("on_open", "Every", "show")};
    const int id = door.id;
    auto g = make_game(lv);
    int first = 0, every = 0;
    for (int round = 0; round < 3; ++round) {
        g->step({});
        REQUIRE(g->run_action(level::LinkAction::Open, id));
        first += shown(*g, "first");
        every += shown(*g, "every");
        REQUIRE(g->run_action(level::LinkAction::Close, id));
    }
    CHECK(first == 1);
    CHECK(every == 3);
}

TEST_CASE("objectives: completed by a link or by their robots' deaths; the level is won when all are") {
    auto lv = flat_level();
    add_message(lv, "Done", "first objective done");
    for (const char* name : {"Guard A", "Guard B"}) {
        auto& r = add_robot(lv, Vec3(name[6] == 'A' ? 30.0f : -30.0f, 0, -40));
        r.name = name;
        r.as<level::RobotProps>().dormant = true;
    }
    lv.objectives = {
        {"guards", "Deal with the guards", {"Guard A", "Guard B"}, {link("on_complete", "Done", "show")}},
        {"panel", "Use the panel", {}, {}}};
    auto g = make_game(lv);
    g->step({});
    CHECK(g->logic().current_objective() == 0);
    g->damage_robot(0, 1000.0f, true);
    g->step({});
    CHECK_FALSE(g->logic().objectives()[0].completed);
    g->damage_robot(1, 1000.0f, true);
    g->step({});
    CHECK(g->logic().objectives()[0].completed);
    REQUIRE(count_events(*g, EventType::ObjectiveCompleted) == 1);
    for (const Event& e : g->events())
        if (e.type == EventType::ObjectiveCompleted) CHECK(e.cue == "guards");
    CHECK(shown(*g, "first objective done") == 1);
    CHECK(g->logic().current_objective() == 1);
    CHECK(g->phase() == Phase::Playing); // one of two is not enough
    CHECK_FALSE(g->complete_objective("nonesuch"));
    CHECK(g->complete_objective("panel"));
    CHECK(g->phase() == Phase::Won);
    CHECK(g->logic().current_objective() == -1);
}

TEST_CASE("a level without objectives is never won by them") {
    auto g = make_game(flat_level());
    run_for(*g, 0.5);
    CHECK(g->logic().objectives().empty());
    CHECK(g->phase() == Phase::Playing);
}

TEST_CASE("a zero-delay loop is cut off within its step, reported, and the game goes on") {
    // Built in code, so never validated: two doors toggling each other for ever.
    auto lv = flat_level();
    auto& a = lv.add(level::EntityType::Door, Vec3(-10, 0, -30), "A");
    a.links = {link("on_open", "B", "toggle"), link("on_close", "B", "toggle")};
    lv.add(level::EntityType::Door, Vec3(10, 0, -30), "B").links = {link("on_open", "A", "toggle"),
                                                                    link("on_close", "A", "toggle")};
    lv.links = {link("on_start", "A", "open")};
    auto g = make_game(lv);
    const auto start = std::chrono::steady_clock::now();
    g->step({});
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK(seconds < 1.0);
    CHECK(g->logic().dropped_actions() > 0);
    REQUIRE_FALSE(g->logic().problems().empty());
    CHECK(g->logic().problems().front().find("zero-delay loop") != std::string::npos);
    CHECK(count_events(*g, EventType::DoorToggled) <= LevelLogic::kMaxActionsPerStep + 1);
    run_for(*g, 0.5); // it stops: nothing queued carries it over to the next step
    CHECK(count_events(*g, EventType::DoorToggled) == 0);
    CHECK(g->logic().problems().size() == 1);
}

TEST_CASE("a loop with a delay is a timer: it keeps going, one action per delay") {
    auto lv = flat_level();
    auto& lamp = lv.add(level::EntityType::TopLight, Vec3(0, 16, 0), "Blinker");
    (void)lamp;
    auto& door = lv.add(level::EntityType::Door, Vec3(0, 0, -30), "Door");
    door.links = {link("on_open", "Door", "close", 0.25f), link("on_close", "Door", "open", 0.25f),
                  link("on_open", "Blinker", "toggle")};
    lv.links = {link("on_start", "Door", "open")};
    auto g = make_game(lv);
    int toggles = 0;
    for (int i = 0; i < 120; ++i) {
        g->step({});
        toggles += count_events(*g, EventType::LightToggled);
    }
    CHECK(toggles == 2); // opened at steps 1, 61 (closed at 31, 91)
    CHECK(g->logic().dropped_actions() == 0);
}

TEST_CASE("a positive delay shorter than half a step still waits one step: a door loop with it is a timer") {
    // 0.004 s is under half of a 1/120 s step; rounded to nearest it would be no delay, and the pair below
    // would be a zero-delay loop that the loop check (it reads the file: delay 0.004 is not 0) never warns
    // of.
    auto lv = flat_level();
    auto& door = lv.add(level::EntityType::Door, Vec3(0, 0, -30), "Door");
    door.links = {link("on_open", "Door", "close", 0.004f), link("on_close", "Door", "open", 0.004f)};
    lv.links = {link("on_start", "Door", "open")};
    auto g = make_game(lv);
    int turns = 0;
    for (int i = 0; i < 10; ++i) {
        g->step({});
        turns += count_events(*g, EventType::DoorToggled);
    }
    CHECK(g->logic().dropped_actions() == 0);
    CHECK(g->logic().problems().empty());
    CHECK(turns <= 10); // one turn a step at most, never the 1 024-action cut-off
}

TEST_CASE("links an unvalidated level cannot resolve are ignored and reported, the rest work") {
    auto lv = flat_level();
    add_message(lv, "Hello", "hello");
    lv.links = {link("on_start", "Nobody", "open"), link("on_start", "Hello", "open"),
                link("on_start", "Hello", "show"), link("on_start", "missing", "complete"),
                link("on_fire", "Hello", "show")};
    auto g = make_game(lv);
    CHECK(g->logic().links().size() == 1);
    CHECK(g->logic().problems().size() == 4);
    g->step({});
    CHECK(shown(*g, "hello") == 1);
}

TEST_CASE("the logic's state is in the state hash, and the same run twice gives the same hash") {
    auto lv = flat_level();
    add_message(lv, "Hello", "hello", 5.0f);
    auto& t = lv.add(level::EntityType::Trigger, Vec3(0, 0, -10), "Gate");
    t.links = {link("on_enter", "Hello", "show", 0.5f)};
    auto run = [&](bool disable) {
        auto g = make_game(lv, 3);
        g->step({});
        if (disable) g->run_action(level::LinkAction::Disable, t.id);
        for (int i = 0; i < 240; ++i) g->step(Input{i < 60 ? 1.0f : 0.0f});
        return g->state_hash();
    };
    const auto first = run(false);
    CHECK(run(false) == first);
    CHECK(run(true) != first);

    // A message on screen, a pending action and a trigger's occupancy each change the hash.
    auto a = make_game(lv), b = make_game(lv);
    a->step({});
    b->step({});
    REQUIRE(a->state_hash() == b->state_hash());
    b->teleport_player(Vec3(0, 0, -10), 0.0f);
    a->teleport_player(Vec3(0, 0, -10), 0.0f);
    a->step({});
    b->step({});
    REQUIRE(a->logic().pending().size() == 1);
    CHECK(a->state_hash() == b->state_hash());
    b->run_action(level::LinkAction::Show, lv.entities[1].id);
    CHECK(a->state_hash() != b->state_hash());
}

TEST_CASE(
    "the main level as version 1 (the panel wins) and as version 2 (its objective) plays the same run") {
    // Version 1 of levels/main.json: no objectives, no links; the migration gives them back.
    const std::string v2_text = ks::test::read_file(ks::test::source_dir() / "levels" / "main.json");
    auto doc = nlohmann::ordered_json::parse(v2_text);
    doc["version"] = 1;
    doc.erase("objectives");
    for (auto& e : doc["entities"]) e.erase("links");
    level::LoadReport report;
    auto v1 = level::load_level_string(doc.dump(2), "main-v1.json", &report);
    REQUIRE_MESSAGE(v1.ok(), report.str());
    auto v2 = level::load_level_string(v2_text, "main.json");
    REQUIRE(v2.ok());
    CHECK(*v1 == *v2);
    auto play = [](const level::Level& lv) {
        auto g = make_game(lv, 2);
        auto bot = Autoplay::create(lv, *g, 2);
        REQUIRE(bot.ok());
        for (int i = 0; i < 120 * 40 && g->phase() == Phase::Playing; ++i) g->step(bot->decide(*g));
        CHECK(g->phase() == Phase::Won);
        return std::pair(g->steps(), g->state_hash());
    };
    CHECK(play(*v1) == play(*v2));
}

TEST_CASE("the logic records every event and action with its step, source, target and link") {
    auto lv = flat_level();
    add_message(lv, "Hello", "hello");
    auto& t = lv.add(level::EntityType::Trigger, Vec3(0, 0, -10), "Gate");
    t.links = {link("on_enter", "Hello", "show", 0.5f)};
    const int gate = t.id, hello = lv.entities[1].id;
    auto g = make_game(lv);
    g->step({});
    REQUIRE(g->logic().records().size() == 1); // the level's on_start, with no link
    CHECK(g->logic().records()[0].source.kind == LogicEnd::Kind::Level);
    g->teleport_player(Vec3(0, 0, -10), 0.0f);
    g->step({});
    REQUIRE(g->logic().records().size() == 1); // cleared each step: only this step's on_enter
    const LogicRecord enter = g->logic().records()[0];
    CHECK_FALSE(enter.is_action);
    CHECK(enter.event == level::LinkEvent::OnEnter);
    CHECK(enter.source == LogicEnd{LogicEnd::Kind::Entity, gate});
    CHECK(enter.step == 2);
    for (int i = 0; i < 59; ++i) g->step({});
    CHECK(g->logic().records().empty());
    g->step({}); // 60 steps after the event: the delayed show
    REQUIRE(g->logic().records().size() == 1);
    const LogicRecord show = g->logic().records()[0];
    CHECK(show.is_action);
    CHECK(show.action == level::LinkAction::Show);
    CHECK(show.source == LogicEnd{LogicEnd::Kind::Entity, gate});
    CHECK(show.target == LogicEnd{LogicEnd::Kind::Entity, hello});
    CHECK(show.step == 62);
    CHECK(g->logic().links()[static_cast<std::size_t>(show.link)].action == level::LinkAction::Show);
    CHECK(logic_trace_line(show, LogicTraceNames(lv), 1.0 / 120.0) ==
          "62 0.517 action show trigger:" + std::to_string(gate) +
              ":\"Gate\" message:" + std::to_string(hello) + ":\"Hello\" 0");
    // An action run from outside the links has no source and no link.
    REQUIRE(g->run_action(level::LinkAction::Disable, gate));
    REQUIRE(g->logic().records().size() == 2);
    CHECK(g->logic().records()[1].link == -1);
    CHECK(g->logic().records()[1].source.kind == LogicEnd::Kind::None);
}

// The stored trace is what the bot's run of levels/lockdown.json with seed 1 does, event for event. When a
// change to the game, the bot or the level changes it on purpose, look at the difference, then write the new
// one with (one line):
//   build/bin/killswitch --headless --autoplay --seed 1 --level levels/lockdown.json
//       --logic-trace tests/data/logic/lockdown_seed1.trace
TEST_CASE(
    "the logic trace of levels/lockdown.json with seed 1 is the stored one; an unwritable file is an error") {
    ks::test::ScratchDir dir;
    HeadlessOptions o;
    o.level = ks::test::source_dir() / "levels" / "lockdown.json";
    o.seconds = 60.0;
    o.autoplay = true;
    o.logic_trace = dir / "lockdown.trace";
    auto stats = run_headless(o);
    REQUIRE_MESSAGE(stats.ok(), stats.error().str());
    const std::string stored = ks::test::read_file(ks::test::data_dir() / "logic" / "lockdown_seed1.trace");
    const std::string traced = ks::test::read_file(o.logic_trace);
    std::istringstream a(stored), b(traced);
    std::string want, got;
    int line = 0;
    while (std::getline(a, want)) {
        ++line;
        if (!std::getline(b, got)) got = "(the trace ends)";
        REQUIRE_MESSAGE(want == got, "line ", line, " differs: the stored trace says\n  ", want,
                        "\nthe run says\n  ", got,
                        "\n(if the change is meant, update the file: see this test's comment)");
    }
    CHECK_MESSAGE(!std::getline(b, got), "the run traces more than the stored trace: ", got);

    o.logic_trace = dir / "no_such_folder" / "run.trace";
    auto refused = run_headless(o);
    REQUIRE_FALSE(refused.ok());
    CHECK(ks::test::contains_text(refused.error().str(), (dir / "no_such_folder" / "run.trace").string()));
    CHECK(ks::test::contains_text(refused.error().str(), "cannot write the logic trace"));
}
