// Layers and hiding and locking one entity (edit_layers.h): membership, the active layer, visibility and
// locks reaching the document's hidden and locked sets, names, removal, undo.
#include "editor_test_util.h"
#include "model/edit_entities.h"
#include "model/edit_layers.h"
#include "model/edit_selection.h"
#include "model/groups.h"

using namespace ks;
using namespace ks::editor;
using editor_test::four_walls;

namespace {

std::string last_step(const Editor& ed) {
    return ed.history().step_names().at(ed.history().undo_count() - 1);
}

} // namespace

TEST_CASE("layers: new entities join the active layer; hide and lock a layer; remove it; undo") {
    Editor ed = four_walls();
    auto walls = layer_add(ed, "Walls");
    REQUIRE(walls.ok());
    CHECK(*walls == 1);
    CHECK(ed.level().editor.layers.size() == 2);
    CHECK(ed.level().editor.layers[0].name == "Default");
    CHECK(!layer_add(ed, "Walls").ok()); // names are unique
    CHECK(!layer_add(ed, "").ok());
    REQUIRE(select(ed, {1, 2, 3, 4}).ok());
    REQUIRE(move_selection_to_layer(ed, 1).ok());
    CHECK(layer_of(ed.level().editor, 3) == 1);
    CHECK(layer_of(ed.level().editor, 5) == 0);
    REQUIRE(layer_set_active(ed, 1).ok());
    auto placed = place(ed, level::EntityType::Wall, Vec3(0, 0, -8));
    REQUIRE(placed.ok());
    CHECK(layer_of(ed.level().editor, *placed) == 1);

    REQUIRE(layer_set_visible(ed, 1, false).ok());
    CHECK(ed.doc().hidden.contains(1));
    CHECK(!ed.doc().hidden.contains(5));
    CHECK(select_all(ed) == 1); // only the robot is visible
    REQUIRE(layer_set_visible(ed, 1, true).ok());
    REQUIRE(layer_set_locked(ed, 1, true).ok());
    CHECK(ed.doc().locked.contains(2));
    CHECK(!select(ed, {2}).ok());
    CHECK(!select_picked(ed, 2).ok());
    CHECK(ed.undo()); // unlock again
    CHECK(!ed.doc().locked.contains(2));
    REQUIRE(layer_remove(ed, 1).ok());
    CHECK(ed.level().editor.layers.size() == 1);
    CHECK(layer_of(ed.level().editor, 1) == 0);
    CHECK(ed.level().editor.active_layer == 0);
    CHECK(!layer_remove(ed, 0).ok()); // Default stays
    CHECK(!layer_set_visible(ed, 7, false).ok());
}

TEST_CASE("hiding and locking one entity are saved steps") {
    Editor ed = four_walls();
    REQUIRE(set_hidden(ed, 2, true).ok());
    REQUIRE(set_locked(ed, 3, true).ok());
    CHECK(ed.has_unsaved_changes());
    CHECK(ed.level().editor.hidden == std::vector<int>{2});
    CHECK(ed.level().editor.locked == std::vector<int>{3});
    CHECK(ed.doc().hidden.contains(2));
    CHECK(ed.doc().locked.contains(3));
    CHECK(!set_hidden(ed, 99, true).ok());
    CHECK(ed.undo());
    CHECK(!ed.doc().locked.contains(3));
}

TEST_CASE("layers: rename, the active layer and moving entities between layers; refusals change nothing") {
    Editor ed = four_walls();
    REQUIRE(layer_add(ed, "Walls").ok());
    REQUIRE(layer_add(ed, "Props").ok());
    CHECK(!layer_rename(ed, 1, "Props").ok()); // another layer has the name
    CHECK(!layer_rename(ed, 1, "").ok());
    CHECK(!layer_rename(ed, 5, "Far").ok());
    REQUIRE(layer_rename(ed, 1, "Outer walls").ok());
    CHECK(ed.level().editor.layers[1].name == "Outer walls");
    CHECK(last_step(ed) == "Rename layer");

    ed.clear_selection(); // placing selected the robot
    CHECK(!move_selection_to_layer(ed, 1).ok());
    REQUIRE(select(ed, {1, 2}).ok());
    REQUIRE(move_selection_to_layer(ed, 1).ok());
    CHECK(ed.level().editor.layers[1].entities == std::vector<int>{1, 2});
    REQUIRE(move_selection_to_layer(ed, 2).ok()); // an entity is on one layer at a time
    CHECK(ed.level().editor.layers[1].entities.empty());
    CHECK(ed.level().editor.layers[2].entities == std::vector<int>{1, 2});
    REQUIRE(move_selection_to_layer(ed, 0).ok()); // back to Default: listed nowhere
    CHECK(layer_of(ed.level().editor, 1) == 0);
    CHECK(ed.level().editor.layers[2].entities.empty());

    CHECK(!layer_set_active(ed, 3).ok());
    REQUIRE(layer_set_active(ed, 2).ok());
    CHECK(ed.level().editor.active_layer == 2);
    REQUIRE(layer_remove(ed, 1).ok()); // the active layer's index follows the removal
    CHECK(ed.level().editor.active_layer == 1);
    CHECK(ed.level().editor.layers[1].name == "Props");
    const std::string before = editor_test::text_of(ed);
    CHECK(!layer_set_locked(ed, 9, true).ok());
    CHECK(editor_test::text_of(ed) == before);
    REQUIRE(ed.undo());
    CHECK(ed.level().editor.layers.size() == 3);
    CHECK(ed.level().editor.active_layer == 2);
}

TEST_CASE("locking an entity drops it from the selection; unlocking and showing are steps of their own") {
    Editor ed = four_walls();
    REQUIRE(select(ed, {1, 2, 5}).ok());
    REQUIRE(set_locked(ed, 2, true).ok());
    CHECK(ed.doc().selection == std::vector<int>{1, 5});
    CHECK(last_step(ed) == "Lock wall 2");
    REQUIRE(set_hidden(ed, 1, true).ok());
    CHECK(ed.doc().selection == std::vector<int>{1, 5}); // hiding keeps the selection
    REQUIRE(set_locked(ed, 2, false).ok());
    REQUIRE(set_hidden(ed, 1, false).ok());
    CHECK(ed.level().editor.hidden.empty());
    CHECK(ed.level().editor.locked.empty());
    CHECK(!ed.doc().locked.contains(2));
    CHECK(ed.history().undo_count() == 9);
    CHECK(!set_locked(ed, 42, true).ok());
}
