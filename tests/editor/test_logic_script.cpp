// The script language's level-logic lines: name, link, objective and their expectations drive the Editor's
// logic edits (one undo step per line); parse errors name file:line:column with a did-you-mean for event and
// action names; run-time refusals name the line and what is wrong.
#include "editor_test_util.h"

#include "model/script.h"

using namespace ks;
using namespace ks::editor;
using namespace ks::editor_test;

namespace {

// kTwoRoomScript's door, robot and panel ids; the script below places the trigger and the message after them.
constexpr int kTrigger = 14, kMessage = 15; // added to kTwoRoomScript by the tests

Result<ScriptReport> run_logic(Editor& ed, const std::string& text) {
    return run_script_text(text, "logic.kss", {}, ed);
}

std::string parse_errors(const std::string& text) {
    auto parsed = parse_script(text, "levels/logic.kss");
    REQUIRE_FALSE(parsed.ok());
    return parsed.error().str();
}

const char* kLogicScript = R"(# the guard is dormant until the player walks in; killing it unlocks the door
place trigger at 0,0,12 name Entry
place message at 0,0,14 name Hint
set text The door unlocks when the guard is down
name 10 Guard
select 10
set dormant true
select 9
set locked true
link 14 add on_enter Guard activate
link 14 add on_enter Hint show delay 0.5 once
link 10 add on_death Door unlock
objective add clear Kill the guard
objective clear kill Guard
link objective:clear add on_complete Door open delay 1
link level add on_start Hint show
expect links 14 2
expect link 14 2 on_enter Hint show delay 0.5 once
expect link objective:clear 1 on_complete Door open delay 1
expect links level 1
expect objectives 2
)";

} // namespace

TEST_CASE("logic script: builds a level's links and objectives, every line one undo step") {
    Editor ed = two_rooms();
    const size_t steps = ed.history().undo_count();
    auto r = run_logic(ed, kLogicScript);
    REQUIRE_MESSAGE(r.ok(), (r.ok() ? std::string() : r.error().str()));
    CHECK(r->expectations_checked == 5);
    // 2 places, 1 set text, 1 name, 2 selects (no step), 2 sets, 5 links, 1 objective add, 1 kill list
    CHECK(ed.history().undo_count() == steps + 2 + 1 + 1 + 2 + 5 + 2);
    const level::Level& level = ed.level();
    REQUIRE(level.find(kTrigger)->type() == level::EntityType::Trigger);
    REQUIRE(level.find(kMessage)->type() == level::EntityType::Message);
    CHECK(level.find(kRobot)->name == "Guard");
    REQUIRE(level.objectives.size() == 2); // the two-room level's shutdown, then clear
    CHECK(level.objectives[1].kill == std::vector<std::string>{"Guard"});
    CHECK(level.find(kPanel)->links ==
          std::vector<level::Link>{{"on_use", "shutdown", "complete", 0, false}});
    CHECK(level.find(kDoor)->as<level::DoorProps>().locked);

    // The level's logic is sound: no format errors and no logic warnings.
    for (const Issue& issue : ed.issues()) {
        INFO(issue.message);
        CHECK(issue.rule != Rule::Format);
    }
    // Saved and loaded, it is the same level.
    auto reloaded = level::load_level_string(text_of(ed), "logic.json");
    REQUIRE_MESSAGE(reloaded.ok(), (reloaded.ok() ? std::string() : reloaded.error().str()));
    CHECK(*reloaded == ed.level());
}

TEST_CASE("logic script: set, remove, text, kill, move and remove objectives; undo and redo") {
    Editor ed = two_rooms();
    REQUIRE(run_logic(ed, kLogicScript).ok());
    const std::string built = text_of(ed);
    auto r = run_logic(ed, R"(link 14 set 2 delay 2.5
link 14 set 2 once false
link 14 set 1 event on_exit
link 14 set 1 action show
link 14 set 1 target Hint
expect link 14 1 on_exit Hint show
expect link 14 2 on_enter Hint show delay 2.5
link 14 remove 1
expect links 14 1
expect link 14 1 on_enter Hint show delay 2.5
objective clear text Kill every guard
objective clear kill
objective clear move 1
expect objectives 2
objective clear remove
expect objectives 1
name 9 Vault_door
expect link 10 1 on_death Vault_door unlock
)");
    REQUIRE_MESSAGE(r.ok(), (r.ok() ? std::string() : r.error().str()));
    CHECK(ed.level().objectives.size() == 1);
    CHECK(ed.level().objectives[0].id == "shutdown");
    CHECK(ed.level().find(kRobot)->links[0].target == "Vault_door");
    auto back =
        run_logic(ed, "undo 11\nexpect objectives 2\nexpect link objective:clear 1 on_complete Door open "
                      "delay 1\nexpect links 14 2\n");
    REQUIRE_MESSAGE(back.ok(), (back.ok() ? std::string() : back.error().str()));
    CHECK(text_of(ed) == built);
    REQUIRE(run_logic(ed, "redo all\nexpect objectives 1\n").ok());
}

TEST_CASE("logic script: parse errors name file:line:column, with did-you-mean for events and actions") {
    const std::string all = parse_errors("link 3 add on_entr Door open\n"
                                         "link 3 add on_enter Door opne\n"
                                         "link level add on_start Door open delay -1\n"
                                         "link door add on_use Door open\n"
                                         "link 3 set 0 delay 1\n"
                                         "link 3 set 1 dealy 1\n"
                                         "link 3 set 1 once maybe\n"
                                         "link 3 frob 1\n"
                                         "objective add clear\n"
                                         "objective clear move first\n"
                                         "expect links 3\n"
                                         "expect link 3 1 on_enter Door open soon\n"
                                         "name x Door\n"
                                         "link objective: add on_complete level win\n");
    INFO(all);
    CHECK(all.find("levels/logic.kss:1:12: unknown event 'on_entr'") != std::string::npos);
    CHECK(all.find("did you mean 'on_enter'?") != std::string::npos);
    CHECK(all.find("levels/logic.kss:2:26: unknown action 'opne'") != std::string::npos);
    CHECK(all.find("did you mean 'open'?") != std::string::npos);
    CHECK(all.find("levels/logic.kss:3:41: expected seconds from 0 to 3600, got '-1'") != std::string::npos);
    CHECK(all.find("levels/logic.kss:4:6: expected an entity id, level or objective:ID") !=
          std::string::npos);
    CHECK(all.find("levels/logic.kss:5:12: expected a link number (counted from 1)") != std::string::npos);
    CHECK(all.find("levels/logic.kss:6:14: unknown link field 'dealy'") != std::string::npos);
    CHECK(all.find("did you mean 'delay'?") != std::string::npos);
    CHECK(all.find("levels/logic.kss:7:19: expected true or false") != std::string::npos);
    CHECK(all.find("levels/logic.kss:8:8: unknown link command 'frob'") != std::string::npos);
    CHECK(all.find("levels/logic.kss:9:") != std::string::npos);
    CHECK(all.find("levels/logic.kss:10:22: expected a position (counted from 1)") != std::string::npos);
    CHECK(all.find("levels/logic.kss:11:") != std::string::npos);
    CHECK(all.find("levels/logic.kss:12:36: unexpected 'soon'") != std::string::npos);
    CHECK(all.find("levels/logic.kss:13:6: expected an entity id") != std::string::npos);
    CHECK(all.find("levels/logic.kss:14:6: expected an entity id, level or objective:ID") !=
          std::string::npos);
}

TEST_CASE("logic script: run-time refusals stop at their line and change nothing") {
    Editor ed = two_rooms();
    REQUIRE(run_logic(ed, kLogicScript).ok());
    const std::string before = text_of(ed);
    auto fails = [&](const std::string& line, const char* part) {
        auto r = run_logic(ed, line);
        REQUIRE_FALSE(r.ok());
        INFO(r.error().str());
        CHECK(r.error().str().find("logic.kss:1") != std::string::npos);
        CHECK(r.error().str().find(part) != std::string::npos);
        CHECK(text_of(ed) == before);
    };
    fails("link 14 add on_death Door open\n", "does not emit \"on_death\"");
    fails("link 1 add on_use Door open\n", "emits no events"); // the floor
    fails("link 99 add on_use Door open\n", "no entity with id 99");
    fails("link objective:clera add on_complete Door open\n", "no objective \"clera\"");
    fails("link 14 set 3 delay 1\n", "no link 3 on 14");
    fails("link 14 remove 5\n", "no link");
    fails("objective clera text Hi\n", "did you mean \"clear\"?");
    fails("objective add clear Again\n", "already an objective \"clear\"");
    fails("objective clear move 3\n", "no position 3");
    fails("name 99 Door\n", "no entity with id 99");
    fails("expect links 14 3\n", "14 has 2 links, expected 3");
    fails("expect link 14 1 on_enter Guard alert\n", "link 1 of 14 is 'on_enter Guard activate'");
    fails("expect link 14 5 on_enter Guard alert\n", "no link 5");
    fails("expect objectives 3\n", "the level has 2 objectives, expected 3");
}

TEST_CASE("logic script: the logic example in docs/editor.md runs on the two-room level and is sound") {
    const std::string doc = ks::test::read_file(ks::test::source_dir() / "docs" / "editor.md");
    size_t begin = doc.find("Logic example (on the two-room level");
    REQUIRE(begin != std::string::npos);
    begin = doc.find("```\n", begin);
    REQUIRE(begin != std::string::npos);
    begin += 4;
    const size_t end = doc.find("```", begin);
    REQUIRE(end != std::string::npos);
    Editor ed = two_rooms();
    auto r = run_logic(ed, doc.substr(begin, end - begin));
    REQUIRE_MESSAGE(r.ok(), (r.ok() ? std::string() : r.error().str()));
    CHECK(r->expectations_checked == 2);
    for (const Issue& issue : ed.issues()) {
        INFO(issue.message);
        CHECK(issue.rule != Rule::Format);
        CHECK(issue.rule != Rule::LinkTarget);
        CHECK(issue.rule != Rule::Objective);
        CHECK(issue.rule != Rule::LockedDoor);
        CHECK(issue.rule != Rule::TriggerReach);
    }
}
