// Brushes as ground in the editor: the player start, robots and spawners stand on a brush's top (a ramp's
// slope included) by the support rules, a spawner in the air is flagged like a robot, and the viewport
// picks a ramp on its slope and places things on it; a door in a doorway cut through a brush wall is in its
// gap. Also the disabled-trigger quick fix.
#include "brush/brush_build.h"
#include "brush/brush_csg.h"
#include "editor_test_util.h"
#include "model/edit_entities.h"
#include "model/edit_logic.h"
#include "model/edit_selection.h"
#include "model/quick_fix.h"
#include "model/validation.h"
#include "view/picking.h"

using namespace ks;
using namespace ks::editor;
using level::EntityType;

namespace {

std::vector<Issue> issues_with(Editor& ed, Rule rule) {
    std::vector<Issue> out;
    for (const Issue& issue : ed.issues())
        if (issue.rule == rule) out.push_back(issue);
    return out;
}

// A 20 x 20 brush floor 1 thick with its top at y = 0, and a ramp 6 wide rising 4 over 8 toward -z whose
// foot is at z = 4, standing on it at x = 0.
level::Level brush_ground() {
    level::Level lv;
    auto slab = brush::make_box({-10, -1, -10}, {10, 0, 10});
    REQUIRE(slab.ok());
    lv.add(EntityType::Brush, Vec3(0), "slab").as<level::BrushProps>().brush = *slab;
    const std::vector<DVec3> profile = {{-3, 0, 4}, {-3, 0, -4}, {-3, 4, -4}};
    auto ramp = brush::make_extrusion(profile, DVec3(6, 0, 0));
    REQUIRE(ramp.ok());
    lv.add(EntityType::Brush, Vec3(0), "ramp").as<level::BrushProps>().brush = *ramp;
    lv.player_start = {{6, 0, 6}, 0};
    return lv;
}

Editor editor_on(level::Level lv) {
    Editor ed;
    ed.replace_level(std::move(lv), {}, {});
    return ed;
}

} // namespace

TEST_CASE("the player start stands on a brush floor and on a ramp's slope; floating above one is fixed") {
    Editor ed = editor_on(brush_ground());
    CHECK(issues_with(ed, Rule::PlayerStart).empty());
    REQUIRE(set_player_start(ed, {{0, 2, 0}, 0}).ok()); // on the ramp, halfway up
    CHECK(issues_with(ed, Rule::PlayerStart).empty());
    REQUIRE(set_player_start(ed, {{0, 5, 0}, 0}).ok());
    auto issues = issues_with(ed, Rule::PlayerStart);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].message.find("floats 3.00") != std::string::npos);
    REQUIRE(apply_quick_fix(ed, issues[0]).ok());
    CHECK(ed.level().player_start.position.y == doctest::Approx(2.0f));
    REQUIRE(set_player_start(ed, {{30, 0, 0}, 0}).ok());
    REQUIRE(issues_with(ed, Rule::PlayerStart).size() == 1);
    CHECK(issues_with(ed, Rule::PlayerStart)[0].message.find("outside every floor") != std::string::npos);
}

TEST_CASE("robots and spawners on a brush top are supported; a spawner in the air is flagged") {
    Editor ed = editor_on(brush_ground());
    REQUIRE(place(ed, EntityType::Robot, {6, 0, -6}).ok());
    const int spawner = *place(ed, EntityType::Spawner, {-6, 0, -6});
    CHECK_MESSAGE(issues_with(ed, Rule::Support).empty(), ed.issues().size());
    REQUIRE(select(ed, {spawner}).ok());
    REQUIRE(set_field_text(ed, "position", "-6,4,-6").ok());
    auto issues = issues_with(ed, Rule::Support);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].entity_id == spawner);
    CHECK(issues[0].message.find("spawner") != std::string::npos);
    CHECK(issues[0].message.find("floats 4.00") != std::string::npos);
}

TEST_CASE("the viewport picks a ramp on its slope and places on it, not on its box") {
    Editor ed = editor_on(brush_ground());
    const int ramp = ed.level().entities[1].id;
    // Straight down at z = 2: the slope is 1 high there (its box's top is 4).
    const geometry::Ray down{{0, 20, 2}, {0, -1, 0}};
    const PickHit hit = pick_entity(ed.doc(), down, editor_test::all_shown);
    CHECK(hit.id == ramp);
    CHECK(hit.distance == doctest::Approx(19.0f).epsilon(1e-4));
    CHECK(place_point(ed.doc(), down, editor_test::all_shown, Vec3(0)).y ==
          doctest::Approx(1.0f).epsilon(1e-4));
    // Through the empty corner of the ramp's box above its foot: the slab below is hit instead.
    const geometry::Ray corner{{0, 20, 3.5f}, {0, -1, 0}};
    CHECK(pick_entity(ed.doc(), corner, editor_test::all_shown).distance ==
          doctest::Approx(19.75f).epsilon(1e-4));
}

TEST_CASE(
    "trigger_reach: a trigger with links that starts disabled and nothing enables is fixed by enabling it") {
    Editor ed = editor_test::two_rooms();
    const int trigger = *place(ed, EntityType::Trigger, {0, 0, 10}, 0, "Latch");
    REQUIRE(link_add(ed, LinkOwner::entity(trigger), {"on_enter", "level", "win", 0, false}).ok());
    CHECK(issues_with(ed, Rule::TriggerReach).empty());
    REQUIRE(select(ed, {trigger}).ok());
    REQUIRE(set_field(ed, "enabled", FieldValue(false)).ok());
    auto issues = issues_with(ed, Rule::TriggerReach);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].entity_id == trigger);
    CHECK(issues[0].message.find("starts disabled and no link enables it") != std::string::npos);
    CHECK(issues[0].fix.label == "Enable the trigger at start");
    REQUIRE(apply_quick_fix(ed, issues[0]).ok());
    CHECK(ed.level().find(trigger)->as<level::TriggerProps>().enabled);
    CHECK(issues_with(ed, Rule::TriggerReach).empty());
}

TEST_CASE("door_gap and the player start see brush walls: a doorway cut by subtract, a brush in the way") {
    level::Level lv = brush_ground();
    // A wall 0.5 thick along x at z = -8 with a doorway 5 wide and 5 high cut out of it.
    auto wall = brush::make_box({-10, 0, -8.25}, {10, 8, -7.75});
    auto cutter = brush::make_box({-2.5, 0, -9}, {2.5, 5, -7});
    REQUIRE(wall.ok());
    REQUIRE(cutter.ok());
    auto pieces = brush::subtract(*wall, *cutter);
    REQUIRE(pieces.ok());
    REQUIRE(pieces->fragments.size() == 3); // either side of the doorway, over it
    for (const brush::Brush& piece : pieces->fragments)
        lv.add(EntityType::Brush, Vec3(0), "wall piece").as<level::BrushProps>().brush = piece;
    lv.add(EntityType::Door, {0, 0, -8}, "Door");
    Editor ed = editor_on(std::move(lv));
    const int door = ed.level().entities.back().id;
    CHECK_MESSAGE(issues_with(ed, Rule::DoorGap).empty(), issues_with(ed, Rule::DoorGap)[0].message);

    REQUIRE(select(ed, {door}).ok());
    REQUIRE(set_field_text(ed, "position", "6,0,-8").ok()); // into the wall beside the doorway
    auto issues = issues_with(ed, Rule::DoorGap);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].message.find("is blocked by brush") != std::string::npos);
    REQUIRE(set_field_text(ed, "position", "-6,0,6").ok()); // in the room, away from the wall
    issues = issues_with(ed, Rule::DoorGap);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].message.find("either side") != std::string::npos);

    // The player start inside the wall beside the doorway is an error; in the doorway it is not.
    REQUIRE(set_player_start(ed, {{6, 0, -8}, 0}).ok());
    issues = issues_with(ed, Rule::PlayerStart);
    REQUIRE(issues.size() == 1);
    CHECK(issues[0].message.find("is inside brush") != std::string::npos);
    REQUIRE(set_player_start(ed, {{0, 0, -8}, 0}).ok());
    CHECK(issues_with(ed, Rule::PlayerStart).empty());
}
