// The level logic in the file: links, objectives and the logic entities load, save and load back exactly;
// every bad link, objective or list gives an error that names the entity and the field, with a did-you-mean
// where a name was mistyped; huge lists are refused before they are read.
#include "level/level_io.h"
#include "level/logic_checks.h"
#include "level/shutdown_objective.h"
#include "test_support.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <limits>

using namespace ks::level;

namespace {

// A level with one of each logic-relevant entity; the trigger (entities[2], id 3) carries `trigger_links`.
std::string logic_level(const std::string& trigger_links, const std::string& level_links = "[]",
                        const std::string& objectives = "[]", const std::string& extra = "") {
    return R"({"format": "killswitch-level", "version": 2, "objectives": )" + objectives + R"(, "links": )" +
           level_links + R"(, "entities": [
  {"id": 1, "type": "floor", "name": "Ground", "position": [0, 0, 0], "props": {"size": [40, 40]}},
  {"id": 2, "type": "door", "name": "Door 2", "position": [0, 0, -5]},
  {"id": 3, "type": "trigger", "name": "Hall trigger", "position": [0, 0, 5], "links": )" +
           trigger_links + R"(},
  {"id": 4, "type": "robot", "name": "Guard", "position": [5, 0, -10]},
  {"id": 5, "type": "spawner", "name": "Hall spawner", "position": [-5, 0, -10]},
  {"id": 6, "type": "message", "name": "Alarm", "position": [0, 2, 0]},
  {"id": 7, "type": "top_light", "name": "Lamp", "position": [0, 16, 0]},
  {"id": 8, "type": "wall", "name": "Wall", "position": [0, 0, -19]},
  {"id": 9, "type": "robot", "name": "Dummy", "position": [9, 0, 9], "props": {"dummy": true}})" +
           extra + "\n]}\n";
}

std::string link(const std::string& event, const std::string& target, const std::string& action,
                 const std::string& rest = "") {
    return R"({"event": ")" + event + R"(", "target": ")" + target + R"(", "action": ")" + action + "\"" +
           rest + "}";
}

LoadReport load_report(const std::string& text, bool expect_ok) {
    LoadReport report;
    auto level = load_level_string(text, "logic.json", &report);
    CHECK_MESSAGE(level.ok() == expect_ok, report.str());
    return report;
}

// Loads `text` expecting exactly one error, and returns the report.
std::string only_error(const std::string& text) {
    const LoadReport report = load_report(text, false);
    CHECK_MESSAGE(report.error_count() == 1, report.str());
    return report.str();
}

} // namespace

TEST_CASE("links, objectives and the logic entities load, save and load back byte for byte") {
    const std::string text =
        logic_level("[" + link("on_enter", "Hall spawner", "spawn", R"(, "delay": 0.5, "once": true)") +
                        ", " + link("on_exit", "Door 2", "close") + "]",
                    "[" + link("on_start", "Alarm", "show") + "]",
                    R"([{"id": "clear", "text": "Clear the hall", "kill": ["Hall spawner", "Guard"],
             "links": [)" +
                        link("on_complete", "Door 2", "unlock") + R"(]},
            {"id": "win", "text": "Win", "links": [)" +
                        link("on_complete", "level", "win", R"(, "delay": 2)") + "]}]",
                    R"(,
  {"id": 10, "type": "control_panel", "name": "Panel", "position": [0, 0, 15], "links": [)" +
                        link("on_use", "win", "complete") + "]}");
    const LoadReport report = load_report(text, true);
    CHECK_MESSAGE(report.diagnostics.empty(), report.str());
    auto level = load_level_string(text, "logic.json");
    REQUIRE(level.ok());
    const auto& links = level->entities[2].links;
    REQUIRE(links.size() == 2);
    CHECK(links[0] == Link{"on_enter", "Hall spawner", "spawn", 0.5f, true});
    CHECK(links[1] == Link{"on_exit", "Door 2", "close", 0.0f, false}); // delay and once default
    REQUIRE(level->objectives.size() == 2);
    CHECK(level->objectives[0].kill == std::vector<std::string>{"Hall spawner", "Guard"});
    CHECK(level->objectives[1].links.front().target == "level");
    CHECK(level->links.size() == 1);

    const std::string saved = save_level_string(*level);
    CHECK(ks::test::contains_text(saved, R"("objectives": [)"));
    CHECK(ks::test::contains_text(saved, "\"delay\": 0.5,\n          \"once\": true"));
    auto back = load_level_string(saved, "saved.json");
    REQUIRE(back.ok());
    CHECK(*back == *level);
    CHECK(save_level_string(*back) == saved);
}

TEST_CASE("a level without logic saves no logic keys") {
    Level level;
    level.add(EntityType::Wall);
    const std::string saved = save_level_string(level);
    CHECK_FALSE(ks::test::contains_text(saved, "objectives"));
    CHECK_FALSE(ks::test::contains_text(saved, "links"));
    CHECK(ks::test::contains_text(saved, "\"version\": 4,"));
}

TEST_CASE(
    "a mistyped event or action gets a did-you-mean; an event the source does not emit says which it does") {
    std::string r = only_error(logic_level("[" + link("on_entre", "Door 2", "open") + "]"));
    CHECK_MESSAGE(ks::test::contains_text(r, "logic.json:4:"), r);
    CHECK_MESSAGE(ks::test::contains_text(
                      r,
                      "entities[2].links[0].event: trigger 3 (\"Hall trigger\"): unknown event \"on_entre\" "
                      "(did you mean \"on_enter\"? a trigger emits: on_enter, on_exit)"),
                  r);
    r = only_error(logic_level("[" + link("on_open", "Door 2", "open") + "]"));
    CHECK_MESSAGE(
        ks::test::contains_text(r, "trigger 3 (\"Hall trigger\"): a trigger does not emit \"on_open\""), r);
    r = only_error(logic_level("[" + link("on_enter", "Door 2", "opne") + "]"));
    CHECK_MESSAGE(ks::test::contains_text(
                      r, "entities[2].links[0].action: trigger 3 (\"Hall trigger\"): unknown action \"opne\" "
                         "(did you mean \"open\"?"),
                  r);
}

TEST_CASE("a link target that names nothing, two things or the wrong kind of thing is an error") {
    std::string r = only_error(logic_level("[" + link("on_enter", "Door 3", "open") + "]"));
    CHECK_MESSAGE(ks::test::contains_text(
                      r,
                      "entities[2].links[0].target: trigger 3 (\"Hall trigger\"): no entity named \"Door 3\" "
                      "(did you mean \"Door 2\"?"),
                  r);
    r = only_error(logic_level("[" + link("on_enter", "Lamp", "open") + "]"));
    CHECK_MESSAGE(ks::test::contains_text(
                      r, "top_light 7 (\"Lamp\") cannot \"open\" (a top light takes: on, off, toggle)"),
                  r);
    r = only_error(logic_level("[" + link("on_enter", "Door 2", "open") + "]", "[]", "[]",
                               R"(, {"id": 11, "type": "door", "name": "Door 2", "position": [9, 0, -5]})"));
    CHECK_MESSAGE(
        ks::test::contains_text(r, "\"Door 2\" names 2 entities (door 2 (\"Door 2\"), door 11 (\"Door 2\"))"),
        r);
    CHECK_MESSAGE(ks::test::contains_text(r, "must be unique"), r);
    r = only_error(logic_level("[" + link("on_enter", "Dummy", "kill") + "]"));
    CHECK_MESSAGE(ks::test::contains_text(r, "robot 9 (\"Dummy\") is an animation dummy"), r);
    r = only_error(logic_level("[" + link("on_enter", "Door 2", "win") + "]"));
    CHECK_MESSAGE(ks::test::contains_text(
                      r, "\"win\" acts on the level, not on \"Door 2\" (write \"target\": \"level\")"),
                  r);
    r = only_error(logic_level("[" + link("on_enter", "clera", "complete") + "]", "[]",
                               R"([{"id": "clear", "text": "Clear", "kill": ["Guard"]}])"));
    CHECK_MESSAGE(
        ks::test::contains_text(r, "no objective \"clera\" (did you mean \"clear\"? objectives: clear)"), r);
    // Names that are not targets may repeat (two walls called "Wall" are fine).
    load_report(logic_level("[]", "[]", "[]",
                            R"(, {"id": 11, "type": "wall", "name": "Wall", "position": [9, 0, -19]})"),
                true);
}

TEST_CASE("findings a tool can fix are tagged with their kind and the did-you-mean name") {
    auto kinds = [](const std::string& text) {
        LoadReport report;
        (void)load_level_string(text, "logic.json", &report);
        std::vector<std::pair<Diagnostic::Kind, std::string>> out;
        for (const Diagnostic& d : report.diagnostics) out.emplace_back(d.kind, d.suggestion);
        return out;
    };
    using Kind = Diagnostic::Kind;
    using Tags = std::vector<std::pair<Kind, std::string>>;
    CHECK(kinds(logic_level("[" + link("on_enter", "Door 3", "open") + "]")) ==
          Tags{{Kind::DanglingTarget, "Door 2"}});
    CHECK(kinds(logic_level("[" + link("on_enter", "Zebra", "open") + "]")) ==
          Tags{{Kind::DanglingTarget, ""}});
    CHECK(kinds(logic_level("[" + link("on_enter", "Door 2", "win") + "]")) ==
          Tags{{Kind::DanglingTarget, "level"}});
    CHECK(kinds(logic_level("[]", "[]", R"([{"id": "clear", "text": "Clear", "kill": ["Gaurd"]}])")) ==
          Tags{{Kind::DanglingTarget, "Guard"}});
    // Not a dangling name: a light cannot open. Left untagged.
    CHECK(kinds(logic_level("[" + link("on_enter", "Lamp", "open") + "]")) == Tags{{Kind::Other, ""}});
    CHECK(kinds(logic_level("[]", "[]", R"([{"id": "clear", "text": "Clear"}])")) ==
          Tags{{Kind::ObjectiveNeverCompletes, ""}});
    CHECK(kinds(logic_level("[]", "[]", "[]",
                            R"(, {"id": 11, "type": "door", "name": "Vault", "position": [9, 0, -5], )"
                            R"("props": {"locked": true}})")) == Tags{{Kind::LockedDoor, ""}});
    // A trigger with links that starts disabled, and nothing enables it: its links never fire.
    const std::string disabled_trigger =
        R"(, {"id": 12, "type": "trigger", "name": "Latch", "position": [9, 0, 5], "props": {"enabled": false}, )"
        R"("links": [{"event": "on_enter", "target": "Alarm", "action": "show"}]})";
    CHECK(kinds(logic_level("[]", "[]", "[]", disabled_trigger)) == Tags{{Kind::DisabledTrigger, ""}});
    const std::string report = load_report(logic_level("[]", "[]", "[]", disabled_trigger), true).str();
    CHECK_MESSAGE(ks::test::contains_text(report,
                                          "entities[9].props.enabled: trigger 12 (\"Latch\"): the trigger "
                                          "starts disabled and no link enables it: its links never fire"),
                  report);
    // Enabled by a link (the hall trigger's), or without links of its own: nothing to say.
    CHECK(kinds(logic_level("[" + link("on_enter", "Latch", "enable") + "]", "[]", "[]", disabled_trigger))
              .empty());
    CHECK(kinds(logic_level("[]", "[]", "[]",
                            R"(, {"id": 12, "type": "trigger", "name": "Latch", "position": [9, 0, 5], )"
                            R"("props": {"enabled": false}})"))
              .empty());
}

TEST_CASE("negative, NaN and absurd delays, and a link missing a key, are errors naming the entity") {
    std::string r =
        only_error(logic_level("[" + link("on_enter", "Door 2", "open", R"(, "delay": -1)") + "]"));
    CHECK_MESSAGE(ks::test::contains_text(
                      r, "entities[2].links[0].delay: trigger 3 (\"Hall trigger\"): delay -1 is out of range "
                         "(valid: 0 .. 3600 s"),
                  r);
    r = only_error(logic_level("[" + link("on_enter", "Door 2", "open", R"(, "delay": "nan")") + "]"));
    CHECK_MESSAGE(
        ks::test::contains_text(
            r, "entities[2].links[0].delay: trigger 3 (\"Hall trigger\"): \"nan\" is not a finite number"),
        r);
    r = only_error(logic_level("[" + link("on_enter", "Door 2", "open", R"(, "delay": 1e9)") + "]"));
    CHECK_MESSAGE(ks::test::contains_text(r, "delay 1000000000 is out of range"), r);
    r = only_error(logic_level(R"([{"event": "on_enter", "action": "open"}])"));
    CHECK_MESSAGE(
        ks::test::contains_text(
            r,
            "entities[2].links[0].target: trigger 3 (\"Hall trigger\"): missing required field \"target\""),
        r);
    r = only_error(logic_level(R"({"event": "on_enter"})"));
    CHECK_MESSAGE(ks::test::contains_text(
                      r, "entities[2].links: trigger 3 (\"Hall trigger\"): expected an array of links"),
                  r);

    // In memory (the editor's drafts): NaN and a negative delay.
    Level level = *load_level_string(logic_level("[" + link("on_enter", "Door 2", "open") + "]"), "ok.json");
    level.entities[2].links[0].delay = std::numeric_limits<float>::quiet_NaN();
    CHECK(ks::test::contains_text(
        validate(level).str(),
        "entities[2].links[0].delay: trigger 3 (\"Hall trigger\"): delay NaN is not a finite number"));
    level.entities[2].links[0].delay = -0.5f;
    CHECK(ks::test::contains_text(validate(level).str(), "delay -0.5 is out of range"));
}

TEST_CASE("links on an entity that emits no events, and events of the level and objectives") {
    const std::string wall =
        R"(, {"id": 12, "type": "wall", "name": "Talking wall", "position": [9, 0, 9], "links": [)" +
        link("on_use", "Door 2", "open") + "]}";
    std::string r = only_error(logic_level("[]", "[]", "[]", wall));
    CHECK_MESSAGE(
        ks::test::contains_text(
            r,
            "entities[9].links: wall 12 (\"Talking wall\"): a wall emits no events, so its links never fire"),
        r);
    r = only_error(logic_level("[]", "[" + link("on_enter", "Door 2", "open") + "]"));
    CHECK_MESSAGE(
        ks::test::contains_text(
            r, "links[0].event: the level: the level does not emit \"on_enter\" (the level emits: on_start)"),
        r);
    r = only_error(logic_level("[]", "[]",
                               R"([{"id": "a", "text": "A", "kill": ["Guard"], "links": [)" +
                                   link("on_start", "Door 2", "open") + "]}]"));
    CHECK_MESSAGE(
        ks::test::contains_text(
            r, "objectives[0].links[0].event: objective \"a\": an objective does not emit \"on_start\""),
        r);
}

TEST_CASE("a million links are refused at once, naming the entity and the field") {
    std::string many = "[";
    const int count = 1000000;
    many.reserve(count * 3 + 2);
    for (int i = 0; i < count; ++i) many += i ? ",{}" : "{}";
    many += "]";
    const auto start = std::chrono::steady_clock::now();
    const std::string r = only_error(logic_level(many));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK_MESSAGE(ks::test::contains_text(
                      r, "entities[2].links: trigger 3 (\"Hall trigger\"): 1000000 links; at most 64"),
                  r);
    CHECK_MESSAGE(seconds < 20.0, seconds);
    // The same for the level's and an objective's lists, and an objective's kill list.
    CHECK(ks::test::contains_text(only_error(logic_level("[]", many)),
                                  "links: the level: 1000000 links; at most 64"));
    std::string names = "[";
    for (int i = 0; i < 300; ++i) names += i ? ",\"Guard\"" : "\"Guard\"";
    names += "]";
    CHECK(ks::test::contains_text(
        only_error(logic_level("[]", "[]", R"([{"id": "a", "text": "A", "kill": )" + names + "}]")),
        "objectives[0].kill: objective \"a\": 300 names; at most 256"));
    std::string sixty_five = "[";
    for (int i = 0; i < 65; ++i) sixty_five += (i ? "," : "") + link("on_enter", "Door 2", "open");
    sixty_five += "]";
    CHECK(ks::test::contains_text(only_error(logic_level(sixty_five)), "65 links; at most 64"));
}

TEST_CASE("many dangling targets load in bounded time, every one reported") {
    std::string extra;
    std::string links = "[";
    for (int k = 0; k < 64; ++k)
        links += (k ? "," : "") + link("on_enter", "Nowhere " + std::to_string(k), "open");
    links += "]";
    for (int i = 0; i < 300; ++i)
        extra += R"(, {"id": )" + std::to_string(100 + i) + R"(, "type": "trigger", "name": "T)" +
                 std::to_string(i) + R"(", "position": [0, 0, 0], "links": )" + links + "}";
    const auto start = std::chrono::steady_clock::now();
    const LoadReport report = load_report(logic_level("[]", "[]", "[]", extra), false);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK(report.error_count() == 300 * 64);
    CHECK_MESSAGE(seconds < 20.0, seconds);
}

TEST_CASE("objectives: ids unique and present, text present, kill names robots and spawners") {
    std::string r = only_error(logic_level("[]", "[]", R"([{"id": "a", "text": "A", "kill": ["Guard"]},
                                                           {"id": "a", "text": "B", "kill": ["Guard"]}])"));
    CHECK_MESSAGE(
        ks::test::contains_text(r, "objectives[1].id: objective \"a\": duplicate objective id \"a\""), r);
    r = only_error(logic_level("[]", "[]", R"([{"text": "A", "kill": ["Guard"]}])"));
    CHECK_MESSAGE(ks::test::contains_text(r, "objectives[0].id: objective \"\": the objective has no id"), r);
    r = only_error(logic_level("[]", "[]", R"([{"id": "a", "text": "", "kill": ["Guard"]}])"));
    CHECK_MESSAGE(
        ks::test::contains_text(r, "objectives[0].text: objective \"a\": the objective has no text"), r);
    r = only_error(logic_level("[]", "[]", R"([{"id": "a", "text": "A", "kill": ["Gaurd"]}])"));
    CHECK_MESSAGE(ks::test::contains_text(
                      r, "objectives[0].kill[0]: objective \"a\": no robot or spawner named \"Gaurd\" (did "
                         "you mean \"Guard\"?"),
                  r);
    r = only_error(logic_level("[]", "[]", R"([{"id": "a", "text": "A", "kill": ["Door 2"]}])"));
    CHECK_MESSAGE(ks::test::contains_text(r, "door 2 (\"Door 2\") cannot be killed"), r);
    r = only_error(logic_level("[]", "[]", R"([{"id": "a", "text": "A", "kill": ["Dummy"]}])"));
    CHECK_MESSAGE(ks::test::contains_text(r, "an animation dummy never dies"), r);
    std::string lots = "[";
    for (int i = 0; i < 33; ++i)
        lots += (i ? "," : "") + std::string(R"({"id": "o)") + std::to_string(i) +
                R"(", "text": "T", "kill": ["Guard"]})";
    lots += "]";
    CHECK(ks::test::contains_text(only_error(logic_level("[]", "[]", lots)),
                                  "objectives: 33 objectives; at most 32"));
}

TEST_CASE(
    "design warnings: a zero-delay door loop, an objective nothing completes, a locked door nothing frees") {
    Level level;
    level.add(EntityType::Floor, {0, 0, 0}, "Ground");
    level.add(EntityType::Door, {0, 0, -5}, "A");
    level.add(EntityType::Door, {9, 0, -5}, "B");
    level.entities[1].links = {{"on_open", "B", "toggle"}};
    level.entities[2].links = {{"on_open", "A", "toggle"}, {"on_close", "A", "toggle"}};
    LoadReport report = validate(level);
    CHECK(report.error_count() == 0);
    REQUIRE_MESSAGE(report.warning_count() == 1, report.str());
    CHECK_MESSAGE(ks::test::contains_text(
                      report.str(),
                      "entities[1].links[0]: zero-delay loop of door links (\"A\" on_open -> toggle \"B\"; "
                      "\"B\" on_open -> toggle \"A\"; \"B\" on_close -> toggle \"A\")"),
                  report.str());
    // A delay, or a once link, breaks it; so does a chain that only opens.
    level.entities[1].links[0].delay = 0.5f;
    CHECK(validate(level).diagnostics.empty());
    level.entities[1].links[0] = {"on_open", "B", "toggle", 0, true};
    CHECK(validate(level).diagnostics.empty());
    level.entities[1].links[0] = {"on_open", "B", "open"};
    level.entities[2].links = {{"on_open", "A", "open"}};
    CHECK(validate(level).diagnostics.empty());
    level.entities[1].links = {{"on_open", "A", "close"},
                               {"on_close", "A", "open"}}; // a door slamming itself
    CHECK(ks::test::contains_text(
        validate(level).str(),
        "zero-delay loop of door links (\"A\" on_open -> close \"A\"; \"A\" on_close -> open \"A\")"));
    level.entities[1].links.clear();
    level.entities[2].links.clear();

    level.objectives = {{"never", "Never", {}, {}}};
    CHECK(ks::test::contains_text(
        validate(level).str(),
        "warning: objectives[0]: objective \"never\": nothing completes the objective"));
    level.add(EntityType::Spawner, {0, 0, -9}, "Sleeper");
    level.objectives = {{"wait", "Wait", {"Sleeper"}, {}}};
    CHECK(ks::test::contains_text(
        validate(level).str(),
        "objectives[0].kill[0]: objective \"wait\": spawner \"Sleeper\" never spawns"));
    level.links = {{"on_start", "Sleeper", "spawn"}};
    CHECK(validate(level).diagnostics.empty());

    level.entities[1].as<DoorProps>().locked = true;
    CHECK(ks::test::contains_text(
        validate(level).str(),
        "entities[1].props.locked: door 2 (\"A\"): the door is locked and no link unlocks or opens it"));
    level.links.push_back({"on_start", "A", "unlock", 5});
    CHECK(validate(level).diagnostics.empty());
}

TEST_CASE(
    "unwinnable by construction: every chain of links toward an objective is followed to where it breaks") {
    Level level;
    level.add(EntityType::Floor, {0, 0, 0}, "Ground");
    level.add(EntityType::ControlPanel, {0, 0, -9}, "Panel");
    level.add(EntityType::Trigger, {0, 0, 5}, "Latch");
    level.add(EntityType::Door, {9, 0, -5}, "Vault").as<DoorProps>().locked = true;
    level.add(EntityType::Spawner, {0, 0, -20}, "Hive");
    Entity& latch = level.entities[2];
    latch.as<TriggerProps>().enabled = false;
    // The objective is completed by the latch, which only the vault's opening enables; the vault is never
    // unlocked. Two links deep: the one-step checks see a link for each, so only the chain shows it.
    level.objectives = {{"escape", "Escape", {}, {}}};
    latch.links = {{"on_enter", "escape", "complete"}};
    level.entities[3].links = {{"on_open", "Latch", "enable"}};
    LoadReport report = validate(level);
    const std::string chain = "objectives[0]: objective \"escape\": the objective can never be completed, "
                              "whatever the player does: the link completing it (on_enter) never fires: "
                              "trigger \"Latch\" starts disabled and nothing that can happen enables it";
    CHECK_MESSAGE(ks::test::contains_text(report.str(), chain), report.str());
    for (const auto& d : report.diagnostics)
        if (ks::test::contains_text(d.error.str(), "can never be completed"))
            CHECK(d.kind == Diagnostic::Kind::ObjectiveNeverCompletes);
    // Unlocking the vault from the panel makes the whole chain possible.
    level.entities[1].links = {{"on_use", "Vault", "unlock"}};
    CHECK_FALSE(ks::test::contains_text(validate(level).str(), "can never be completed"));

    // A kill list waiting on a spawner whose spawn link comes from an objective that never completes.
    level.objectives = {{"first", "First", {}, {}}, {"second", "Second", {"Hive"}, {}}};
    level.objectives[0].links = {{"on_complete", "Hive", "spawn"}};
    level.entities[1].links.clear(); // the vault stays locked: "escape" is gone, "first" has no completer
    latch.links = {{"on_enter", "first", "complete"}};
    const std::string text = validate(level).str();
    CHECK_MESSAGE(ks::test::contains_text(text,
                                          "objective \"second\": the objective can never be completed, "
                                          "whatever the player does: spawner \"Hive\" never spawns (the "
                                          "link that spawns it never fires: objective \"first\" never "
                                          "completes)"),
                  text);
    CHECK(ks::test::contains_text(text, "objective \"first\": the objective can never be completed"));
    // Enabling the latch at start frees the whole chain: first, then the hive, then second.
    latch.as<TriggerProps>().enabled = true;
    CHECK_FALSE(ks::test::contains_text(validate(level).str(), "can never be completed"));

    // Without objectives, a win link whose event can never happen.
    level.objectives.clear();
    latch.as<TriggerProps>().enabled = false;
    latch.links = {{"on_enter", "level", "win"}};
    CHECK(ks::test::contains_text(validate(level).str(),
                                  "no link that wins the level can fire, so it can never be won: trigger "
                                  "\"Latch\" starts disabled"));
}

TEST_CASE(
    "migration 1 -> 2: the panel's win becomes the shutdown objective; version-1 leftovers are dropped") {
    LoadReport report;
    auto level =
        load_level_file(ks::test::data_dir() / "levels" / "good" / "version1_migration.json", &report);
    REQUIRE_MESSAGE(level.ok(), report.str());
    CHECK(report.error_count() == 0);
    REQUIRE_MESSAGE(report.warning_count() == 1, report.str());
    CHECK(ks::test::contains_text(report.str(), "version 1 -> 2"));
    REQUIRE(level->objectives.size() == 1);
    CHECK(level->objectives[0].id == kShutdownObjective);
    CHECK(level->objectives[0].text == kShutdownObjectiveText);
    CHECK(level->links.empty()); // version 1 ignored them; so does the migrated level
    CHECK(level->entities[1].links == std::vector<Link>{shutdown_link()});
    CHECK(level->entities[2].links == std::vector<Link>{shutdown_link()});
    CHECK(level->entities[3].links.empty());
    // Saved, it is a clean version-2 file that re-saves byte for byte.
    const std::string saved = save_level_string(*level);
    LoadReport again;
    auto back = load_level_string(saved, "v2.json", &again);
    REQUIRE(back.ok());
    CHECK(again.diagnostics.empty());
    CHECK(save_level_string(*back) == saved);

    // A version-1 level without a panel gets no objective (it was never won; it still is not).
    auto dojo = load_level_string(R"({"format": "killswitch-level", "version": 1, "entities": []})",
                                  "v1.json", &report);
    REQUIRE(dojo.ok());
    CHECK(dojo->objectives.empty());
}

TEST_CASE("add_shutdown_objective: once, and only where a panel can complete it") {
    Level level;
    level.add(EntityType::Wall);
    CHECK_FALSE(add_shutdown_objective(level));
    CHECK(level.objectives.empty());
    level.add(EntityType::ControlPanel, {0, 0, -5}, "Panel");
    CHECK(add_shutdown_objective(level));
    CHECK_FALSE(add_shutdown_objective(level)); // already there
    CHECK(level.objectives.size() == 1);
    CHECK(level.entities[1].links.size() == 1);
    CHECK(validate(level).diagnostics.empty());
}

TEST_CASE("a pasted entity with a bad link is refused like a file") {
    nlohmann::json json = entity_to_json(*load_level_string(logic_level("[]"), "ok.json")->find(3));
    json["links"] = nlohmann::json::array({{{"event", "on_entre"}, {"target", "x"}, {"action", "open"}}});
    LoadReport report;
    CHECK_FALSE(entity_from_json(json, "clipboard", &report).ok());
    CHECK_MESSAGE(
        ks::test::contains_text(report.str(), "unknown event \"on_entre\" (did you mean \"on_enter\"?"),
        report.str());
}

TEST_CASE(
    "the logic vocabulary: every source's events and every target's actions have names that read back") {
    for (LinkEvent e : all_events()) CHECK(event_from_name(event_name(e)) == e);
    for (LinkAction a : all_actions()) CHECK(action_from_name(action_name(a)) == a);
    CHECK_FALSE(event_from_name("on_fire"));
    CHECK(entity_takes(EntityType::Door, LinkAction::Lock));
    CHECK(entity_takes(EntityType::FloorLight, LinkAction::Toggle));
    CHECK_FALSE(entity_takes(EntityType::Wall, LinkAction::Open));
    CHECK(entity_events(EntityType::Wall).empty());
    CHECK(target_kind(LinkAction::Complete) == TargetKind::Objective);
    CHECK(target_kind(LinkAction::Lose) == TargetKind::Level);
    const Level level = *load_level_string(logic_level("[]"), "ok.json");
    const NameIndex names(level);
    CHECK(names.find("Door 2").size() == 1);
    CHECK(names.find("nobody").empty());
}
