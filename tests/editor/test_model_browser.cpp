// The Models tab's library (model_library.h: both folders listed, searched, a change on disk picked up),
// placing a model (edit_models.h: one entity, one undo step) and its collision overlay
// (model_collision_wire.h: the segments are the collision's own edges).
#include "editor_test_util.h"
#include "level/model_entity.h"
#include "model/edit_entities.h"
#include "model/edit_models.h"
#include "model/model_collision_wire.h"
#include "model/model_library.h"
#include "model/quick_fix.h"
#include "model/validation.h"
#include "test_support.h"
#include "view/model_drop.h"

#include <cstdlib>
#include <filesystem>

using namespace ks;
using namespace ks::editor;

namespace {

// The user's models folder (with a props/ folder) and a stand-in shipped folder, both scratch.
class ScratchModels {
  public:
    ScratchModels() {
        std::filesystem::create_directories(user() / "props");
        std::filesystem::create_directories(shipped());
    }
    std::filesystem::path user() const { return home_.models(); }
    std::filesystem::path shipped() const { return home_.path() / "shipped"; }

  private:
    test::ScratchDataHome home_;
};

// A box 2 wide, 2 tall, 2 deep standing on its origin, its faces' corners shared (8 vertices).
const char* const kCubeObj =
    "v -1 0 -1\nv 1 0 -1\nv 1 2 -1\nv -1 2 -1\nv -1 0 1\nv 1 0 1\nv 1 2 1\nv -1 2 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 5 8 4\nf 2 3 7 6\nf 4 8 7 3\nf 1 2 6 5\n";

std::vector<std::string> names_of(const std::vector<const ModelEntry*>& entries) {
    std::vector<std::string> names;
    for (const ModelEntry* e : entries) names.push_back(e->name);
    return names;
}

} // namespace

TEST_CASE("model browser: both folders listed by name, searched by words, changes on disk picked up") {
    ScratchModels scratch;
    test::write_file(scratch.shipped() / "crate.glb", "shipped");
    test::write_file(scratch.shipped() / "notes.txt", "not a model");
    test::write_file(scratch.user() / "props/Red Crate.obj", kCubeObj);
    test::write_file(scratch.user() / "props/pipe_run.fbx", "fbx");
    test::write_file(scratch.user() / "crate.glb", "the designer's, shadowed by the shipped one");
    ModelLibrary library(scratch.shipped(), scratch.user());
    CHECK(library.rescan());
    const std::uint64_t revision = library.revision();
    CHECK(names_of(library.search("")) ==
          std::vector<std::string>{"crate.glb", "crate.glb", "props/Red Crate.obj", "props/pipe_run.fbx"});
    CHECK(library.entries()[0].shipped);
    CHECK_FALSE(library.entries()[0].shadowed);
    CHECK(library.entries()[1].shadowed);
    CHECK(library.find("crate.glb")->shipped);
    CHECK(names_of(library.search("CRATE red")) == std::vector<std::string>{"props/Red Crate.obj"});
    CHECK(names_of(library.search("props pipe")) == std::vector<std::string>{"props/pipe_run.fbx"});
    CHECK(library.search("statue").empty());
    CHECK(library.find("nothing.glb") == nullptr);

    CHECK_FALSE(library.rescan()); // nothing changed
    CHECK(library.revision() == revision);
    test::write_file(scratch.user() / "props/pipe_run.fbx", "fbx, exported again and longer");
    CHECK(library.rescan());
    std::filesystem::remove(scratch.user() / "props/Red Crate.obj");
    CHECK(library.rescan());
    CHECK(library.search("red").empty());
    CHECK(library.revision() == revision + 2);
}

TEST_CASE("model browser: placing a model is one entity and one undo step; bad names place nothing") {
    ScratchModels scratch;
    test::write_file(scratch.user() / "props/crate.obj", kCubeObj);
    Editor ed;
    const std::size_t before = ed.level().entities.size();
    Result<int> id = place_model(ed, "props/crate.obj", {4.2f, 0.0f, -3.9f});
    REQUIRE_MESSAGE(id.ok(), id.error().str());
    const level::Entity* e = ed.level().find(*id);
    REQUIRE(e != nullptr);
    CHECK(e->type() == level::EntityType::Model);
    CHECK(e->name == "crate");
    CHECK(e->as<level::ModelProps>().file == "props/crate.obj");
    CHECK(e->position == ed.doc().grid.snap_point({4.2f, 0.0f, -3.9f}));
    CHECK(ed.doc().selection == std::vector<int>{*id});
    CHECK(ed.history().undo_name() == "Place model crate");
    ed.undo();
    CHECK(ed.level().entities.size() == before);
    CHECK(ed.level().find(*id) == nullptr);

    CHECK_FALSE(place_model(ed, "../crate.obj", {0, 0, 0}).ok());
    CHECK_FALSE(place_model(ed, "crate.blend", {0, 0, 0}).ok());
    CHECK(ed.level().entities.size() == before);
}

TEST_CASE(
    "model browser: a thumbnail dropped on a view stands on the surface under the mouse, one undo step") {
    ScratchModels scratch;
    test::write_file(scratch.user() / "props/crate.obj", kCubeObj);
    Editor ed;
    ed.grid().step = 0.5f;
    REQUIRE(place(ed, level::EntityType::Floor, Vec3(0, 2, 0)).ok()); // a slab whose top is at y = 2
    const std::size_t before = ed.level().entities.size();
    const std::string history_before = ed.history().undo_name();
    const ViewCamera top = editor_test::top_view();
    Vec2 mouse;
    REQUIRE(top.project(Vec3(1.3f, 2, -2.2f), mouse));

    // The payload as the Models tab sends it: the name and its terminating zero.
    const std::string name = "props/crate.obj";
    const std::optional<std::string> file =
        model_payload_file(name.c_str(), static_cast<int>(name.size() + 1));
    REQUIRE(file);
    CHECK(*file == name);
    // The preview's box and the placed model agree: both are model_drop_point.
    const Vec3 preview = model_drop_point(ed.doc(), top.ray(mouse), editor_test::all_shown, Vec3(0.0f));
    Result<int> id = place_model_at(ed, *file, top.ray(mouse), editor_test::all_shown, Vec3(0.0f));
    REQUIRE_MESSAGE(id.ok(), id.error().str());
    const level::Entity* e = ed.level().find(*id);
    REQUIRE(e != nullptr);
    CHECK(e->type() == level::EntityType::Model);
    CHECK(e->as<level::ModelProps>().file == name);
    CHECK(e->position == preview);
    CHECK(e->position.y == doctest::Approx(2.0f)); // on the slab, not the ground
    CHECK(e->position.x == doctest::Approx(1.5f)); // snapped to the 0.5 grid
    CHECK(e->position.z == doctest::Approx(-2.0f));
    CHECK(ed.doc().selection == std::vector<int>{*id});
    CHECK(ed.level().entities.size() == before + 1);
    CHECK(ed.history().undo_name() == "Place model crate");
    ed.undo(); // one step takes it all back
    CHECK(ed.level().entities.size() == before);
    CHECK(ed.history().undo_name() == history_before);

    // Off the slab: the ground.
    REQUIRE(top.project(Vec3(40.2f, 0, 20.1f), mouse));
    id = place_model_at(ed, name, top.ray(mouse), editor_test::all_shown, Vec3(0.0f));
    REQUIRE(id.ok());
    CHECK(ed.level().find(*id)->position == Vec3(40.0f, 0.0f, 20.0f));
    // A payload that is not a model name places nothing.
    CHECK_FALSE(place_model_at(ed, "../crate.obj", top.ray(mouse), editor_test::all_shown, Vec3(0.0f)).ok());
    CHECK(ed.level().entities.size() == before + 1);
}

TEST_CASE("model browser: a drag payload is a zero-terminated name or nothing") {
    const char good[] = "props/crate.glb";
    CHECK(model_payload_file(good, sizeof(good)) == std::optional<std::string>("props/crate.glb"));
    CHECK_FALSE(model_payload_file(nullptr, 4));
    CHECK_FALSE(model_payload_file(good, 0));
    CHECK_FALSE(model_payload_file(good, 1));                                  // only the zero
    CHECK_FALSE(model_payload_file(good, static_cast<int>(sizeof(good)) - 1)); // no zero at the end
    const char inner[] = "props\0crate.glb";
    CHECK_FALSE(model_payload_file(inner, sizeof(inner))); // a zero inside
    const std::string huge(5000, 'a');
    CHECK_FALSE(model_payload_file(huge.c_str(), static_cast<int>(huge.size() + 1)));
}

TEST_CASE("model browser: the collision overlay is the collision's own edges") {
    ScratchModels scratch;
    test::write_file(scratch.user() / "cube.obj", kCubeObj);
    level::Level level;
    level::Entity& e = level.add(level::EntityType::Model, {10, 0, 5}, "Cube");
    e.rotation = {90, 0, 0};
    auto& props = e.as<level::ModelProps>();
    props.file = "cube.obj";
    props.scale = 2.0f;
    // The box and the hull of a box: its 12 edges, every end a corner of the turned, scaled box (4 x 4 x 4
    // standing on (10, 0, 5)).
    for (const char* collision : {"box", "hull"}) {
        props.collision.value = collision;
        Result<CollisionWire> wire = model_collision_wire(e);
        REQUIRE_MESSAGE(wire.ok(), wire.error().str());
        CHECK(wire->segments.size() == 12);
        for (const auto& segment : wire->segments)
            for (const Vec3& p : segment) {
                CHECK(std::abs(std::abs(p.x - 10.0f) - 2.0f) < 1e-3f);
                CHECK((std::abs(p.y) < 1e-3f || std::abs(p.y - 4.0f) < 1e-3f));
                CHECK(std::abs(std::abs(p.z - 5.0f) - 2.0f) < 1e-3f);
            }
    }
    // The triangle mesh: its 12 box edges and the 6 faces' diagonals, each once.
    props.collision.value = "mesh";
    Result<CollisionWire> mesh = model_collision_wire(e);
    REQUIRE_MESSAGE(mesh.ok(), mesh.error().str());
    CHECK(mesh->segments.size() == 18);
    CHECK_FALSE(mesh->truncated);
    props.collision.value = "none";
    CHECK(model_collision_wire(e)->segments.empty());
    props.collision.value = "box";
    props.file = "gone.obj";
    CHECK_FALSE(model_collision_wire(e).ok());
}

TEST_CASE("model validation: an absurd scale, a missing file and a flat hull, each with its quick fix") {
    ScratchModels scratch;
    test::write_file(scratch.user() / "props/crate.obj", kCubeObj);
    test::write_file(scratch.user() / "props/hall.obj", // 10 units across
                     "v -5 0 -5\nv 5 0 -5\nv 5 10 -5\nv -5 10 -5\nv -5 0 5\nv 5 0 5\nv 5 10 5\nv -5 10 5\n"
                     "f 1 4 3 2\nf 5 6 7 8\nf 1 5 8 4\nf 2 3 7 6\nf 4 8 7 3\nf 1 2 6 5\n");
    test::write_file(scratch.user() / "sheet.obj", "v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\nf 1 2 3 4\n");
    Editor ed;
    auto model_issues = [&](int id) {
        std::vector<Issue> found;
        for (const Issue& issue : ed.issues())
            if (issue.entity_id == id && issue.rule == Rule::Format) found.push_back(issue);
        return found;
    };
    const int crate = *place_model(ed, "props/hall.obj", {0, 0, 0});
    CHECK(model_issues(crate).empty());
    REQUIRE(set_field_text(ed, "scale", "300").ok()); // 10 units across: 3000 placed
    std::vector<Issue> issues = model_issues(crate);
    REQUIRE(issues.size() == 1);
    INFO(issues[0].message);
    CHECK(test::contains_text(issues[0].message, "props.scale"));
    CHECK(test::contains_text(issues[0].message, "3000 units across, larger than a level"));
    CHECK(test::contains_text(issues[0].message, "the file alone is 10 units across"));
    CHECK(issues[0].severity == IssueSeverity::Warning);
    CHECK(issues[0].fix.label == "Reset scale");
    REQUIRE(apply_quick_fix(ed, issues[0]).ok());
    CHECK(ed.level().find(crate)->as<level::ModelProps>().scale == 1.0f);
    CHECK(model_issues(crate).empty());
    ed.undo(); // one step
    CHECK(ed.level().find(crate)->as<level::ModelProps>().scale == 300.0f);
    ed.redo();

    REQUIRE(set_field_text(ed, "file", "props/crates.obj").ok()); // not there; a close name is
    issues = model_issues(crate);
    REQUIRE(issues.size() == 1);
    CHECK(test::contains_text(issues[0].message, "no such model file"));
    CHECK(issues[0].fix.label == "Use props/crate.obj");
    REQUIRE(apply_quick_fix(ed, issues[0]).ok());
    CHECK(ed.level().find(crate)->as<level::ModelProps>().file == "props/crate.obj");

    const int sheet = *place_model(ed, "sheet.obj", {8, 0, 0}); // flat: no hull
    issues = model_issues(sheet);
    REQUIRE_FALSE(issues.empty());
    CHECK(test::contains_text(issues[0].message, "props.collision"));
    CHECK(issues[0].fix.label == "No collision");
    REQUIRE(apply_quick_fix(ed, issues[0]).ok());
    CHECK(model_issues(sheet).empty());
}
