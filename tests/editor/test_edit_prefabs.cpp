// Prefabs in the editor model: the file format and its errors, saving a selection as a prefab, placing
// linked instances (turned, names made unique, links kept inside), overrides recorded and kept when the
// prefab changes, apply to prefab, updates on open, revert, unlink, and the shipped prefabs.
#include "editor_test_util.h"
#include "model/edit_entities.h"
#include "model/edit_files.h"
#include "model/edit_logic.h"
#include "model/edit_prefabs.h"
#include "model/edit_selection.h"
#include "model/edit_transforms.h"
#include "model/prefab.h"
#include "model/quick_fix.h"
#include "model/script.h"

#include "core/files.h"
#include "jsonio/bad_documents.h"

using namespace ks;
using namespace ks::editor;

namespace {

// A door (named Gate) between two walls, with a trigger that opens it.
Editor doorway(const std::filesystem::path& prefab_folder) {
    Editor ed;
    ed.prefabs().set_folders({prefab_folder});
    REQUIRE(place(ed, level::EntityType::Wall, Vec3(-5, 0, 0), 0, "West").ok());
    REQUIRE(place(ed, level::EntityType::Wall, Vec3(5, 0, 0), 0, "East").ok());
    REQUIRE(place(ed, level::EntityType::Door, Vec3(0, 0, 0), 0, "Gate").ok());
    REQUIRE(place(ed, level::EntityType::Trigger, Vec3(0, 0, 4), 0, "Mat").ok());
    REQUIRE(link_add(ed, LinkOwner::entity(4), {"on_enter", "Gate", "open", 0.0f, false}).ok());
    REQUIRE(select(ed, {1, 2, 3, 4}).ok());
    return ed;
}

const level::Entity& member(const Editor& ed, int group, size_t index) {
    const level::Group* g = ed.level().editor.find_group(group);
    REQUIRE(g);
    REQUIRE(index < g->prefab.members.size());
    const level::Entity* e = ed.level().find(g->prefab.members[index]);
    REQUIRE(e);
    return *e;
}

} // namespace

TEST_CASE("a prefab file round-trips; a broken one names the file, the place and the fix") {
    Prefab prefab{"doorway", "Doorway", {}};
    level::Entity wall;
    wall.id = 1;
    wall.position = Vec3(1, 0, 2);
    wall.props = level::default_props(level::EntityType::Wall);
    prefab.entities.push_back(wall);
    auto again = prefab_from_text(prefab_to_text(prefab), "doorway.json");
    REQUIRE(again.ok());
    CHECK(*again == prefab);

    auto syntax = prefab_from_text("{\"format\": \"killswitch-prefab\",\n \"version\": 1,,}", "p.json");
    REQUIRE(!syntax.ok());
    CHECK(syntax.error().where.line == 2);
    auto format = prefab_from_text(R"({"format": "killswitch-level", "version": 1})", "p.json");
    REQUIRE(!format.ok());
    CHECK(format.error().str().find("not a prefab file") != std::string::npos);
    auto entity = prefab_from_text(
        R"({"format": "killswitch-prefab", "version": 1, "name": "p", "entities": [{"type": "wal"}]})",
        "p.json");
    REQUIRE(!entity.ok());
    CHECK(entity.error().str().find("p.json") != std::string::npos);
    CHECK(entity.error().str().find("wall") != std::string::npos); // did you mean
    CHECK(!prefab_name_problem("Door Way").empty());
    CHECK(prefab_name_problem("door-way_2").empty());
}

TEST_CASE("a prefab file is read like a level: the bad cases get the level's treatment, each at its place") {
    const std::string head = "{\"format\": \"killswitch-prefab\", \"version\": 1, \"name\": \"p\",\n";
    const std::string wall = "\"entities\": [{\"id\": 1, \"type\": \"wall\", \"position\": [0, 0, 0]}]}";
    SUBCASE("a duplicate key is an error") {
        auto r = prefab_from_text(head + "\"title\": \"A\", \"title\": \"B\",\n" + wall, "p.json");
        REQUIRE_FALSE(r.ok());
        CHECK(r.error().str().find("p.json:2:15: title: duplicate key (also at line 2:1)") !=
              std::string::npos);
    }
    SUBCASE("a numeric title is an error") {
        auto r = prefab_from_text(head + "\"title\": 7,\n" + wall, "p.json");
        REQUIRE_FALSE(r.ok());
        CHECK(r.error().str().find("p.json:2:1: title: expected a string, found the number 7") !=
              std::string::npos);
    }
    SUBCASE("unknown keys and an objectives key are warnings with a did-you-mean; the prefab reads") {
        std::vector<Error> warnings;
        auto r =
            prefab_from_text(head + "\"titel\": \"A\", \"objectives\": [],\n" + wall, "p.json", &warnings);
        REQUIRE_MESSAGE(r.ok(), (r.ok() ? "" : r.error().str()));
        REQUIRE(warnings.size() == 2);
        CHECK(warnings[0].str().find("p.json:2:1: titel: unknown field \"titel\" is ignored (did you mean "
                                     "\"title\"?") != std::string::npos);
        CHECK(warnings[1].str().find("p.json:2:15: objectives: unknown field \"objectives\" is ignored") !=
              std::string::npos);
    }
    SUBCASE("an entity's problems are located in the prefab file") {
        auto r = prefab_from_text(
            head + "\"entities\": [{\"id\": 1, \"type\": \"wall\", \"position\": [0, \"x\", 0]}]}", "p.json");
        REQUIRE_FALSE(r.ok());
        CHECK(r.error().str().find("p.json:2:56: entities[0].position[1]: expected a number") !=
              std::string::npos);
    }
    SUBCASE("every bad document, at its line:column") {
        for (const ks::test::BadDocument& bad : ks::test::bad_documents()) {
            CAPTURE(bad.name);
            auto r = prefab_from_text(bad.text, "p.json");
            REQUIRE_FALSE(r.ok());
            CHECK(r.error().str().find("p.json" + bad.place + bad.message) != std::string::npos);
        }
    }
}

TEST_CASE("frames: into and out of a turned frame is exact at quarter turns, patrols turn along") {
    level::Entity robot;
    robot.props = level::default_props(level::EntityType::Robot);
    robot.position = Vec3(3, 0, 1);
    robot.rotation = Vec3(30, 0, 0);
    robot.as<level::RobotProps>().patrol.points = {Vec3(3, 0, 1), Vec3(6, 0, 1)};
    const Frame frame{Vec3(10, 2, -4), 90.0f};
    const level::Entity world = entity_out_of_frame(robot, frame);
    CHECK(world.position == Vec3(11, 2, -7)); // +x turns toward -z
    CHECK(world.rotation.x == doctest::Approx(120));
    CHECK(world.as<level::RobotProps>().patrol.points[1] == Vec3(11, 2, -10));
    const level::Entity back = entity_into_frame(world, frame);
    CHECK(differing_fields(back, robot).empty());
    level::Entity moved = back;
    moved.position.x += 0.5f;
    moved.links.push_back({"on_death", "level", "win", 0.0f, false});
    CHECK(differing_fields(moved, robot) == std::vector<std::string>{"position", "links"});
}

TEST_CASE("save a selection as a prefab, place instances: turned, unique names, links kept inside") {
    test::ScratchDir dir;
    Editor ed = doorway(dir.path());
    auto saved = save_prefab(ed, "doorway", "Doorway with a mat");
    REQUIRE(saved.ok());
    CHECK(std::filesystem::exists(dir / "doorway.json"));
    // The selection became instance 1 of it.
    const level::Group* first = ed.level().editor.find_group(1);
    REQUIRE(first);
    CHECK(first->has_prefab);
    CHECK(first->prefab.members == std::vector<int>{1, 2, 3, 4});
    CHECK(!save_prefab(ed, "doorway").ok()); // exists: not replaced by accident

    auto placed = place_prefab(ed, "doorway", Vec3(0, 0, 40), 90);
    REQUIRE(placed.ok());
    CHECK(*placed == 2);
    CHECK(ed.doc().selection.size() == 4);
    const level::Entity& gate = member(ed, 2, 2);
    CHECK(gate.name == "Gate_2");
    CHECK(gate.rotation.x == doctest::Approx(90));
    const level::Entity& mat = member(ed, 2, 3);
    CHECK(mat.links.front().target == "Gate_2"); // the copy's trigger opens the copy's door
    CHECK(mat.position.x == doctest::Approx(2)); // (0, 2) from the origin (0, 0, 2), turned: (2, 0)
    CHECK(mat.position.z == doctest::Approx(40));
    CHECK(ed.undo());
    CHECK(ed.level().entities.size() == 4);
    CHECK(ed.level().editor.groups.size() == 1);

    auto missing = place_prefab(ed, "doorwya", Vec3(0));
    REQUIRE(!missing.ok());
    CHECK(missing.error().str().find("did you mean 'doorway'") != std::string::npos);
}

TEST_CASE("overrides are recorded, kept when the prefab changes, reverted; moving the instance is none") {
    test::ScratchDir dir;
    Editor ed = doorway(dir.path());
    REQUIRE(save_prefab(ed, "doorway").ok());
    REQUIRE(place_prefab(ed, "doorway", Vec3(0, 0, 40), 0).ok());
    // Moving the whole instance changes no member relative to its frame.
    REQUIRE(select_picked(ed, 5).ok());
    REQUIRE(move_selection(ed, Vec3(2, 0, 0)).ok());
    REQUIRE(rotate_selection(ed, 90).ok());
    for (const auto& overrides : ed.level().editor.find_group(2)->prefab.overrides) CHECK(overrides.empty());
    // An edited member field is an override of that member.
    REQUIRE(select(ed, {7}).ok()); // the second instance's door
    REQUIRE(set_field(ed, "width", FieldValue(6.0)).ok());
    CHECK(ed.level().editor.find_group(2)->prefab.overrides[2] == std::vector<std::string>{"width"});

    // The first instance is edited and applied: the second follows, except its overridden width.
    REQUIRE(select(ed, {3}).ok());
    REQUIRE(set_field(ed, "height", FieldValue(12.0)).ok());
    REQUIRE(set_field(ed, "width", FieldValue(4.5)).ok());
    REQUIRE(apply_instance_to_prefab(ed, 1).ok());
    CHECK(ed.level().editor.find_group(1)->prefab.overrides[2].empty());
    const level::Entity& door = member(ed, 2, 2);
    CHECK(door.as<level::DoorProps>().height == doctest::Approx(12));
    CHECK(door.as<level::DoorProps>().width == doctest::Approx(6));
    // Revert: the width follows the prefab again.
    REQUIRE(revert_prefab_overrides(ed, 2, 7, "width").ok());
    CHECK(member(ed, 2, 2).as<level::DoorProps>().width == doctest::Approx(4.5));
    CHECK(!revert_prefab_overrides(ed, 2, 7, "width").ok()); // nothing left to revert
    // Unlink: a plain group that no longer follows.
    REQUIRE(unlink_prefab(ed, 2).ok());
    CHECK(!ed.level().editor.find_group(2)->has_prefab);
    CHECK(!unlink_prefab(ed, 2).ok());
}

TEST_CASE(
    "a prefab changed on disk: instances follow when the level is reopened; deleted members stay deleted") {
    test::ScratchDir dir;
    std::filesystem::create_directories(dir / "prefabs");
    Editor ed = doorway(dir / "prefabs");
    REQUIRE(save_prefab(ed, "doorway").ok());
    REQUIRE(place_prefab(ed, "doorway", Vec3(0, 0, 40)).ok());
    REQUIRE(delete_entities(ed, {5}).ok()); // the second instance's west wall
    CHECK(ed.level().editor.find_group(2)->prefab.members[0] == 0);
    REQUIRE(save_as(ed, dir / "level.json").ok());

    // Another session changes the prefab: the walls get taller, and a light joins.
    auto text = files::read_text(dir / "prefabs" / "doorway.json");
    REQUIRE(text.ok());
    auto prefab = prefab_from_text(*text, "doorway.json");
    REQUIRE(prefab.ok());
    for (level::Entity& e : prefab->entities)
        if (auto* wall = e.try_as<level::WallProps>()) wall->size.y = 20;
    level::Entity light;
    light.props = level::default_props(level::EntityType::TopLight);
    light.position = Vec3(0, 12, 2);
    light.id = 5;
    prefab->entities.push_back(light);
    REQUIRE(files::write_atomic(dir / "prefabs" / "doorway.json", prefab_to_text(*prefab)).ok());

    Editor again;
    again.prefabs().set_folders({dir / "prefabs"});
    REQUIRE(open(again, dir / "level.json").ok());
    CHECK(again.has_unsaved_changes()); // the update is a step of its own
    CHECK(again.history().undo_name().find("Update prefab instances (doorway)") == 0);
    CHECK(member(again, 2, 1).as<level::WallProps>().size.y == doctest::Approx(20));
    CHECK(again.level().editor.find_group(2)->prefab.members[0] == 0); // still deleted
    CHECK(again.level().editor.find_group(2)->prefab.members.size() == 5);
    CHECK(member(again, 2, 4).position.z == doctest::Approx(42));
    CHECK(again.level().editor.find_group(1)->prefab.members.size() == 5);
    CHECK(again.undo());
    CHECK(again.level().entities.size() == 7);
}

TEST_CASE("the script's prefab lines") {
    test::ScratchDir dir;
    Editor ed;
    auto report = run_script_text(R"(
prefab folder prefabs
place wall at -5,0,0 name West
place door at 0,0,0 name Gate
select 1 2
prefab save gate title A gate
expect instance 1 gate 2
prefab place gate at 0,0,30 yaw 180
expect instance 2 gate 2
select 4
set width 6
expect override 2 4 width
expect no_override 2 3 width
prefab revert 2 4
expect no_override 2 4 width
prefab apply 1
prefab unlink 2
expect groups 2
)",
                                  "prefabs.kss", dir.path(), ed);
    REQUIRE_MESSAGE(report.ok(), (report.ok() ? "" : report.error().str()));
    CHECK(report->saved.size() == 2);
    CHECK(std::filesystem::exists(dir / "prefabs" / "gate.json"));
}

TEST_CASE("the shipped prefabs load, place into a level and give a valid level") {
    Editor ed;
    ed.prefabs().set_folders({test::source_dir() / "prefabs"});
    ed.prefabs().rescan();
    std::vector<std::string> names;
    for (const PrefabEntry& entry : ed.prefabs().entries()) {
        INFO(entry.path.string());
        REQUIRE_MESSAGE(entry.prefab.ok(), (entry.prefab.ok() ? "" : entry.prefab.error().str()));
        names.push_back(entry.name);
    }
    for (const char* shipped : {"doorway", "stair_platform", "lit_corridor"})
        CHECK(std::find(names.begin(), names.end(), shipped) != names.end());
    float z = 0;
    for (const std::string& name : names) {
        REQUIRE(place_prefab(ed, name, Vec3(0, 0, z)).ok());
        z += 60;
    }
    const level::LoadReport report = level::validate(ed.level());
    CHECK_MESSAGE(!report.has_errors(),
                  (report.diagnostics.empty() ? "" : report.diagnostics.front().error.str()));
}

TEST_CASE("the prefab rule: an instance whose prefab is gone is a warning, fixed by unlinking it") {
    test::ScratchDir dir;
    Editor ed = doorway(dir.path());
    REQUIRE(save_prefab(ed, "doorway").ok());
    auto prefab_issue = [&]() -> const Issue* {
        for (const Issue& issue : ed.issues())
            if (issue.rule == Rule::Prefab) return &issue;
        return nullptr;
    };
    CHECK(prefab_issue() == nullptr);
    std::filesystem::rename(dir / "doorway.json", dir / "doorway_old.json");
    ed.prefabs().rescan();
    const Issue* issue = prefab_issue();
    REQUIRE(issue);
    CHECK(issue->severity == IssueSeverity::Warning);
    CHECK(issue->entity_id == 1);
    CHECK(issue->message.find("no prefab named 'doorway'") != std::string::npos);
    CHECK(issue->message.find("prefabs: doorway_old") != std::string::npos);
    REQUIRE(apply_quick_fix(ed, *issue).ok());
    CHECK(!ed.level().editor.find_group(1)->has_prefab);
    CHECK(prefab_issue() == nullptr);
}
