// Every design rule: it fires on a level built to break it, names the offender, and its quick fix (where
// there is one) makes it go away. The shipped main level and the scripted two-room level pass them all.
#include "editor_test_util.h"
#include "model/edit_brushes.h"
#include "model/edit_entities.h"
#include "model/edit_layers.h"
#include "model/edit_logic.h"
#include "model/edit_patrols.h"
#include "model/edit_selection.h"
#include "model/edit_transforms.h"
#include "model/quick_fix.h"

#include "core/log.h"
#include "model/reachability.h"
#include "model/script.h"
#include "model/validation.h"

#include <cmath>

using namespace ks;
using namespace ks::editor;
using level::EntityType;

namespace {
std::string dump(const std::vector<Issue>& issues) {
    std::string s;
    for (const auto& i : issues)
        s += std::string(rule_name(i.rule)) + " #" + std::to_string(i.entity_id) + ": " + i.message + "\n";
    return s;
}

std::vector<Issue> of_rule(const std::vector<Issue>& issues, Rule rule) {
    std::vector<Issue> out;
    for (const auto& i : issues)
        if (i.rule == rule) out.push_back(i);
    return out;
}

// The two-room level of editor_test_util.h, built through the script language.
void build_two_rooms(Editor& ed) {
    auto r = run_script_text(editor_test::kTwoRoomScript, "two_rooms.kss", {}, ed);
    REQUIRE_MESSAGE(r.ok(), (r.ok() ? std::string() : r.error().str()));
}

int id_named(const Editor& ed, const std::string& name) {
    for (const auto& e : ed.level().entities)
        if (e.name == name) return e.id;
    FAIL("no entity named " << name);
    return 0;
}
// Four walls closing a 6 x 6 box around `c` on the floor: nothing inside can walk out.
void wall_in_box(Editor& ed, const Vec3& c) {
    for (const auto& [offset, size] :
         {std::pair{Vec3(0, 0, -3), Vec3(6.5f, 16, 0.5f)}, std::pair{Vec3(0, 0, 3), Vec3(6.5f, 16, 0.5f)},
          std::pair{Vec3(-3, 0, 0), Vec3(0.5f, 16, 6.5f)}, std::pair{Vec3(3, 0, 0), Vec3(0.5f, 16, 6.5f)}}) {
        REQUIRE(place(ed, EntityType::Wall, c + offset).ok());
        REQUIRE(set_field_text(ed, "size",
                               std::to_string(size.x) + "," + std::to_string(size.y) + "," +
                                   std::to_string(size.z))
                    .ok());
    }
}
} // namespace

TEST_CASE("validation: the shipped main level passes every design rule, reachability included") {
    const auto level = editor_test::load_shipped("main.json");
    auto issues = validate_design(level);
    INFO(dump(issues));
    CHECK(issues.empty());
    auto walk = walk_to_control_panel(level, {});
    CHECK(walk.decided);
    CHECK(walk.reachable);
    CHECK(walk.panel_approaches > 0);
}

TEST_CASE("validation: the scripted two-room level is valid") {
    Editor ed;
    build_two_rooms(ed);
    INFO(dump(ed.issues()));
    CHECK(ed.issues().empty());
}

TEST_CASE("rule format: range problems from the level checks point at their entity") {
    level::Level level;
    auto& robot = level.add(EntityType::Robot, {0, 0, 0});
    robot.as<level::RobotProps>().eye_radius_min = 50; // above eye_radius_max
    auto issues = of_rule(validate_design(level), Rule::Format);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].entity_id == robot.id);
    CHECK(issues[0].message.find("eye_radius_min") != std::string::npos);
}

TEST_CASE("rule player_start: floating (drop fix), outside every floor, inside a wall (push-out fix)") {
    Editor ed;
    build_two_rooms(ed);
    REQUIRE(set_player_start(ed, {{0, 2, 15}, 0}).ok());
    auto issues = of_rule(ed.issues(), Rule::PlayerStart);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].entity_id == 0);
    CHECK(issues[0].message.find("floats 2.00") != std::string::npos);
    REQUIRE(issues[0].fix.is<fixes::MovePlayerStart>());
    REQUIRE(apply_quick_fix(ed, issues[0]).ok());
    CHECK(ed.level().player_start.position == Vec3(0, 0, 15));
    CHECK(of_rule(ed.issues(), Rule::PlayerStart).empty());

    REQUIRE(set_player_start(ed, {{50, 0, 0}, 0}).ok());
    issues = of_rule(ed.issues(), Rule::PlayerStart);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].severity == IssueSeverity::Error);
    CHECK(issues[0].message.find("outside every floor") != std::string::npos);

    REQUIRE(set_player_start(ed, {{-9.5f, 0, 10}, 0}).ok()); // the west wall is at x = -10
    issues = of_rule(ed.issues(), Rule::PlayerStart);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].message.find("inside wall") != std::string::npos);
    REQUIRE(apply_quick_fix(ed, issues[0]).ok());
    CHECK(ed.level().player_start.position.x == doctest::Approx(-8.74).epsilon(0.01));
    CHECK(of_rule(ed.issues(), Rule::PlayerStart).empty());
}

TEST_CASE("rule control_panel: missing in a level without objectives is an error, extras are warnings with a "
          "delete fix") {
    Editor ed;
    build_two_rooms(ed);
    const int panel = id_named(ed, "Panel");
    REQUIRE(select(ed, {panel}).ok());
    REQUIRE(duplicate(ed, Vec3(-4, 0, 0)).ok());
    auto issues = of_rule(ed.issues(), Rule::ControlPanel);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].severity == IssueSeverity::Warning);
    CHECK(issues[0].entity_id == ed.level().next_id - 1);
    REQUIRE(apply_quick_fix(ed, issues[0]).ok());
    CHECK(of_rule(ed.issues(), Rule::ControlPanel).empty());

    // With an objective (the panel's "shutdown"), the objective rule says whether the level can be won.
    REQUIRE(delete_entities(ed, {panel}).ok());
    CHECK(of_rule(ed.issues(), Rule::ControlPanel).empty());
    CHECK(of_rule(ed.issues(), Rule::Objective).size() == 1);
    REQUIRE(objective_remove(ed, 0).ok());
    issues = of_rule(ed.issues(), Rule::ControlPanel);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].severity == IssueSeverity::Error);
    CHECK(issues[0].entity_id == 0);
    CHECK(!issues[0].fix.available());
    CHECK_FALSE(apply_quick_fix(ed, issues[0]).ok());
}

TEST_CASE("rule wall_overlap: a robot in a wall is found by its oriented box and pushed out") {
    Editor ed;
    build_two_rooms(ed);
    int robot = *place(ed, EntityType::Robot, {-9.5f, 0, 10}, 30); // turned, half inside the west wall
    auto issues = of_rule(ed.issues(), Rule::WallOverlap);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].entity_id == robot);
    CHECK(issues[0].message.find("West") != std::string::npos);
    REQUIRE(issues[0].fix.is<fixes::MoveEntity>());
    REQUIRE(apply_quick_fix(ed, issues[0]).ok());
    CHECK(ed.doc().selection == std::vector<int>{robot});
    CHECK(of_rule(ed.issues(), Rule::WallOverlap).empty());
    CHECK(ed.level().find(robot)->position.x > -9.5f);

    // Touching the wall's face is fine; a rotated control panel reaching through it is not.
    REQUIRE(select(ed, {robot}).ok());
    REQUIRE(set_field(ed, "rotation", FieldValue(Vec3(0))).ok());
    REQUIRE(set_field(ed, "position", FieldValue(Vec3(-9.75f + 0.8f, 0, 10))).ok());
    CHECK(of_rule(ed.issues(), Rule::WallOverlap).empty());
    int panel = id_named(ed, "Panel");
    REQUIRE(select(ed, {panel}).ok());
    REQUIRE(set_field(ed, "rotation", FieldValue(Vec3(90, 0, 0))).ok()); // 5.34 deep along x: fits (20 wide)
    CHECK(of_rule(ed.issues(), Rule::WallOverlap).empty());
    REQUIRE(
        set_field(ed, "position", FieldValue(Vec3(0, 0, -19))).ok()); // 1.47 half-depth: into the north wall
    issues = of_rule(ed.issues(), Rule::WallOverlap);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].entity_id == panel);
}

TEST_CASE("rule support: a point exactly on a floor brush's edge stands on it, as on a floor's box") {
    // The brief's door, dragged onto the room's outer edge (z = 11 on a floor brush spanning -11..11), was
    // "outside every floor": brush::top_at counts touching a side face as outside.
    Editor ed;
    REQUIRE(place_box_brush(ed, {-11, 0, -11}, {11, 1, 11}).ok());
    ed.grid().snap = false;
    const int on_edge = *place(ed, EntityType::Pickup, {0, 1, 11});
    const int on_corner = *place(ed, EntityType::Pickup, {-11, 1, -11});
    const int outside = *place(ed, EntityType::Pickup, {0, 1, 11.01f});
    auto issues = of_rule(ed.issues(), Rule::Support);
    INFO(dump(issues));
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].entity_id == outside);
    CHECK(issues[0].message.find("outside every floor") != std::string::npos);
    CHECK(on_edge != on_corner);
}

TEST_CASE("rule support: floating and sunk entities drop to the floor; outside every floor offers delete") {
    Editor ed;
    build_two_rooms(ed);
    ed.grid().snap = false;
    int pickup = *place(ed, EntityType::Pickup, {-5, 3, 5});
    int gas = *place(ed, EntityType::GasCylinder, {5, -0.5f, 5});
    int robot = *place(ed, EntityType::Robot, {40, 0, 0});
    auto issues = of_rule(ed.issues(), Rule::Support);
    INFO(dump(issues));
    REQUIRE(issues.size() == 3);
    CHECK(issues[0].entity_id == pickup);
    CHECK(issues[0].message.find("floats 3.00") != std::string::npos);
    CHECK(issues[0].fix.label == "Drop to floor");
    CHECK(issues[1].entity_id == gas);
    CHECK(issues[1].message.find("sunk 0.50") != std::string::npos);
    CHECK(issues[2].entity_id == robot);
    CHECK(issues[2].severity == IssueSeverity::Error);
    CHECK(issues[2].fix.is<fixes::DeleteEntity>());
    for (const auto& issue : issues) REQUIRE(apply_quick_fix(ed, issue).ok());
    CHECK(ed.level().find(pickup)->position.y == 0.0f);
    CHECK(ed.level().find(gas)->position.y == 0.0f);
    CHECK(ed.level().find(robot) == nullptr);
    CHECK(of_rule(ed.issues(), Rule::Support).empty());
    // Standing on a stair tread counts as supported.
    const auto level = editor_test::load_shipped("main.json");
    level::Level copy = level;
    auto& p = copy.add(EntityType::Pickup, {-4, 3.6f, -72.5f}); // step 6 of S1 (treads every 0.6)
    CHECK(of_rule(validate_design(copy), Rule::Support).empty());
    p.position.y = 4.5f;
    CHECK(of_rule(validate_design(copy), Rule::Support).size() == 1);
}

TEST_CASE("rule stair_slope: steeper than the character's limit, fixed by lengthening the run") {
    Editor ed;
    build_two_rooms(ed);
    int stair = *place(ed, EntityType::Stair, {0, 0, 10});
    REQUIRE(set_field_text(ed, "size", "6,6,4").ok()); // 56°
    auto issues = of_rule(ed.issues(), Rule::StairSlope);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].entity_id == stair);
    CHECK(issues[0].message.find("56.31") != std::string::npos);
    REQUIRE(apply_quick_fix(ed, issues[0]).ok());
    const Vec3 size = ed.level().find(stair)->as<level::StairProps>().size;
    CHECK(size.x == 6.0f);
    CHECK(size.y == 6.0f);
    const float slope = degrees(std::atan2(size.y, size.z));
    CHECK(slope <= CharacterLimits{}.max_slope_degrees);
    CHECK(slope > CharacterLimits{}.max_slope_degrees - 0.1f);
    CHECK(of_rule(ed.issues(), Rule::StairSlope).empty());
    REQUIRE(set_field_text(ed, "size", "6,6,12").ok()); // the reference's 26.6°
    CHECK(of_rule(ed.issues(), Rule::StairSlope).empty());
}

TEST_CASE("rule door_gap: in the open, beside one wall only, and blocked by a wall") {
    Editor ed;
    build_two_rooms(ed);
    int door = id_named(ed, "Door");
    CHECK(of_rule(ed.issues(), Rule::DoorGap).empty());
    REQUIRE(select(ed, {door}).ok());
    REQUIRE(move_selection(ed, {0, 0, 10}).ok());
    auto issues = of_rule(ed.issues(), Rule::DoorGap);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].entity_id == door);
    CHECK(issues[0].message.find("either side") != std::string::npos);
    REQUIRE(ed.undo());

    REQUIRE(delete_entities(ed, {id_named(ed, "Door east side")}).ok());
    issues = of_rule(ed.issues(), Rule::DoorGap);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].message.find("+x jamb") != std::string::npos);
    REQUIRE(ed.undo());

    // The shipped level: sliding the wall beside door 2 over the doorway.
    level::Level main = editor_test::load_shipped("main.json");
    main.find(10)->position.x += 1.0f;
    issues = of_rule(validate_design(main), Rule::DoorGap);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].entity_id == 24);
    CHECK(issues[0].message.find("blocked by wall 10") != std::string::npos);
    // A door turned with its walls (both 90°) is still in its gap.
    level::Level turned;
    auto& f = turned.add(EntityType::Floor, {0, 0, 0});
    f.as<level::FloorProps>().size = {40, 40};
    for (float z : {-6.25f, 6.25f}) {
        auto& w = turned.add(EntityType::Wall, {0, 0, z});
        w.rotation.x = 90;
        w.as<level::WallProps>().size = {7.5f, 16, 0.5f};
    }
    auto& d = turned.add(EntityType::Door, {0, 0, 0});
    d.rotation.x = 90;
    CHECK(of_rule(validate_design(turned), Rule::DoorGap).empty());
    d.rotation.x = 0; // across the wall line: no longer in the gap
    CHECK(of_rule(validate_design(turned), Rule::DoorGap).size() == 1);
}

TEST_CASE("rule reachability: a sealed room or a platform without stairs makes the panel unreachable") {
    Editor ed;
    build_two_rooms(ed);
    CHECK(of_rule(ed.issues(), Rule::Reachability).empty());
    // Seal the doorway with a wall (and remove the door, so door_gap does not mask the point).
    REQUIRE(delete_entities(ed, {id_named(ed, "Door")}).ok());
    (void)place(ed, EntityType::Wall, {0, 0, 0});
    REQUIRE(set_field_text(ed, "size", "5,16,0.5").ok());
    auto issues = of_rule(ed.issues(), Rule::Reachability);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].entity_id == id_named(ed, "Panel"));
    CHECK(issues[0].severity == IssueSeverity::Warning);

    // Main level: the health pickup's platform is reached by stair 27; put the panel there, then remove the
    // stair.
    level::Level main = editor_test::load_shipped("main.json");
    main.find(56)->position = {56, 6, -39};
    CHECK(walk_to_control_panel(main, {}).reachable);
    // The game collides with a stair as a wedge: three 2-unit steps are as walkable as ten 0.6 ones.
    main.find(27)->as<level::StairProps>().steps = 3;
    CHECK(walk_to_control_panel(main, {}).reachable);
    std::erase_if(main.entities, [](const level::Entity& e) { return e.id == 27; });
    auto walk = walk_to_control_panel(main, {});
    CHECK(walk.decided);
    CHECK_FALSE(walk.reachable);
    CHECK(walk.panel_approaches > 0); // the platform is walkable, just not from the start

    // A slab too low to walk under (headroom 2 < the player's 3) across the doorway blocks it as well.
    REQUIRE(ed.undo());
    REQUIRE(ed.undo());
    CHECK(of_rule(ed.issues(), Rule::Reachability).empty());
    int low = *place(ed, EntityType::Floor, {0, 2.5f, 0});
    REQUIRE(set_field_text(ed, "size", "20,4").ok());
    CHECK(of_rule(ed.issues(), Rule::Reachability).size() == 1);
    REQUIRE(select(ed, {low}).ok());
    // Headroom 3.6 - 0.5 thickness = 3.1: the player (3 tall, standing a skin above the floor) fits.
    REQUIRE(move_selection(ed, {0, 1.1f, 0}).ok());
    CHECK(of_rule(ed.issues(), Rule::Reachability).empty());
    REQUIRE(ed.undo()); // the move,
    REQUIRE(ed.undo()); // the size,
    REQUIRE(ed.undo()); // the slab: open again
    CHECK(of_rule(ed.issues(), Rule::Reachability).empty());
    REQUIRE(ed.redo());
    REQUIRE(ed.redo()); // the low slab is back
    CHECK(of_rule(ed.issues(), Rule::Reachability).size() == 1);

    // During a drag (open transaction) the walk check waits for the commit; other rules stay live.
    ed.begin_transaction("Drag");
    REQUIRE(select(ed, {id_named(ed, "Panel")}).ok());
    REQUIRE(move_selection(ed, {0, 3, 0}).ok());
    CHECK(of_rule(ed.issues(), Rule::Reachability).empty());
    CHECK(of_rule(ed.issues(), Rule::Support).size() == 1);
    ed.commit_transaction();
    CHECK(of_rule(ed.issues(), Rule::Reachability).size() == 1);

    // Nothing to decide without a panel (the control_panel rule reports that).
    level::Level empty;
    CHECK_FALSE(walk_to_control_panel(empty, {}).decided);
}

TEST_CASE("validation: issues are cached per revision and clicking one selects the offender") {
    Editor ed;
    build_two_rooms(ed);
    int pickup = *place(ed, EntityType::Pickup, {-5, 3, 5});
    const auto* first = &ed.issues();
    CHECK(&ed.issues() == first);
    REQUIRE(select(ed, {}).ok());
    auto issues = of_rule(ed.issues(), Rule::Support);
    REQUIRE(issues.size() == 1);
    REQUIRE(select_issue(ed, issues[0]).ok());
    CHECK(ed.doc().selection == std::vector<int>{pickup});
    // A locked offender cannot be selected or fixed.
    REQUIRE(set_locked(ed, pickup, true).ok());
    CHECK_FALSE(select_issue(ed, issues[0]).ok());
    CHECK_FALSE(apply_quick_fix(ed, issues[0]).ok());
}

TEST_CASE(
    "reachability: the default cell climbs the steepest stair the slope rule allows, and not a steeper one") {
    auto level_with_stair = [](float slope_degrees) {
        level::Level level;
        level.add(EntityType::Floor, {0, 0, 0}).as<level::FloorProps>().size = {40, 60};
        level.add(EntityType::Floor, {0, 6, -20}).as<level::FloorProps>().size = {12, 12}; // z -26..-14
        const float run = 6.0f / std::tan(radians(slope_degrees));
        auto& stair = level.add(EntityType::Stair, {0, 0, -14 + run / 2}); // top edge meets the platform
        stair.as<level::StairProps>().size = {12, 6, run};
        level.add(EntityType::ControlPanel, {0, 6, -22});
        level.player_start.position = {0, 0, 10};
        return level;
    };
    const float limit = CharacterLimits{}.max_slope_degrees;
    auto allowed = level_with_stair(limit - 0.1f);
    CHECK(of_rule(validate_design(allowed), Rule::StairSlope).empty());
    CHECK(walk_to_control_panel(allowed, {}).reachable);
    CHECK(of_rule(validate_design(allowed), Rule::Reachability).empty());
    auto steep = level_with_stair(limit + 5.0f);
    CHECK(of_rule(validate_design(steep), Rule::StairSlope).size() == 1);
    CHECK_FALSE(walk_to_control_panel(steep, {}).reachable);
}

TEST_CASE("validation: the walk check reruns only when what it reads changes, and always agrees with a "
          "fresh validation") {
    Editor ed;
    build_two_rooms(ed);
    auto same_as_fresh = [&] {
        INFO("cached:\n" << dump(ed.issues()) << "fresh:\n" << dump(validate_design(ed.level())));
        CHECK(dump(ed.issues()) == dump(validate_design(ed.level())));
    };
    same_as_fresh();
    const size_t runs = ed.validation().walk_checks_run();
    // Robots, pickups, names and lights do not block or carry the player: no new walk.
    REQUIRE(select_all_of_type(ed, EntityType::Robot) == 1);
    REQUIRE(move_selection(ed, {2, 0, 0}).ok());
    same_as_fresh();
    REQUIRE(rename(ed, id_named(ed, "Door"), "Front door").ok());
    same_as_fresh();
    (void)place(ed, EntityType::Pickup, {5, 0, 5});
    (void)place(ed, EntityType::TopLight, {0, 15, 5});
    same_as_fresh();
    CHECK(ed.validation().walk_checks_run() == runs);
    // A wall across the doorway, the panel moved, the player start moved: each reruns it.
    (void)place(ed, EntityType::Wall, {0, 0, 0});
    REQUIRE(set_field_text(ed, "size", "5,16,0.5").ok());
    same_as_fresh();
    CHECK(of_rule(ed.issues(), Rule::Reachability).size() == 1);
    CHECK(ed.validation().walk_checks_run() > runs);
    const size_t runs_sealed = ed.validation().walk_checks_run();
    REQUIRE(select(ed, {id_named(ed, "Panel")}).ok());
    REQUIRE(move_selection(ed, {1, 0, 0}).ok());
    same_as_fresh();
    CHECK(ed.validation().walk_checks_run() == runs_sealed + 1);
    REQUIRE(ed.undo());
    REQUIRE(ed.undo());
    REQUIRE(ed.undo()); // the wall is gone: reachable again
    same_as_fresh();
    CHECK(of_rule(ed.issues(), Rule::Reachability).empty());
    level::PlayerStart start = ed.level().player_start;
    start.position.z = 14;
    REQUIRE(set_player_start(ed, start).ok());
    const size_t before = ed.validation().walk_checks_run();
    same_as_fresh();
    CHECK(ed.validation().walk_checks_run() == before + 1);
}

TEST_CASE("validation: in the window the walk check runs in the background and its issue arrives when done") {
    Editor ed;
    ed.validation_options().background_reachability = true;
    build_two_rooms(ed);
    (void)ed.issues();
    ed.validation().wait_for_reachability();
    CHECK(of_rule(ed.issues(), Rule::Reachability).empty());
    // Seal the doorway: the edit returns at once; the rule's answer follows the finished check.
    (void)place(ed, EntityType::Wall, {0, 0, 0});
    REQUIRE(set_field_text(ed, "size", "5,16,0.5").ok());
    const auto& during = ed.issues();
    if (ed.validation().reachability_pending())
        CHECK(of_rule(during, Rule::Reachability).empty()); // the previous answer
    ed.validation().wait_for_reachability();
    CHECK_FALSE(ed.validation().reachability_pending());
    CHECK(of_rule(ed.issues(), Rule::Reachability).size() == 1);
    CHECK(dump(ed.issues()) == dump(validate_design(ed.level())));
    REQUIRE(ed.undo());
    REQUIRE(ed.undo());
    (void)ed.issues();
    ed.validation().wait_for_reachability();
    CHECK(of_rule(ed.issues(), Rule::Reachability).empty());
}

TEST_CASE("rule robot_reach: a robot walled off from the player's area is a warning; moving it out clears it "
          "without rebuilding the mesh") {
    Editor ed;
    build_two_rooms(ed);
    REQUIRE(of_rule(ed.issues(), Rule::RobotReach).empty());
    // A closed box of walls around a spot in the first room, and a robot inside it.
    const Vec3 c(-8, 0, 8);
    wall_in_box(ed, c);
    REQUIRE(place(ed, EntityType::Robot, c).ok());
    const int trapped = ed.doc().selection.front();
    auto issues = of_rule(ed.issues(), Rule::RobotReach);
    INFO(dump(ed.issues()));
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].entity_id == trapped);
    CHECK(issues[0].message.find("can never walk to the player's area") != std::string::npos);
    CHECK(dump(ed.issues()) == dump(validate_design(ed.level())));
    const size_t runs = ed.validation().walk_checks_run();
    REQUIRE(move_selection(ed, {0, 0, 12}).ok()); // out of the box, still in the room
    CHECK(of_rule(ed.issues(), Rule::RobotReach).empty());
    CHECK(ed.validation().walk_checks_run() == runs); // robots do not shape the mesh: no rebuild
    CHECK(dump(ed.issues()) == dump(validate_design(ed.level())));
}

TEST_CASE("rule patrol on the mesh: a point inside a prop snaps to the nearest walkable point; a point the "
          "robot can never walk to is reported") {
    Editor ed;
    build_two_rooms(ed);
    REQUIRE(place(ed, EntityType::GasCylinder, {-2, 0, 14}).ok());
    REQUIRE(place(ed, EntityType::Robot, {-8, 0, 18}).ok());
    const int robot = ed.doc().selection.front();
    REQUIRE(patrol_add(ed, robot, {-8, 0, 18}).ok());
    REQUIRE(patrol_add(ed, robot, {-2, 0, 14}).ok()); // on the floor, but inside the cylinder
    auto issues = of_rule(ed.issues(), Rule::Patrol);
    INFO(dump(ed.issues()));
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].message.find("patrol point 1 is where robots cannot walk") != std::string::npos);
    REQUIRE(issues[0].fix.is<fixes::MovePatrolPoint>());
    CHECK(dump(ed.issues()) == dump(validate_design(ed.level())));
    REQUIRE(apply_quick_fix(ed, issues[0]).ok());
    CHECK(of_rule(ed.issues(), Rule::Patrol).empty());
    const Vec3 moved = ed.level().find(robot)->as<level::RobotProps>().patrol.points[1];
    CHECK(glm::length(Vec2(moved.x + 2.0f, moved.z - 14.0f)) < 4.0f); // near where it was

    // A point inside a walled-off box: on a floor, on the mesh, but not reachable from the robot.
    const Vec3 c(-8, 0, 8);
    wall_in_box(ed, c);
    REQUIRE(patrol_add(ed, robot, c).ok());
    issues = of_rule(ed.issues(), Rule::Patrol);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].message.find("patrol point 2 cannot be walked to") != std::string::npos);
    CHECK(dump(ed.issues()) == dump(validate_design(ed.level())));
}

TEST_CASE("rule start_ambush: a robot that sees the player start and can shoot within seconds is a warning; "
          "a wall between, a dormant robot or one beyond its eye radius is not") {
    Editor ed;
    build_two_rooms(ed); // the player starts at (0, 0, 15); its robot waits behind the shut door
    CHECK(of_rule(ed.issues(), Rule::StartAmbush).empty());
    const int robot = *place(ed, EntityType::Robot, {0, 0, 9.5f}); // 5.5 units away (on the grid), in plain sight
    auto issues = of_rule(ed.issues(), Rule::StartAmbush);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].entity_id == robot);
    CHECK(issues[0].severity == IssueSeverity::Warning);
    MESSAGE(issues[0].message);
    CHECK(issues[0].message.find("5.5 units away") != std::string::npos);
    CHECK(issues[0].message.find("within 0.9 s") != std::string::npos);
    CHECK(std::string(rule_name(Rule::StartAmbush)) == "start_ambush");

    REQUIRE(set_field_text(ed, "dormant", "true").ok());
    CHECK(of_rule(ed.issues(), Rule::StartAmbush).empty());
    REQUIRE(set_field_text(ed, "dormant", "false").ok());
    REQUIRE(!of_rule(ed.issues(), Rule::StartAmbush).empty());
    REQUIRE(set_field_text(ed, "eye_radius_min", "5").ok()); // the start 5.5 away is beyond its eye
    CHECK(of_rule(ed.issues(), Rule::StartAmbush).empty());
    REQUIRE(set_field_text(ed, "eye_radius_min", "19").ok());
    REQUIRE(!of_rule(ed.issues(), Rule::StartAmbush).empty());
    REQUIRE(place(ed, EntityType::Wall, {0, 0, 12}).ok()); // a wall across the line of sight
    REQUIRE(set_field_text(ed, "size", "4,16,0.5").ok());
    CHECK(of_rule(ed.issues(), Rule::StartAmbush).empty());
}
