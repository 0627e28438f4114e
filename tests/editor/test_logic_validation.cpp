// The level logic's validation rules in the editor: each fires on the bad case and not on the good one, names
// its culprit (entity, or the owner and link), and its quick fix -- where it has one -- makes it go away in
// one undo step; `fix RULE` in scripts runs them.
#include "editor_test_util.h"
#include "model/edit_entities.h"
#include "model/edit_logic.h"
#include "model/edit_selection.h"
#include "model/edit_transforms.h"
#include "model/logic_validation.h"
#include "model/quick_fix.h"
#include "model/script.h"

using namespace ks;
using namespace ks::editor;
using namespace ks::editor_test;
using level::EntityType;

namespace {

// kTwoRoomScript: the door between the rooms, the robot in the far room, the control panel (completing the
// objective "shutdown"). The player starts in the near room (z > 0), the robot stands in the far one (z < 0).

Result<ScriptReport> run_rules(Editor& ed, const std::string& text) {
    return run_script_text(text, "logic_rules.kss", {}, ed);
}

void run_ok(Editor& ed, const std::string& text) {
    auto r = run_rules(ed, text);
    REQUIRE_MESSAGE(r.ok(), (r.ok() ? std::string() : r.error().str()));
}

std::vector<Issue> issues_of(Editor& ed, Rule rule) {
    std::vector<Issue> out;
    for (const Issue& issue : ed.issues())
        if (issue.rule == rule) out.push_back(issue);
    return out;
}

level::Link rule_link(std::string event, std::string target, std::string action, float delay = 0) {
    return {std::move(event), std::move(target), std::move(action), delay, false};
}

// Applies the only issue of `rule`'s quick fix: one undo step that makes the issue go away, and undo brings
// it back.
void fix_in_one_step(Editor& ed, Rule rule) {
    auto issues = issues_of(ed, rule);
    REQUIRE(issues.size() == 1);
    const size_t steps = ed.history().undo_count();
    const std::string before = text_of(ed);
    REQUIRE_MESSAGE(apply_quick_fix(ed, issues.front()).ok(), issues.front().fix.label);
    CHECK(ed.history().undo_count() == steps + 1);
    CHECK(issues_of(ed, rule).empty());
    REQUIRE(ed.undo());
    CHECK(text_of(ed) == before);
    CHECK(issues_of(ed, rule).size() == 1);
    REQUIRE(ed.redo());
}

} // namespace

TEST_CASE("link_target: a link naming nothing is retargeted to the did-you-mean name, else removed") {
    Editor ed = two_rooms();
    const int trigger = *place(ed, EntityType::Trigger, {0, 0, 10}, 0, "Entry");
    REQUIRE(link_add(ed, LinkOwner::entity(trigger), rule_link("on_enter", "Door", "open")).ok());
    CHECK(issues_of(ed, Rule::LinkTarget).empty()); // the good case

    REQUIRE(link_set(ed, LinkOwner::entity(trigger), 0, rule_link("on_enter", "Dor", "open")).ok());
    auto issues = issues_of(ed, Rule::LinkTarget);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].severity == IssueSeverity::Error);
    CHECK(issues[0].entity_id == trigger);
    CHECK(issues[0].owner == LinkOwner::entity(trigger));
    CHECK(issues[0].link_index == 0);
    CHECK(issues[0].message.find("no entity named \"Dor\"") != std::string::npos);
    CHECK(issues[0].fix.is<fixes::SetLink>());
    CHECK(issues[0].fix.label == "Retarget to \"Door\"");
    for (const Issue& issue : ed.issues()) CHECK(issue.rule != Rule::Format); // not reported twice
    REQUIRE(select_issue(ed, issues[0]).ok());
    CHECK(ed.doc().selection == std::vector<int>{trigger});
    fix_in_one_step(ed, Rule::LinkTarget);
    CHECK(links_of(ed, LinkOwner::entity(trigger))->at(0) == rule_link("on_enter", "Door", "open"));

    // Nothing close: the fix removes the link. On the level's own links: no entity to select.
    REQUIRE(link_add(ed, LinkOwner::level(), rule_link("on_start", "Zebra", "open")).ok());
    issues = issues_of(ed, Rule::LinkTarget);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].entity_id == 0);
    CHECK(issues[0].owner == LinkOwner::level());
    CHECK(issues[0].fix.is<fixes::RemoveLink>());
    fix_in_one_step(ed, Rule::LinkTarget);
    CHECK(ed.level().links.empty());

    // A win link must name the level.
    REQUIRE(link_add(ed, LinkOwner::entity(trigger), rule_link("on_exit", "Door", "win")).ok());
    issues = issues_of(ed, Rule::LinkTarget);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].fix.label == "Retarget to \"level\"");
    fix_in_one_step(ed, Rule::LinkTarget);
}

TEST_CASE("link_target: kill-list names and links to a deleted entity") {
    Editor ed = two_rooms();
    REQUIRE(rename(ed, kRobot, "Guard").ok());
    REQUIRE(objective_add(ed, {"clear", "Kill the guard", {"Gaurd"}, {}}).ok());
    auto issues = issues_of(ed, Rule::LinkTarget);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].owner == LinkOwner::objective("clear"));
    CHECK(issues[0].fix.is<fixes::SetKillName>());
    fix_in_one_step(ed, Rule::LinkTarget);
    CHECK(ed.level().objectives[1].kill == std::vector<std::string>{"Guard"});

    // Deleting the door leaves the panel's link naming nothing, and nothing else takes "open": removed.
    REQUIRE(link_add(ed, LinkOwner::entity(kPanel), rule_link("on_use", "Door", "open")).ok());
    REQUIRE(delete_entities(ed, {kDoor}).ok());
    issues = issues_of(ed, Rule::LinkTarget);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].entity_id == kPanel);
    CHECK(issues[0].fix.is<fixes::RemoveLink>());
    // Deleting the guard too: its kill-list name goes.
    REQUIRE(delete_entities(ed, {kRobot}).ok());
    run_ok(ed, "fix link_target\nexpect no_issue link_target\n");
    CHECK(ed.level().find(kPanel)->links == std::vector{rule_link("on_use", "shutdown", "complete")});
    CHECK(ed.level().objectives[1].kill.empty());
}

TEST_CASE("logic_loop: two doors toggling each other with no delay; the fix delays the first link") {
    Editor ed = two_rooms();
    const int other = *place(ed, EntityType::Door, {0, 0, 30}, 0, "Other");
    REQUIRE(link_add(ed, LinkOwner::entity(kDoor), rule_link("on_open", "Other", "toggle", 0.5f)).ok());
    REQUIRE(link_add(ed, LinkOwner::entity(other), rule_link("on_open", "Door", "toggle")).ok());
    CHECK(issues_of(ed, Rule::LogicLoop).empty()); // a delay breaks the loop

    REQUIRE(link_set(ed, LinkOwner::entity(kDoor), 0, rule_link("on_open", "Other", "toggle")).ok());
    auto issues = issues_of(ed, Rule::LogicLoop);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].severity == IssueSeverity::Warning);
    CHECK(issues[0].entity_id == kDoor);
    CHECK(issues[0].link_index == 0);
    CHECK(issues[0].fix.label == "Delay this link by 0.1 s");
    fix_in_one_step(ed, Rule::LogicLoop);
    CHECK(ed.level().find(kDoor)->links[0].delay == kLoopBreakDelay);
    CHECK(ed.level().find(kDoor)->links[0].action == "toggle");
    REQUIRE(ed.undo());
    run_ok(ed, "expect issue logic_loop 9\nfix logic_loop\nexpect no_issue logic_loop\n"
               "expect link 9 1 on_open Other toggle delay 0.1\n");
}

TEST_CASE("objective: one nothing can complete gets an on_use -> complete link on the control panel") {
    Editor ed = two_rooms();
    CHECK(issues_of(ed, Rule::Objective).empty()); // the panel completes "shutdown"
    REQUIRE(rename(ed, kRobot, "Guard").ok());
    REQUIRE(objective_add(ed, {"clear", "Kill the guard", {"Guard"}, {}}).ok());
    CHECK(issues_of(ed, Rule::Objective).empty()); // completed by the kill list

    REQUIRE(objective_add(ed, {"escape", "Escape", {}, {}}).ok());
    auto issues = issues_of(ed, Rule::Objective);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].owner == LinkOwner::objective("escape"));
    CHECK(issues[0].entity_id == 0);
    CHECK(issues[0].message.find("can never be won") != std::string::npos);
    CHECK(issues[0].fix.is<fixes::AddLink>());
    fix_in_one_step(ed, Rule::Objective);
    CHECK(ed.level().find(kPanel)->links == std::vector{rule_link("on_use", "shutdown", "complete"),
                                                        rule_link("on_use", "escape", "complete")});

    // Without a control panel there is nothing to add the link to: no fix, and `fix objective` leaves them.
    REQUIRE(delete_entities(ed, {kPanel}).ok());
    issues = issues_of(ed, Rule::Objective);
    REQUIRE(issues.size() == 2); // shutdown and escape
    CHECK(!issues[0].fix.available());
    run_ok(ed, "fix objective\nexpect issue objective\nexpect no_issue control_panel\n");

    // A spawner nothing starts: reported on the kill-list name, no fix (the hint says what to add).
    const int spawner = *place(ed, EntityType::Spawner, {0, 0, -10}, 0, "Wave");
    REQUIRE(objective_remove(ed, 2).ok());
    REQUIRE(objective_set(ed, 0, {"shutdown", "Beat the wave", {"Wave"}, {}}).ok());
    issues = issues_of(ed, Rule::Objective);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].message.find("never spawns") != std::string::npos);
    CHECK(!issues[0].fix.available());
    const int trigger = *place(ed, EntityType::Trigger, {0, 0, 10}, 0, "Entry");
    REQUIRE(link_add(ed, LinkOwner::entity(trigger), rule_link("on_enter", "Wave", "spawn")).ok());
    CHECK(issues_of(ed, Rule::Objective).empty());
    CHECK(ed.level().find(spawner) != nullptr);
}

TEST_CASE(
    "objective: a chain of links that breaks two links before the objective is named; fixed at the panel") {
    Editor ed = two_rooms();
    const int trigger = *place(ed, EntityType::Trigger, {0, 0, 10}, 0, "Latch");
    REQUIRE(select(ed, {trigger}).ok());
    REQUIRE(set_field(ed, "enabled", FieldValue(false)).ok());
    // The latch completes "escape"; only the far room's robot dying after a spawn enables it, and nothing
    // spawns.
    const int spawner = *place(ed, EntityType::Spawner, {0, 0, -10}, 0, "Wave");
    REQUIRE(link_add(ed, LinkOwner::entity(trigger), rule_link("on_enter", "escape", "complete")).ok());
    REQUIRE(objective_add(ed, {"escape", "Escape", {}, {}}).ok());
    REQUIRE(objective_add(ed, {"wave", "Beat the wave", {"Wave"}, {}}).ok());
    REQUIRE(link_add(ed, LinkOwner::objective("escape"), rule_link("on_complete", "Wave", "spawn")).ok());
    REQUIRE(link_add(ed, LinkOwner::entity(kRobot), rule_link("on_death", "Latch", "enable")).ok());
    CHECK(issues_of(ed, Rule::TriggerReach).empty());
    CHECK(issues_of(ed, Rule::Objective).empty()); // the robot can die: the chain holds
    // The robot's enabling link is taken back: the latch can never fire, so neither objective can complete.
    REQUIRE(link_remove(ed, LinkOwner::entity(kRobot), 0).ok());
    auto issues = issues_of(ed, Rule::Objective);
    REQUIRE(issues.size() == 2);
    CHECK(issues[0].owner == LinkOwner::objective("escape"));
    CHECK(
        issues[0].message.find("trigger \"Latch\" starts disabled and nothing that can happen enables it") !=
        std::string::npos);
    CHECK(issues[1].owner == LinkOwner::objective("wave"));
    CHECK(issues[1].message.find("spawner \"Wave\" never spawns (the link that spawns it never fires: "
                                 "objective \"escape\" never completes)") != std::string::npos);
    // Completing "escape" at the control panel frees both.
    REQUIRE(apply_quick_fix(ed, issues[0]).ok());
    CHECK(issues_of(ed, Rule::Objective).empty());
    CHECK(ed.level().find(spawner) != nullptr);
}

TEST_CASE("objective: a level with no objectives and no win link can never be won; the fix adds shutdown") {
    Editor ed = two_rooms();
    REQUIRE(objective_remove(ed, 0).ok());
    REQUIRE(link_remove(ed, LinkOwner::entity(kPanel), 0).ok());
    auto issues = issues_of(ed, Rule::Objective);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].message.find("no objectives and no link wins it") != std::string::npos);
    CHECK(issues[0].fix.is<fixes::AddShutdownObjective>());
    fix_in_one_step(ed, Rule::Objective);
    REQUIRE(ed.level().objectives.size() == 1);
    CHECK(ed.level().objectives[0].id == "shutdown");
    CHECK(ed.level().find(kPanel)->links == std::vector{rule_link("on_use", "shutdown", "complete")});

    // A win link is enough; without a panel there is nothing to fix with, and the panel is missed again.
    REQUIRE(ed.undo());
    const int trigger = *place(ed, EntityType::Trigger, {0, 0, -10}, 0, "Exit");
    REQUIRE(link_add(ed, LinkOwner::entity(trigger), rule_link("on_enter", "level", "win")).ok());
    CHECK(issues_of(ed, Rule::Objective).empty());
    REQUIRE(link_remove(ed, LinkOwner::entity(trigger), 0).ok());
    REQUIRE(delete_entities(ed, {kPanel}).ok());
    issues = issues_of(ed, Rule::Objective);
    REQUIRE(issues.size() == 1);
    CHECK(!issues[0].fix.available());
    CHECK(issues_of(ed, Rule::ControlPanel).size() == 1);
    CHECK_FALSE(add_shutdown_objective(ed).ok());
}

TEST_CASE("locked_door: a locked door nothing frees is unlocked by the fix") {
    Editor ed = two_rooms();
    REQUIRE(select(ed, {kDoor}).ok());
    REQUIRE(set_field(ed, "locked", FieldValue(true)).ok());
    auto issues = issues_of(ed, Rule::LockedDoor);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].entity_id == kDoor);
    CHECK(issues[0].fix.label == "Unlock the door");
    fix_in_one_step(ed, Rule::LockedDoor);
    CHECK_FALSE(ed.level().find(kDoor)->as<level::DoorProps>().locked);

    // Locked, but the robot's death unlocks it: the good case.
    REQUIRE(ed.undo());
    REQUIRE(link_add(ed, LinkOwner::entity(kRobot), rule_link("on_death", "Door", "unlock")).ok());
    CHECK(issues_of(ed, Rule::LockedDoor).empty());
    run_ok(ed, "link 10 remove 1\nexpect issue locked_door 9\nfix locked_door\nexpect no_issue locked_door\n"
               "expect field 9 locked false\n");
}

TEST_CASE("trigger_reach: a trigger the player or the robots can never walk into") {
    Editor ed = two_rooms();
    const int near = *place(ed, EntityType::Trigger, {0, 0, 10}, 0, "Near");     // the player's room
    const int behind = *place(ed, EntityType::Trigger, {0, 0, -6}, 0, "Behind"); // past the (closed) door
    CHECK(issues_of(ed, Rule::TriggerReach).empty());

    // Out of the level, and hanging above the floor (the body's 3 units do not reach a box 5 units up).
    const int outside = *place(ed, EntityType::Trigger, {60, 0, 60}, 0, "Outside");
    const int high = *place(ed, EntityType::Trigger, {0, 5, 10}, 0, "High");
    auto issues = issues_of(ed, Rule::TriggerReach);
    REQUIRE(issues.size() == 2);
    CHECK(issues[0].entity_id == outside);
    CHECK(issues[1].entity_id == high);
    CHECK(issues[0].message.find("the player cannot walk into its box") != std::string::npos);
    CHECK(!issues[0].fix.available());
    // Lowered to 2 units up, the box meets the player's body (3 units tall) again.
    REQUIRE(select(ed, {high}).ok());
    REQUIRE(move_selection(ed, {0, -3, 0}).ok());
    CHECK(issues_of(ed, Rule::TriggerReach).size() == 1);

    // An island of floor nobody walks to: robots cannot set it off either, until a robot stands there.
    run_ok(ed, "place floor at 60,0,60\nset size 10,10\nselect " + std::to_string(outside) +
                   "\nset who robots\nexpect issue trigger_reach " + std::to_string(outside) + "\n");
    issues = issues_of(ed, Rule::TriggerReach);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].message.find("no robot can walk into its box") != std::string::npos);
    const int guard = *place(ed, EntityType::Robot, {62, 0, 62});
    CHECK(issues_of(ed, Rule::TriggerReach).empty());
    REQUIRE(select(ed, {near}).ok());
    REQUIRE(
        set_field(ed, "who", FieldValue(std::string("robots"))).ok()); // the robots reach the near room too
    CHECK(issues_of(ed, Rule::TriggerReach).empty());
    REQUIRE(select(ed, {behind}).ok());
    REQUIRE(set_field(ed, "who", FieldValue(std::string("both"))).ok());
    CHECK(issues_of(ed, Rule::TriggerReach).empty());
    REQUIRE(delete_entities(ed, {guard}).ok());
    CHECK(issues_of(ed, Rule::TriggerReach).size() == 1);
}

TEST_CASE("trigger_reach: checked without a control panel, and answered off the UI thread in the window") {
    Editor ed = two_rooms();
    REQUIRE(delete_entities(ed, {kPanel}).ok());
    const int outside = *place(ed, EntityType::Trigger, {60, 0, 60}, 0, "Outside");
    REQUIRE(issues_of(ed, Rule::TriggerReach).size() == 1);

    Editor window = two_rooms();
    window.validation_options().background_reachability = true;
    const int trigger = *place(window, EntityType::Trigger, {60, 0, 60}, 0, "Outside");
    (void)window.issues(); // starts the walk check in the background
    window.validation().wait_for_reachability();
    auto issues = issues_of(window, Rule::TriggerReach);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].entity_id == trigger);
    // Triggers do not shape the mesh: moving one is answered again at once, without a new walk check.
    const size_t checks = window.validation().walk_checks_run();
    REQUIRE(select(window, {trigger}).ok());
    REQUIRE(move_selection(window, {-60, 0, -50}).ok());
    CHECK(issues_of(window, Rule::TriggerReach).empty());
    CHECK_FALSE(window.validation().reachability_pending());
    CHECK(window.validation().walk_checks_run() == checks);
    CHECK(outside == trigger);
}
