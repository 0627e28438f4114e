// The model entity: its fields in the file, its validation (a badly spelt file is an error, a missing or
// broken one a warning so the level still opens), the designer's models folder, and its collision as a brush.
#include "../../bench/brush/solid_meshes.h"
#include "brush/brush.h"
#include "level/level_io.h"
#include "level/model_entity.h"
#include "modelio/model_files.h"
#include "modelio/model_writers.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <sstream>

using namespace ks;
using namespace ks::level;

namespace {

using test::ScratchDataHome;

// A UV sphere of `rings` x `segments` quads as OBJ text, radius 1 centred on (0, 1, 0).
std::string sphere_obj(int rings, int segments) {
    std::ostringstream obj;
    for (int r = 0; r <= rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const double t = kPi * r / rings, p = 2 * kPi * s / segments;
            obj << "v " << std::sin(t) * std::cos(p) << " " << 1 + std::cos(t) << " "
                << std::sin(t) * std::sin(p) << "\n";
        }
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const int a = r * segments + s + 1, b = r * segments + (s + 1) % segments + 1;
            obj << "f " << a << " " << a + segments << " " << b + segments << " " << b << "\n";
        }
    return obj.str();
}

const char* const kCubeObj =
    "v -1 0 -1\nv 1 0 -1\nv 1 2 -1\nv -1 2 -1\nv -1 0 1\nv 1 0 1\nv 1 2 1\nv -1 2 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 5 8 4\nf 2 3 7 6\nf 4 8 7 3\nf 1 2 6 5\n";

Entity model_entity(const std::string& file, const std::string& collision, float scale = 1.0f) {
    Level level;
    Entity& e = level.add(EntityType::Model, {10, 0, 5}, "Prop");
    e.as<ModelProps>().file = file;
    e.as<ModelProps>().scale = scale;
    e.as<ModelProps>().collision.value = collision;
    return e;
}

bool inside_any(const std::vector<brush::Brush>& brushes, const DVec3& p) {
    for (const brush::Brush& b : brushes) {
        bool inside = true;
        for (const brush::Face& f : b.faces()) inside &= f.plane.signed_distance(p) <= 1e-9;
        if (inside) return true;
    }
    return false;
}

} // namespace

TEST_CASE(
    "model entity: \"hulls\" collision is the model's convex decomposition, capped, scaled and turned") {
    ScratchDataHome home;
    test::write_file(home.models() / "arch.obj",
                     brush::bench::obj_text(brush::bench::arch())); // 4 wide, 4 tall, 1 deep
    Entity arch = model_entity("arch.obj", "hulls", 2.0f);
    arch.rotation = {90, 0, 0};
    auto hulls = model_collision(arch);
    REQUIRE_MESSAGE(hulls.ok(), hulls.error().str());
    CHECK(hulls->size() == 3); // two pillars and the lintel
    // Turned a quarter about y and doubled, standing on (10, 0, 5): the opening is under the lintel's middle.
    const glm::dmat3 turn = glm::mat3_cast(dquat_from_ypr_degrees(DVec3(90, 0, 0)));
    auto world = [&](const DVec3& model_point) { return turn * (model_point * 2.0) + DVec3(10, 0, 5); };
    CHECK_FALSE(inside_any(*hulls, world({2.0, 1.0, 0.5}))); // the opening
    CHECK(inside_any(*hulls, world({0.5, 1.0, 0.5})));       // a pillar
    CHECK(inside_any(*hulls, world({2.0, 3.5, 0.5})));       // the lintel
    CHECK_FALSE(inside_any(*hulls, world({2.0, 1.0, 1.5}))); // beside it

    arch.as<ModelProps>().hulls = 1; // the cap: one hull, the opening filled
    auto one = model_collision(arch);
    REQUIRE(one.ok());
    CHECK(one->size() == 1);
    CHECK(inside_any(*one, world({2.0, 1.0, 0.5})));

    test::write_file(home.models() / "flat.obj", "v 0 0 0\nv 1 0 0\nv 0 0 1\nf 1 2 3\n");
    auto flat = model_collision(model_entity("flat.obj", "hulls"));
    REQUIRE_FALSE(flat.ok());
    CHECK(test::contains_text(flat.error().str(), "no volume"));
    CHECK(test::contains_text(flat.error().str(), "choose collision"));

    // The field is written only when it is not the default, and read back.
    Level level;
    Entity& saved = level.add(EntityType::Model, {0, 0, 0}, "Arch");
    saved.as<ModelProps>().file = "arch.obj";
    saved.as<ModelProps>().collision.value = "hulls";
    CHECK(save_level_string(level).find("\"hulls\":") == std::string::npos);
    saved.as<ModelProps>().hulls = 3;
    const std::string text = save_level_string(level);
    CHECK(text.find("\"hulls\": 3") != std::string::npos);
    LoadReport report;
    auto back = load_level_string(text, "arch.json", &report);
    REQUIRE_MESSAGE(back.ok(), report.str());
    CHECK(*back == level);
    saved.as<ModelProps>().hulls = 0;
    LoadReport refused;
    CHECK_FALSE(load_level_string(save_level_string(level), "arch.json", &refused).ok());
    CHECK(test::contains_text(refused.str(), "entities[0].props.hulls"));
}

TEST_CASE("model entity: saved and loaded with its fields; a version-3 file loads silently") {
    Level level;
    auto& props = level.add(EntityType::Model, {1, 2, 3}, "Crate").as<ModelProps>();
    props.file = "door.gltf";
    props.scale = 2.5f;
    props.collision.value = "box";
    LoadReport report;
    auto back = load_level_string(save_level_string(level), "model.json", &report);
    REQUIRE_MESSAGE(back.ok(), report.str());
    CHECK(report.diagnostics.empty());
    CHECK(*back == level);

    LoadReport v3;
    CHECK(load_level_file(test::data_dir() / "levels/good/version3_migration.json", &v3).ok());
    CHECK_MESSAGE(v3.diagnostics.empty(), v3.str());
}

TEST_CASE(
    "model entity: a badly spelt file is an error at props.file; a missing file a warning, the level opens") {
    auto load = [](const std::string& file, const std::string& extra = "") {
        LoadReport report;
        const std::string text = R"({"format": "killswitch-level", "version": 4, "entities": [
  {"id": 1, "type": "model", "name": "Crate", "position": [0, 0, 0], "props": {"file": ")" +
                                 file + "\"" + extra + "}}]}";
        auto level = load_level_string(text, "models.json", &report);
        return std::make_pair(level.ok(), report.str());
    };
    for (const char* bad : {"../secret.glb", "/abs/crate.glb", "crate.blend", "a//b.glb", "a\\\\b.glb"}) {
        auto [loaded, text] = load(bad);
        INFO(bad, " ", text);
        CHECK_FALSE(loaded);
        CHECK(test::contains_text(text, "entities[0].props.file"));
        CHECK(test::contains_text(text, "model 1"));
    }
    auto [meshed, mesh_text] = load("door.gltf", R"(, "collision": "mesh")");
    CHECK_MESSAGE(meshed, mesh_text);
    CHECK_MESSAGE(mesh_text.find("warning") == std::string::npos, mesh_text);
    auto [loaded, text] = load("nowhere/crate.glb");
    CHECK(loaded);
    CHECK(test::contains_text(text, "warning"));
    CHECK(test::contains_text(text, "no such model file"));
    CHECK(test::contains_text(text, "nowhere/crate.glb"));
    auto [scaled, scale_text] = load("door.gltf", R"(, "scale": 0)");
    CHECK_FALSE(scaled);
    CHECK(test::contains_text(scale_text, "entities[0].props.scale"));
    auto [chosen, choice_text] = load("door.gltf", R"(, "collision": "sphere")");
    CHECK_FALSE(chosen);
    CHECK(test::contains_text(choice_text, "entities[0].props.collision"));
}

TEST_CASE("model entity: the user's models folder; box and hull collision as brushes, turned and scaled") {
    ScratchDataHome home;
    test::write_file(home.models() / "cube.obj", kCubeObj);
    CHECK(modelio::resolve_model_file("cube.obj") == home.models() / "cube.obj");
    CHECK(modelio::resolve_model_file("door.gltf").parent_path().filename() ==
          "models"); // the shipped one first

    Entity none = model_entity("cube.obj", "none");
    auto no_body = model_collision(none);
    REQUIRE(no_body.ok());
    CHECK(no_body->empty());

    Entity box = model_entity("cube.obj", "box", 2.0f);
    box.rotation = {90, 0, 0};
    auto box_brush = model_collision(box);
    REQUIRE_MESSAGE(box_brush.ok(), box_brush.error().str());
    REQUIRE(box_brush->size() == 1);
    CHECK(box_brush->front().bounds_min().x == doctest::Approx(8.0));
    CHECK(box_brush->front().bounds_max().y == doctest::Approx(4.0));
    CHECK(box_brush->front().bounds_max().z == doctest::Approx(7.0));
    const PlacedShape picked = bounding_shape(box);
    CHECK(picked.half.x == doctest::Approx(2.0f));
    CHECK(picked.centre().y == doctest::Approx(2.0f));

    test::write_file(home.models() / "ball.obj", sphere_obj(24, 48));
    Entity hull = model_entity("ball.obj", "hull");
    auto hull_brush = model_collision(hull);
    REQUIRE_MESSAGE(hull_brush.ok(), hull_brush.error().str());
    REQUIRE(hull_brush->size() == 1);
    const brush::Brush& b = hull_brush->front();
    CHECK(b.faces().size() <= kMaxModelHullFaces);
    CHECK(b.bounds_max().y == doctest::Approx(2.0).epsilon(0.05));
    CHECK(b.bounds_min().x == doctest::Approx(9.0).epsilon(0.05));
    for (const DVec3& v : b.vertices()) // every corner near the sphere: the hull hugs it
        CHECK(std::abs(glm::length(v - DVec3(10, 1, 5)) - 1.0) < 0.11); // within the snapping grid's step

    test::write_file(home.models() / "flat.obj", "v 0 0 0\nv 1 0 0\nv 0 0 1\nf 1 2 3\n");
    auto flat = model_collision(model_entity("flat.obj", "hull"));
    REQUIRE_FALSE(flat.ok());
    CHECK(test::contains_text(flat.error().str(), "choose collision"));
    CHECK(model_collision(model_entity("flat.obj", "box")).ok() == false); // a box with no height
}

TEST_CASE("model entity: mesh collision is the model's triangles, turned, scaled and placed") {
    ScratchDataHome home;
    test::write_file(home.models() / "cube.obj", kCubeObj);
    Entity cube = model_entity("cube.obj", "mesh", 2.0f);
    cube.rotation = {90, 0, 0};
    auto none = model_collision(cube); // no brush: the triangles are the collision
    REQUIRE(none.ok());
    CHECK(none->empty());
    auto mesh = model_mesh_collision(cube);
    REQUIRE_MESSAGE(mesh.ok(), mesh.error().str());
    REQUIRE(mesh->has_value());
    CHECK((**mesh).triangles.size() == 12); // six quads
    DVec3 lo(1e9), hi(-1e9);
    for (const auto& t : (**mesh).triangles)
        for (std::uint32_t i : t)
            lo = glm::min(lo, (**mesh).vertices[i]), hi = glm::max(hi, (**mesh).vertices[i]);
    CHECK(lo.x == doctest::Approx(8.0)); // the box collision's bounds: the same placement
    CHECK(hi.y == doctest::Approx(4.0));
    CHECK(hi.z == doctest::Approx(7.0));
    auto hull = model_mesh_collision(model_entity("cube.obj", "hull"));
    REQUIRE(hull.ok());
    CHECK_FALSE(hull->has_value());
    auto missing = model_mesh_collision(model_entity("gone.obj", "mesh"));
    REQUIRE_FALSE(missing.ok());
    CHECK(test::contains_text(missing.error().str(), "gone.obj"));
}

TEST_CASE(
    "model entity: a .glb whose embedded texture is broken loads as a warning naming file and texture") {
    ScratchDataHome home;
    test::write_glb_cube(home.models(), "painted", {.image = "definitely not a picture"});
    const std::string text = R"({"format": "killswitch-level", "version": 4, "entities": [
  {"id": 1, "type": "model", "name": "Crate", "position": [0, 0, 0], "props": {"file": "painted.glb"}}]})";
    LoadReport report;
    auto level = load_level_string(text, "painted.json", &report);
    REQUIRE_MESSAGE(level.ok(), report.str()); // the level opens: the model is drawn as a marker
    const std::string said = report.str();
    INFO(said);
    CHECK(test::contains_text(said, "warning"));
    CHECK(test::contains_text(said, "painted.glb"));
    CHECK(test::contains_text(said, "is not an image the game reads"));
    CHECK(test::contains_text(said, "entities[0].props.file"));
    auto none = model_collision(level->entities.at(0)); // no collision either: the same error, not a crash
    CHECK_FALSE(none.ok());
}
