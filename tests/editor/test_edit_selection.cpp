// Selecting: by id and mode, by type, box and predicate; locked and hidden entities skipped; what a click
// picks; the entity a validation issue names (edit_selection.h).
#include "editor_test_util.h"
#include "model/edit_entities.h"
#include "model/edit_groups.h"
#include "model/edit_layers.h"
#include "model/edit_selection.h"

using namespace ks;
using namespace ks::editor;
using level::EntityType;

TEST_CASE(
    "selection: single, add, toggle, remove, all of a type, box; locked and hidden entities are skipped") {
    Editor ed;
    int a = *place(ed, EntityType::Robot, {0, 0, 0});
    int b = *place(ed, EntityType::Robot, {10, 0, 0});
    int c = *place(ed, EntityType::Pickup, {20, 0, 0});
    int d = *place(ed, EntityType::Robot, {30, 0, 0});

    REQUIRE(select(ed, {a}).ok());
    REQUIRE(select(ed, {b, c}, SelectMode::Add).ok());
    CHECK(ed.doc().selection == std::vector<int>{a, b, c});
    REQUIRE(select(ed, {b, d}, SelectMode::Toggle).ok());
    CHECK(ed.doc().selection == std::vector<int>{a, c, d});
    REQUIRE(select(ed, {a}, SelectMode::Remove).ok());
    CHECK(ed.doc().selection == std::vector<int>{c, d});

    CHECK(select_all_of_type(ed, EntityType::Robot) == 3);
    CHECK(ed.doc().selection == std::vector<int>{a, b, d});

    REQUIRE(set_locked(ed, b, true).ok());
    REQUIRE(set_hidden(ed, d, true).ok());
    CHECK(ed.doc().selection == std::vector<int>{a, d}); // locking drops it from the selection
    CHECK(select_all_of_type(ed, EntityType::Robot) == 1);
    CHECK(ed.doc().selection == std::vector<int>{a});
    auto locked = select(ed, {b});
    REQUIRE_FALSE(locked.ok());
    CHECK(locked.error().hint.find("unlock") != std::string::npos);
    CHECK_FALSE(select(ed, {999}).ok());
    CHECK(ed.doc().selection == std::vector<int>{a}); // failed selects change nothing

    // Box select: the robot at x=0 spans x -0.8..0.8; the pickup at 20 spans 19.6..20.4.
    CHECK(select_in_box(ed, {{-1, 0, -1}, {20, 3, 1}}) == 2);
    CHECK(ed.doc().selection == std::vector<int>{a, c});
    CHECK(select_in_box(ed, {{0.9f, 0, -1}, {19.5f, 3, 1}}) == 0); // b is inside but locked
    CHECK(ed.doc().selection.empty());
    CHECK(select_where(ed, [](const level::Entity& e) { return e.position.x > 15; }) == 1); // d hidden
    CHECK(select_all(ed) == 2);

    // Locked entities are not edited even when an operation names them.
    REQUIRE(set_locked(ed, b, true).ok());
    CHECK_FALSE(rename(ed, b, "x").ok());
    CHECK_FALSE(delete_entities(ed, {b}).ok());
}

TEST_CASE("select_issue selects the entity or the player start an issue names; a level issue leaves it") {
    Editor ed;
    const int robot = *place(ed, EntityType::Robot, {0, 0, 0});
    const int pickup = *place(ed, EntityType::Pickup, {4, 0, 0});
    REQUIRE(select(ed, {pickup}).ok());
    Issue about_robot;
    about_robot.rule = Rule::Support;
    about_robot.entity_id = robot;
    REQUIRE(select_issue(ed, about_robot).ok());
    CHECK(ed.doc().selection == std::vector<int>{robot});
    Issue about_start;
    about_start.rule = Rule::PlayerStart;
    REQUIRE(select_issue(ed, about_start).ok());
    CHECK(ed.doc().selection == std::vector<int>{kPlayerStartId});
    CHECK(selected_entities(ed).empty()); // the player start has no entity
    Issue about_level;
    about_level.rule = Rule::ControlPanel;
    REQUIRE(select_issue(ed, about_level).ok());
    CHECK(ed.doc().selection == std::vector<int>{kPlayerStartId});
    REQUIRE(set_locked(ed, robot, true).ok());
    CHECK_FALSE(select_issue(ed, about_robot).ok()); // a locked entity is not selected, even from an issue
    Issue gone = about_robot;
    gone.entity_id = 99;
    CHECK_FALSE(select_issue(ed, gone).ok());
}

TEST_CASE("select_picked: a click picks the member's group; inside an entered group, the member alone") {
    Editor ed;
    const int a = *place(ed, EntityType::Wall, {0, 0, 0});
    const int b = *place(ed, EntityType::Wall, {4, 0, 0});
    const int c = *place(ed, EntityType::Robot, {0, 0, 8});
    REQUIRE(select(ed, {a, b}).ok());
    const int group = *group_selection(ed, "Pair");
    REQUIRE(select_picked(ed, a).ok());
    CHECK(ed.doc().selection == std::vector<int>{a, b});
    REQUIRE(select_picked(ed, c, SelectMode::Add).ok());
    CHECK(ed.doc().selection == std::vector<int>{a, b, c});
    REQUIRE(enter_group(ed, group).ok());
    REQUIRE(select_picked(ed, b).ok());
    CHECK(ed.doc().selection == std::vector<int>{b});
    CHECK(ed.open_group() == group);
    REQUIRE(select_picked(ed, c).ok()); // a click outside the entered group leaves it
    CHECK(ed.open_group() == 0);
    CHECK(ed.doc().selection == std::vector<int>{c});
    CHECK_FALSE(select_picked(ed, 77).ok());
}
