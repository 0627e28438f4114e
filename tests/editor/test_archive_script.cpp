// levels/archive.json is built by the editor script levels/source/archive.kss with the brush commands: the
// script, run into a temporary folder, writes the shipped file byte for byte, the level it builds has no
// validation issue, and its architecture is what the campaign's third level is meant to show (brushes cut
// by subtract and clip, an extruded angled wall, a ramp) with the generated bookshelf placed as a model.
#include "editor_test_util.h"

#include "level/entity_shapes.h"
#include "level/model_entity.h"
#include "model/script.h"

#include <algorithm>

using namespace ks;
using namespace ks::editor;

TEST_CASE("levels/source/archive.kss rebuilds levels/archive.json byte for byte, with no issue") {
    const auto source = ks::test::source_dir() / "levels" / "source" / "archive.kss";
    const std::string script = ks::test::read_file(source);
    REQUIRE_FALSE(script.empty());
    ks::test::ScratchDir dir;
    std::filesystem::create_directories(dir / "source"); // the script saves to ../archive.json
    Editor ed;
    auto report = run_script_text(script, source.string(), dir / "source", ed);
    REQUIRE_MESSAGE(report.ok(), (report.ok() ? std::string() : report.error().str()));
    REQUIRE(report->saved.size() == 1);
    const std::string built = ks::test::read_file(dir / "archive.json");
    const std::string shipped = ks::test::read_file(ks::test::source_dir() / "levels" / "archive.json");
    CHECK_MESSAGE(built == shipped, "levels/archive.json is not what levels/source/archive.kss builds: "
                                    "rebuild it with killswitch-editor --script levels/source/archive.kss");
    for (const Issue& issue : ed.issues()) {
        INFO(issue.message);
        CHECK_MESSAGE(false, "issue on entity ", issue.entity_id);
    }

    // The arch wall is in pieces around the arch and the windows; the arch's pieces have sloped faces
    // (the arc), the hall's ceiling a sloped underside, the ramp a slope, the angled wall a 45-degree face.
    const level::Level& lv = ed.level();
    auto faces_of = [&](const std::string& name_prefix) {
        std::vector<brush::Face> faces;
        int pieces = 0;
        for (const level::Entity& e : lv.entities) {
            if (e.type() != level::EntityType::Brush || e.name.rfind(name_prefix, 0) != 0) continue;
            ++pieces;
            auto world = level::world_brush(e);
            REQUIRE(world.ok());
            faces.insert(faces.end(), world->faces().begin(), world->faces().end());
        }
        return std::pair{pieces, faces};
    };
    auto leaning = [](const std::vector<brush::Face>& faces) {
        return std::count_if(faces.begin(), faces.end(), [](const brush::Face& f) {
            const DVec3 n = glm::abs(f.plane.normal);
            return std::max({n.x, n.y, n.z}) < 0.9999;
        });
    };
    const auto [arch_pieces, arch_faces] = faces_of("Arch wall");
    CHECK(arch_pieces >= 6);
    CHECK(leaning(arch_faces) >= 4);
    CHECK(leaning(faces_of("Hall ceiling").second) == 1);
    CHECK(leaning(faces_of("Ramp").second) == 1);
    CHECK(leaning(faces_of("Angled wall").second) == 1);
    CHECK(lv.objectives.size() == 2);

    // The shelves: the generated prop read through the designers' model path, with box collision whose
    // brush the game and the navigation mesh use, standing on the floor against the west wall.
    int shelves = 0;
    for (const level::Entity& e : lv.entities) {
        if (e.type() != level::EntityType::Model) continue;
        ++shelves;
        CAPTURE(e.name);
        CHECK(e.as<level::ModelProps>().file == "archive_shelf.gltf");
        CHECK(e.as<level::ModelProps>().collision.value == "box");
        auto model = level::entity_model(e);
        REQUIRE_MESSAGE(model.ok(), (model.ok() ? std::string() : model.error().str()));
        CHECK((*model)->triangle_count > 1000);
        auto collision = level::model_collision(e);
        REQUIRE(collision.ok());
        REQUIRE(collision->size() == 1);
        const DVec3 lo = collision->front().bounds_min(), hi = collision->front().bounds_max();
        CHECK(lo.y == doctest::Approx(0.0).epsilon(0.01));
        CHECK(lo.x > -16.0); // clear of the wall's inner face
        CHECK(hi.x < -14.0);
    }
    CHECK(shelves == 2);
}
