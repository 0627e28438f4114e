// Groups (edit_groups.h): Ctrl+G / Ctrl+Shift+G, what a click picks inside and outside an entered group,
// moving, turning and duplicating a group as one, deleting members, and the editor section (groups, layers,
// hidden and locked entities) surviving save, reopen and undo. Layers: test_edit_layers.cpp.
#include "editor_test_util.h"
#include "model/edit_entities.h"
#include "model/edit_files.h"
#include "model/edit_groups.h"
#include "model/edit_layers.h"
#include "model/edit_prefabs.h"
#include "model/edit_selection.h"
#include "model/edit_transforms.h"
#include "model/script.h"

using namespace ks;
using namespace ks::editor;
using editor_test::four_walls;

namespace {

std::vector<int> sorted(std::vector<int> ids) {
    std::sort(ids.begin(), ids.end());
    return ids;
}

} // namespace

TEST_CASE("Ctrl+G groups the selection; a click on a member selects the group; ungroup dissolves it") {
    Editor ed = four_walls();
    REQUIRE(select(ed, {1, 2}).ok());
    auto group = group_selection(ed, "Pair");
    REQUIRE(group.ok());
    CHECK(*group == 1);
    const level::Group* g = ed.level().editor.find_group(1);
    REQUIRE(g);
    CHECK(g->name == "Pair");
    CHECK(g->entities == std::vector<int>{1, 2});
    CHECK(g->position == Vec3(2, 0, 0)); // the selection's centre at floor level
    REQUIRE(select_picked(ed, 2).ok());
    CHECK(sorted(ed.doc().selection) == std::vector<int>{1, 2});
    CHECK(selected_groups(ed) == std::vector<int>{1});
    REQUIRE(select_picked(ed, 3).ok());
    CHECK(ed.doc().selection == std::vector<int>{3});

    // A group of the group and a wall: nesting; the click picks the outermost.
    REQUIRE(select(ed, {1, 2, 3}).ok());
    auto outer = group_selection(ed);
    REQUIRE(outer.ok());
    CHECK(ed.level().editor.find_group(*outer)->groups == std::vector<int>{1});
    CHECK(ed.level().editor.find_group(*outer)->entities == std::vector<int>{3});
    REQUIRE(select_picked(ed, 1).ok());
    CHECK(sorted(ed.doc().selection) == std::vector<int>{1, 2, 3});

    // Entering the outer group: a click picks its child group, or its own member.
    REQUIRE(enter_group(ed, *outer).ok());
    REQUIRE(select_picked(ed, 1).ok());
    CHECK(sorted(ed.doc().selection) == std::vector<int>{1, 2});
    REQUIRE(select_picked(ed, 3).ok());
    CHECK(ed.doc().selection == std::vector<int>{3});
    REQUIRE(enter_group(ed, 1).ok());
    REQUIRE(select_picked(ed, 2).ok());
    CHECK(ed.doc().selection == std::vector<int>{2});
    // A click outside the entered group leaves it.
    REQUIRE(select_picked(ed, 5).ok());
    CHECK(ed.open_group() == 0);

    REQUIRE(select_picked(ed, 1).ok());
    REQUIRE(ungroup_selection(ed).ok());
    CHECK(ed.level().editor.groups.size() == 1); // the inner pair is top-level again
    CHECK(ed.level().editor.find_group(1) != nullptr);
    CHECK(ed.undo());
    CHECK(ed.level().editor.groups.size() == 2);
    CHECK(ed.undo()); // the outer group
    CHECK(ed.undo()); // the pair
    CHECK(ed.level().editor.empty());
}

TEST_CASE("a group moves, turns and duplicates as one; its frame follows; copies stay groups") {
    Editor ed = four_walls();
    REQUIRE(select(ed, {1, 2}).ok());
    REQUIRE(group_selection(ed, "Pair").ok());
    REQUIRE(select_picked(ed, 1).ok());
    REQUIRE(move_selection(ed, Vec3(0, 0, 3)).ok());
    CHECK(ed.level().find(1)->position == Vec3(0, 0, 3));
    CHECK(ed.level().find(2)->position == Vec3(4, 0, 3));
    CHECK(ed.level().editor.find_group(1)->position == Vec3(2, 0, 3));
    REQUIRE(rotate_selection(ed, 90).ok());
    const level::Group* g = ed.level().editor.find_group(1);
    CHECK(g->yaw == doctest::Approx(90));
    CHECK(g->position.x == doctest::Approx(2));
    CHECK(g->position.z == doctest::Approx(3));
    CHECK(ed.level().find(1)->position.z == doctest::Approx(5)); // (-2, 0) turned a quarter: (0, 2)
    REQUIRE(duplicate(ed, Vec3(10, 0, 0)).ok());
    REQUIRE(ed.level().editor.groups.size() == 2);
    const level::Group& copy = ed.level().editor.groups[1];
    CHECK(copy.id == 2);
    CHECK(copy.name == "Pair");
    CHECK(copy.entities == std::vector<int>{6, 7});
    CHECK(copy.position.x == doctest::Approx(12));
    CHECK(sorted(ed.doc().selection) == std::vector<int>{6, 7});
    // Moving one member (inside the entered group) leaves the frame.
    REQUIRE(enter_group(ed, 1).ok());
    REQUIRE(select_picked(ed, 1).ok());
    REQUIRE(move_selection(ed, Vec3(1, 0, 0)).ok());
    CHECK(ed.level().editor.find_group(1)->position.x == doctest::Approx(2));
}

TEST_CASE("deleting members: empty groups go; undo brings entities and group back bit for bit") {
    Editor ed = four_walls();
    REQUIRE(select(ed, {1, 2}).ok());
    REQUIRE(group_selection(ed).ok());
    const std::string grouped = editor_test::text_of(ed);
    REQUIRE(delete_entities(ed, {1}).ok());
    CHECK(ed.level().editor.find_group(1)->entities == std::vector<int>{2});
    REQUIRE(delete_entities(ed, {2}).ok());
    CHECK(ed.level().editor.groups.empty());
    CHECK(ed.undo());
    CHECK(ed.undo());
    CHECK(editor_test::text_of(ed) == grouped);
}

TEST_CASE("grouping refuses nothing selected and a selection that is one group already") {
    Editor ed = four_walls();
    ed.clear_selection();
    CHECK(!group_selection(ed).ok());
    REQUIRE(select(ed, {1, 2}).ok());
    REQUIRE(group_selection(ed).ok());
    auto again = group_selection(ed);
    REQUIRE(!again.ok());
    CHECK(again.error().message.find("one group already") != std::string::npos);
    CHECK(!enter_group(ed, 42).ok());
}

TEST_CASE("layers, groups, hidden and locked entities survive save and reopen exactly") {
    test::ScratchDir dir;
    Editor ed = four_walls();
    REQUIRE(layer_add(ed, "Walls").ok());
    REQUIRE(select(ed, {1, 2}).ok());
    REQUIRE(move_selection_to_layer(ed, 1).ok());
    REQUIRE(group_selection(ed, "Pair").ok());
    REQUIRE(layer_set_visible(ed, 1, false).ok());
    REQUIRE(set_locked(ed, 5, true).ok());
    REQUIRE(set_hidden(ed, 4, true).ok());
    REQUIRE(save_as(ed, dir / "structure.json").ok());
    const std::string saved = editor_test::text_of(ed);
    Editor again;
    REQUIRE(open(again, dir / "structure.json").ok());
    CHECK(editor_test::text_of(again) == saved);
    CHECK(!again.has_unsaved_changes());
    CHECK(again.level().editor == ed.level().editor);
    CHECK(again.doc().hidden == ed.doc().hidden);
    CHECK(again.doc().locked == ed.doc().locked);
    CHECK(again.doc().hidden.contains(1)); // through the hidden layer
    // The game reads past the editor section: the level loads with the same entities.
    auto loaded = level::load_level_file(dir / "structure.json");
    REQUIRE(loaded.ok());
    CHECK(loaded->entities.size() == 5);
}

TEST_CASE("the script's group and layer lines, with expectations") {
    Editor ed;
    auto report = run_script_text(R"(
place wall at 0,0,0
place wall at 4,0,0
place wall at 8,0,0
select 1 2
group Pair
expect groups 1
expect group 1 2
pick 2
expect selected 2
select 1 2 3
group
enter 2
pick 1
expect selected 2
expect open_group 2
exit
expect open_group 0
layer add Walls
layer Walls move
expect layer Walls 2 visible unlocked
layer Walls hide
expect hidden 1
expect shown 3
layer 1 show
expect shown 1
layer Walls lock
expect layer 1 2 locked
expect layers 2
ungroup
)",
                                  "structure.kss", {}, ed);
    // ungroup with nothing selected (the layer lock dropped the selection) is a clear error
    REQUIRE(!report.ok());
    INFO(report.error().str());
    CHECK(report.error().str().find("structure.kss:30") != std::string::npos);
    CHECK(report.error().str().find("no group is selected") != std::string::npos);
    auto bad = parse_script("layer Walls paint\n", "bad.kss");
    REQUIRE(!bad.ok());
    CHECK(bad.error().str().find("unknown layer command 'paint'") != std::string::npos);
    Editor fresh;
    auto typo = run_script_text("layer add Walls\nlayer Wals hide\n", "typo.kss", {}, fresh);
    REQUIRE(!typo.ok());
    INFO(typo.error().str());
    CHECK(typo.error().str().find("did you mean 'Walls'") != std::string::npos);
}

TEST_CASE("a 2 000-entity level: a 1 000-entity group picks, moves and undoes as one") {
    // Timings are ks_bench structure's (docs/performance.md); this checks the structure at that size.
    Editor ed;
    for (int i = 0; i < 2000; ++i)
        REQUIRE(place(ed, level::EntityType::Wall, Vec3(float(i % 50) * 4, 0, float(i / 50) * 4)).ok());
    std::vector<int> half;
    for (int id = 1; id <= 1000; ++id) half.push_back(id);
    REQUIRE(select(ed, half).ok());
    REQUIRE(group_selection(ed).ok());
    REQUIRE(select_picked(ed, 500).ok());
    CHECK(ed.doc().selection.size() == 1000);
    REQUIRE(move_selection(ed, Vec3(0, 0, 1)).ok());
    CHECK(ed.undo());
    CHECK(ed.undo());
    CHECK(ed.level().editor.groups.empty());
}

TEST_CASE("copy and paste keep groups and prefab links; a plain entity pastes plain") {
    test::ScratchDir dir;
    Editor ed = four_walls();
    ed.prefabs().set_folders({dir.path()});
    REQUIRE(select(ed, {1, 2}).ok());
    REQUIRE(group_selection(ed, "Pair").ok());
    REQUIRE(select(ed, {3, 4}).ok());
    REQUIRE(save_prefab(ed, "two_walls").ok()); // group 2, an instance
    REQUIRE(select(ed, {1, 2, 3, 4}).ok());
    const std::string text = copy(ed);
    CHECK(text.find("\"editor\"") != std::string::npos);
    REQUIRE(paste(ed).ok());
    CHECK(sorted(ed.doc().selection) == std::vector<int>{6, 7, 8, 9});
    REQUIRE(ed.level().editor.groups.size() == 4);
    const level::Group& pair = ed.level().editor.groups[2];
    CHECK(pair.id == 3);
    CHECK(pair.name == "Pair");
    CHECK(pair.entities == std::vector<int>{6, 7});
    const level::Group& instance = ed.level().editor.groups[3];
    CHECK(instance.has_prefab);
    CHECK(instance.prefab.members == std::vector<int>{8, 9});
    REQUIRE(select_picked(ed, 8).ok());
    CHECK(sorted(ed.doc().selection) == std::vector<int>{8, 9});
    CHECK(ed.undo());
    CHECK(ed.level().editor.groups.size() == 2);
    // One member alone pastes as a plain entity.
    REQUIRE(select(ed, {1}).ok());
    (void)copy(ed);
    REQUIRE(paste(ed).ok());
    CHECK(ed.level().editor.groups.size() == 2);
}

TEST_CASE("box select takes the groups it touches whole, and counts what the box held") {
    Editor ed = four_walls();
    REQUIRE(select(ed, {1, 2}).ok());
    REQUIRE(group_selection(ed).ok());
    const int held = select_picked_where(ed, [](const level::Entity& e) { return e.id == 2 || e.id == 3; });
    CHECK(held == 2);
    CHECK(sorted(ed.doc().selection) == std::vector<int>{1, 2, 3});
    REQUIRE(enter_group(ed, 1).ok()); // inside the group, members one by one
    (void)select_picked_where(ed, [](const level::Entity& e) { return e.id == 2; });
    CHECK(ed.doc().selection == std::vector<int>{2});
}
