// Every edit is one undoable step; undoing everything returns the byte-identical file and redoing
// everything returns the edited one.
#include "editor_test_util.h"

#include "core/log.h"

#include <cmath>
#include <limits>

using namespace ks;
using namespace ks::editor;
using level::EntityType;

TEST_CASE("commands: place, move, rotate, scale, set, rename, duplicate, delete all undo to the exact file") {
    Editor ed;
    const std::string original = editor_test::text_of(ed);

    auto wall = ed.place(EntityType::Wall, {1.2f, 0.1f, -3.7f}, 47.0f, "A wall");
    REQUIRE(wall.ok());
    const level::Entity* w = ed.level().find(*wall);
    REQUIRE(w);
    CHECK(w->position == Vec3(1.0f, 0.0f, -4.0f)); // grid 1: origin snapped
    CHECK(w->rotation.x == 45.0f);                 // 15° steps
    CHECK(ed.doc().selection == std::vector<int>{*wall});

    auto robot = ed.place(EntityType::Robot, {5, 0, 5});
    REQUIRE(robot.ok());
    REQUIRE(ed.select({*wall, *robot}).ok());
    REQUIRE(ed.move_selection({2, 0, 0}).ok());
    REQUIRE(ed.rotate_selection(90).ok());
    REQUIRE(ed.select({*wall}).ok());
    REQUIRE(ed.scale_selection({2, 1, 1}).ok());
    REQUIRE(ed.set_field_text("texture", "wood").ok());
    REQUIRE(ed.rename(*robot, "Guard").ok());
    REQUIRE(ed.select({*robot}).ok());
    REQUIRE(ed.set_field("health", FieldValue(250.0)).ok());
    REQUIRE(ed.duplicate().ok());
    REQUIRE(ed.select({*wall}).ok());
    REQUIRE(ed.delete_selection().ok());
    REQUIRE(ed.set_setting("fog_density", FieldValue(0.01)).ok());
    REQUIRE(ed.set_player_start({{3, 0, 3}, 90}).ok());
    REQUIRE(ed.rename_level("Edited").ok());

    const std::string edited = editor_test::text_of(ed);
    CHECK(ed.history().undo_count() == 13);
    CHECK(edited != original);

    while (ed.undo()) {
    }
    CHECK(editor_test::text_of(ed) == original);
    CHECK_FALSE(ed.has_unsaved_changes());
    while (ed.redo()) {
    }
    CHECK(editor_test::text_of(ed) == edited);
}

TEST_CASE("commands: delete restores entity order, ids and next_id exactly") {
    Editor ed;
    std::vector<int> ids;
    for (int i = 0; i < 6; ++i) ids.push_back(*ed.place(EntityType::Pickup, {float(i) * 2, 0, 0}));
    const std::string before = editor_test::text_of(ed);
    REQUIRE(ed.select({ids[4], ids[1], ids[2]}).ok());
    REQUIRE(ed.delete_selection().ok());
    CHECK(ed.level().entities.size() == 3);
    CHECK(ed.level().next_id == 7); // never reused
    REQUIRE(ed.undo());
    CHECK(editor_test::text_of(ed) == before);
    for (size_t i = 0; i < ids.size(); ++i) CHECK(ed.level().entities[i].id == ids[i]);
    CHECK(ed.doc().selection == std::vector<int>({ids[4], ids[1], ids[2]})); // selection restored too
    // A placed entity after undoing a place does not reuse the id the undone one had.
    REQUIRE(ed.redo());
    auto fresh = ed.place(EntityType::Robot, {0, 0, 0});
    CHECK(*fresh == 7);
}

TEST_CASE("commands: failed edits change nothing and record nothing") {
    Editor ed;
    auto id = *ed.place(EntityType::Door, {0, 0, 0});
    const std::string before = editor_test::text_of(ed);
    const size_t steps = ed.history().undo_count();
    CHECK_FALSE(ed.set_field("width", FieldValue(1e9)).ok());          // out of range
    CHECK_FALSE(ed.set_field("width", FieldValue(std::nan(""))).ok()); // NaN
    CHECK_FALSE(ed.set_field("width", FieldValue(true)).ok());         // wrong type
    CHECK_FALSE(ed.set_field("no_such_field", FieldValue(1.0)).ok());
    CHECK_FALSE(ed.move_selection({std::numeric_limits<float>::infinity(), 0, 0}).ok());
    CHECK_FALSE(ed.move_selection({2e5f, 0, 0}).ok()); // outside the position range
    CHECK_FALSE(ed.scale_selection({-1, 1, 1}).ok());
    CHECK_FALSE(ed.place(EntityType::Robot, {std::nanf(""), 0, 0}).ok());
    auto err = ed.set_field("width", FieldValue(1000.0));
    REQUIRE_FALSE(err.ok());
    CHECK(err.error().message.find("door " + std::to_string(id)) != std::string::npos);
    CHECK(err.error().hint.find("0.5 .. 100") != std::string::npos);
    CHECK(editor_test::text_of(ed) == before);
    CHECK(ed.history().undo_count() == steps);
}

TEST_CASE("commands: a transaction is one step; cancel reverts it; merging folds slider drags") {
    Editor ed;
    auto id = *ed.place(EntityType::Robot, {0, 0, 0});
    const std::string before = editor_test::text_of(ed);
    const size_t steps = ed.history().undo_count();

    ed.begin_transaction("Drag");
    for (int i = 0; i < 30; ++i) REQUIRE(ed.move_selection({0.1f, 0, 0}).ok());
    ed.commit_transaction();
    CHECK(ed.history().undo_count() == steps + 1);
    CHECK(ed.history().undo_name() == "Drag");
    REQUIRE(ed.undo());
    CHECK(editor_test::text_of(ed) == before);

    ed.begin_transaction("Drag");
    REQUIRE(ed.move_selection({5, 0, 0}).ok());
    CHECK(ed.history().in_transaction());
    CHECK_FALSE(ed.history().can_undo());
    ed.cancel_transaction();
    CHECK(editor_test::text_of(ed) == before);
    CHECK(ed.history().undo_count() == steps);

    for (int i = 1; i <= 10; ++i)
        REQUIRE(ed.set_field("health", FieldValue(100.0 + i), "slider:health").ok());
    CHECK(ed.history().undo_count() == steps + 1);
    CHECK(ed.level().find(id)->as<level::RobotProps>().health == 110.0f);
    ed.end_merging();
    REQUIRE(ed.set_field("health", FieldValue(5.0), "slider:health").ok());
    CHECK(ed.history().undo_count() == steps + 2);
    REQUIRE(ed.undo());
    REQUIRE(ed.undo());
    CHECK(editor_test::text_of(ed) == before);
}

TEST_CASE("history: the save point makes undo back to it clean, and a new branch dirty for good") {
    Editor ed;
    (void)ed.place(EntityType::Robot, {0, 0, 0});
    CHECK(ed.has_unsaved_changes());
    ks::test::ScratchDir dir;
    log::Capture quiet; // saving a draft warns
    REQUIRE(ed.save_as(dir / "a.json").ok());
    CHECK_FALSE(ed.has_unsaved_changes());
    REQUIRE(ed.move_selection({1, 0, 0}).ok());
    CHECK(ed.has_unsaved_changes());
    REQUIRE(ed.undo());
    CHECK_FALSE(ed.has_unsaved_changes());
    REQUIRE(ed.undo());
    CHECK(ed.has_unsaved_changes());
    REQUIRE(ed.redo());
    CHECK_FALSE(ed.has_unsaved_changes());
    // Merging never folds into the saved step.
    REQUIRE(ed.set_field("health", FieldValue(10.0), "k").ok());
    REQUIRE(ed.save().ok());
    REQUIRE(ed.set_field("health", FieldValue(20.0), "k").ok());
    CHECK(ed.has_unsaved_changes());
    REQUIRE(ed.undo());
    CHECK_FALSE(ed.has_unsaved_changes());
    // Undo past the save point, then edit: the saved state is unreachable, so the document stays dirty.
    REQUIRE(ed.undo());
    REQUIRE(ed.rename_level("Other").ok());
    CHECK(ed.has_unsaved_changes());
    CHECK_FALSE(ed.history().can_redo());
}

TEST_CASE("history: step names list done and redoable steps for the History panel") {
    Editor ed;
    (void)ed.place(EntityType::Robot, {0, 0, 0});
    (void)ed.place(EntityType::Pickup, {2, 0, 0});
    REQUIRE(ed.delete_selection().ok());
    REQUIRE(ed.undo());
    auto names = ed.history().step_names();
    REQUIRE(names.size() == 3);
    CHECK(names[0] == "Place robot");
    CHECK(names[1] == "Place pickup");
    CHECK(names[2] == "Delete pickup 2");
    CHECK(ed.history().undo_count() == 2);
    CHECK(ed.history().redo_name() == "Delete pickup 2");
}

TEST_CASE("commands: large selections (indexed update path) undo and redo exactly") {
    Editor ed;
    for (int i = 0; i < 40; ++i) (void)ed.place(EntityType::Robot, {float(i % 8) * 3, 0, float(i / 8) * 3});
    const std::string before = editor_test::text_of(ed);
    CHECK(ed.select_all() == 40);
    REQUIRE(ed.move_selection({1, 0, 2}).ok());
    REQUIRE(ed.rotate_selection(45).ok());
    REQUIRE(ed.set_field("health", FieldValue(42.0)).ok());
    const std::string after = editor_test::text_of(ed);
    for (const auto& e : ed.level().entities) CHECK(e.as<level::RobotProps>().health == 42.0f);
    while (ed.history().undo_name() != "Place robot") REQUIRE(ed.undo());
    CHECK(editor_test::text_of(ed) == before);
    while (ed.redo()) {
    }
    CHECK(editor_test::text_of(ed) == after);
}
