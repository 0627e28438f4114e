// Every edit is one undoable step; undoing everything returns the byte-identical file and redoing
// everything returns the edited one.
#include "editor_test_util.h"
#include "model/edit_entities.h"
#include "model/edit_files.h"
#include "model/edit_selection.h"
#include "model/edit_transforms.h"

#include "core/log.h"

#include <cmath>
#include <limits>

using namespace ks;
using namespace ks::editor;
using level::EntityType;

TEST_CASE("commands: place, move, rotate, scale, set, rename, duplicate, delete all undo to the exact file") {
    Editor ed;
    const std::string original = editor_test::text_of(ed);

    auto wall = place(ed, EntityType::Wall, {1.2f, 0.1f, -3.7f}, 47.0f, "A wall");
    REQUIRE(wall.ok());
    const level::Entity* w = ed.level().find(*wall);
    REQUIRE(w);
    CHECK(w->position == Vec3(1.0f, 0.0f, -4.0f)); // grid 1: origin snapped
    CHECK(w->rotation.x == 45.0f);                 // 15° steps
    CHECK(ed.doc().selection == std::vector<int>{*wall});

    auto robot = place(ed, EntityType::Robot, {5, 0, 5});
    REQUIRE(robot.ok());
    REQUIRE(select(ed, {*wall, *robot}).ok());
    REQUIRE(move_selection(ed, {2, 0, 0}).ok());
    REQUIRE(rotate_selection(ed, 90).ok());
    REQUIRE(select(ed, {*wall}).ok());
    REQUIRE(scale_selection(ed, {2, 1, 1}).ok());
    REQUIRE(set_field_text(ed, "texture", "wood").ok());
    REQUIRE(rename(ed, *robot, "Guard").ok());
    REQUIRE(select(ed, {*robot}).ok());
    REQUIRE(set_field(ed, "health", FieldValue(250.0)).ok());
    REQUIRE(duplicate(ed).ok());
    REQUIRE(select(ed, {*wall}).ok());
    REQUIRE(delete_selection(ed).ok());
    REQUIRE(set_setting(ed, "fog_density", FieldValue(0.01)).ok());
    REQUIRE(set_player_start(ed, {{3, 0, 3}, 90}).ok());
    REQUIRE(rename_level(ed, "Edited").ok());

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
    for (int i = 0; i < 6; ++i) ids.push_back(*place(ed, EntityType::Pickup, {float(i) * 2, 0, 0}));
    const std::string before = editor_test::text_of(ed);
    REQUIRE(select(ed, {ids[4], ids[1], ids[2]}).ok());
    REQUIRE(delete_selection(ed).ok());
    CHECK(ed.level().entities.size() == 3);
    CHECK(ed.level().next_id == 7); // never reused
    REQUIRE(ed.undo());
    CHECK(editor_test::text_of(ed) == before);
    for (size_t i = 0; i < ids.size(); ++i) CHECK(ed.level().entities[i].id == ids[i]);
    CHECK(ed.doc().selection == std::vector<int>({ids[4], ids[1], ids[2]})); // selection restored too
    // A placed entity after undoing a place does not reuse the id the undone one had.
    REQUIRE(ed.redo());
    auto fresh = place(ed, EntityType::Robot, {0, 0, 0});
    CHECK(*fresh == 7);
}

TEST_CASE("commands: failed edits change nothing and record nothing") {
    Editor ed;
    auto id = *place(ed, EntityType::Door, {0, 0, 0});
    const std::string before = editor_test::text_of(ed);
    const size_t steps = ed.history().undo_count();
    CHECK_FALSE(set_field(ed, "width", FieldValue(1e9)).ok());          // out of range
    CHECK_FALSE(set_field(ed, "width", FieldValue(std::nan(""))).ok()); // NaN
    CHECK_FALSE(set_field(ed, "width", FieldValue(true)).ok());         // wrong type
    CHECK_FALSE(set_field(ed, "no_such_field", FieldValue(1.0)).ok());
    CHECK_FALSE(move_selection(ed, {std::numeric_limits<float>::infinity(), 0, 0}).ok());
    CHECK_FALSE(move_selection(ed, {2e5f, 0, 0}).ok()); // outside the position range
    CHECK_FALSE(scale_selection(ed, {-1, 1, 1}).ok());
    CHECK_FALSE(place(ed, EntityType::Robot, {std::nanf(""), 0, 0}).ok());
    auto err = set_field(ed, "width", FieldValue(1000.0));
    REQUIRE_FALSE(err.ok());
    CHECK(err.error().message.find("door " + std::to_string(id)) != std::string::npos);
    CHECK(err.error().hint.find("0.5 .. 100") != std::string::npos);
    CHECK(editor_test::text_of(ed) == before);
    CHECK(ed.history().undo_count() == steps);
}

TEST_CASE("commands: a transaction is one step; cancel reverts it; merging folds slider drags") {
    Editor ed;
    auto id = *place(ed, EntityType::Robot, {0, 0, 0});
    const std::string before = editor_test::text_of(ed);
    const size_t steps = ed.history().undo_count();

    ed.begin_transaction("Drag");
    for (int i = 0; i < 30; ++i) REQUIRE(move_selection(ed, {0.1f, 0, 0}).ok());
    ed.commit_transaction();
    CHECK(ed.history().undo_count() == steps + 1);
    CHECK(ed.history().undo_name() == "Drag");
    REQUIRE(ed.undo());
    CHECK(editor_test::text_of(ed) == before);

    ed.begin_transaction("Drag");
    REQUIRE(move_selection(ed, {5, 0, 0}).ok());
    CHECK(ed.history().in_transaction());
    CHECK_FALSE(ed.history().can_undo());
    ed.cancel_transaction();
    CHECK(editor_test::text_of(ed) == before);
    CHECK(ed.history().undo_count() == steps);

    for (int i = 1; i <= 10; ++i)
        REQUIRE(set_field(ed, "health", FieldValue(100.0 + i), "slider:health").ok());
    CHECK(ed.history().undo_count() == steps + 1);
    CHECK(ed.level().find(id)->as<level::RobotProps>().health == 110.0f);
    ed.end_merging();
    REQUIRE(set_field(ed, "health", FieldValue(5.0), "slider:health").ok());
    CHECK(ed.history().undo_count() == steps + 2);
    REQUIRE(ed.undo());
    REQUIRE(ed.undo());
    CHECK(editor_test::text_of(ed) == before);
}

TEST_CASE("history: the save point makes undo back to it clean, and a new branch dirty for good") {
    Editor ed;
    (void)place(ed, EntityType::Robot, {0, 0, 0});
    CHECK(ed.has_unsaved_changes());
    ks::test::ScratchDir dir;
    log::Capture quiet; // saving a draft warns
    REQUIRE(save_as(ed, dir / "a.json").ok());
    CHECK_FALSE(ed.has_unsaved_changes());
    REQUIRE(move_selection(ed, {1, 0, 0}).ok());
    CHECK(ed.has_unsaved_changes());
    REQUIRE(ed.undo());
    CHECK_FALSE(ed.has_unsaved_changes());
    REQUIRE(ed.undo());
    CHECK(ed.has_unsaved_changes());
    REQUIRE(ed.redo());
    CHECK_FALSE(ed.has_unsaved_changes());
    // Merging never folds into the saved step.
    REQUIRE(set_field(ed, "health", FieldValue(10.0), "k").ok());
    REQUIRE(save(ed).ok());
    REQUIRE(set_field(ed, "health", FieldValue(20.0), "k").ok());
    CHECK(ed.has_unsaved_changes());
    REQUIRE(ed.undo());
    CHECK_FALSE(ed.has_unsaved_changes());
    // Undo past the save point, then edit: the saved state is unreachable, so the document stays dirty.
    REQUIRE(ed.undo());
    REQUIRE(rename_level(ed, "Other").ok());
    CHECK(ed.has_unsaved_changes());
    CHECK_FALSE(ed.history().can_redo());
}

TEST_CASE("history: step names list done and redoable steps for the History panel") {
    Editor ed;
    (void)place(ed, EntityType::Robot, {0, 0, 0});
    (void)place(ed, EntityType::Pickup, {2, 0, 0});
    REQUIRE(delete_selection(ed).ok());
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
    for (int i = 0; i < 40; ++i) (void)place(ed, EntityType::Robot, {float(i % 8) * 3, 0, float(i / 8) * 3});
    const std::string before = editor_test::text_of(ed);
    CHECK(select_all(ed) == 40);
    REQUIRE(move_selection(ed, {1, 0, 2}).ok());
    REQUIRE(rotate_selection(ed, 45).ok());
    REQUIRE(set_field(ed, "health", FieldValue(42.0)).ok());
    const std::string after = editor_test::text_of(ed);
    for (const auto& e : ed.level().entities) CHECK(e.as<level::RobotProps>().health == 42.0f);
    while (ed.history().undo_name() != "Place robot") REQUIRE(ed.undo());
    CHECK(editor_test::text_of(ed) == before);
    while (ed.redo()) {
    }
    CHECK(editor_test::text_of(ed) == after);
}
