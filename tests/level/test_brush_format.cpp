// The brush entity in the level file (version 3): its faces round-trip exactly, its world brush follows the
// entity's frame, and every bad brush is an error at its line:column naming the brush, the face and the
// field, with a fix; an unknown material is a warning tagged like a wall's unknown texture.
#include "brush/brush_build.h"
#include "core/random.h"
#include "jsonio/number_text.h"
#include "level/entity_shapes.h"
#include "level/level_io.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <chrono>
#include <cmath>

using namespace ks;
using namespace ks::level;

namespace {

std::string face(const std::string& plane, const std::string& rest = "") {
    return R"({"plane": )" + plane + rest + "}";
}

// A level with one brush entity (id 7, "Block") whose faces are `faces` (JSON array text).
std::string brush_level(const std::string& faces, const std::string& position = "[0, 0, 0]") {
    return R"({"format": "killswitch-level", "version": 3, "entities": [
  {"id": 1, "type": "floor", "position": [0, 0, 0], "props": {"size": [40, 40]}},
  {"id": 7, "type": "brush", "name": "Block", "position": )" +
           position + R"(, "props": {"faces": )" + faces + "}}\n]}\n";
}

// The six faces of the box [-1, 1] x [0, 2] x [-1, 1], each on its own line.
std::vector<std::string> box_faces() {
    return {face("[-1, 0, 0, 1]"), face("[1, 0, 0, 1]"),  face("[0, -1, 0, 0]"),
            face("[0, 1, 0, 2]"),  face("[0, 0, -1, 1]"), face("[0, 0, 1, 1]")};
}

std::string faces_text(const std::vector<std::string>& faces) {
    std::string out = "[\n";
    for (size_t i = 0; i < faces.size(); ++i)
        out += "    " + faces[i] + (i + 1 < faces.size() ? ",\n" : "\n");
    return out + "  ]";
}

// Loads `text` expecting it to fail; returns the report.
LoadReport refused(const std::string& text) {
    LoadReport report;
    auto level = load_level_string(text, "brush.json", &report);
    CHECK_FALSE(level.ok());
    return report;
}

const Diagnostic* find_at(const LoadReport& report, const std::string& path) {
    for (const Diagnostic& d : report.diagnostics)
        if (d.error.where.path == path) return &d;
    return nullptr;
}

} // namespace

TEST_CASE("the default brush is a 4 x 4 x 4 concrete box standing on the entity's position") {
    Level level;
    const Entity& e = level.add(EntityType::Brush, {0, 0, 0});
    const brush::Brush& b = e.as<BrushProps>().brush;
    CHECK(b.faces().size() == 6);
    CHECK(b.vertices().size() == 8);
    CHECK(b.volume() == doctest::Approx(64.0));
    CHECK(b.bounds_min() == DVec3(-2, 0, -2));
    CHECK(b.bounds_max() == DVec3(2, 4, 2));
    for (const brush::Face& f : b.faces()) CHECK(f.attributes.material == "concrete");
    CHECK(validate(level).diagnostics.empty());
}

TEST_CASE("brush faces save as planes and attributes and load back bit for bit") {
    Level level;
    Entity& e = level.add(EntityType::Brush, {3, 1, -2}, "Wedge");
    e.rotation = {33, 0, 0};
    std::vector<brush::Face> faces = brush::make_box({-3, 0, -4}, {3, 4, 4}).value().faces();
    const DVec3 slope = glm::normalize(DVec3(0.1, 2, 1)); // full-precision components
    faces.push_back({{slope, 3.0 * slope.y}, {"metal", {0.1, -0.3}, {2, 0.5}, 12.5}});
    e.as<BrushProps>().brush = brush::Brush::from_faces(faces).value();
    const std::string text = save_level_string(level);
    CHECK(text.find(R"({
            "plane": [-1, 0, 0, 3],
            "material": "",
            "offset": [0, 0],
            "scale": [1, 1],
            "rotation": 0
          })") != std::string::npos);
    // make_box leaves the material empty: an error on load, and in memory.
    CHECK(validate(level).has_errors());
    for (brush::Face& f : faces)
        if (f.attributes.material.empty()) f.attributes.material = "concrete";
    e.as<BrushProps>().brush = brush::Brush::from_faces(faces).value();
    const std::string good = save_level_string(level);
    LoadReport report;
    auto back = load_level_string(good, "wedge.json", &report);
    REQUIRE_MESSAGE(back.ok(), report.str());
    CHECK(report.diagnostics.empty());
    CHECK(*back == level); // every plane and attribute exactly
    CHECK(save_level_string(*back) == good);
}

TEST_CASE("a hand-written brush: normals of any length are normalised, and attributes default") {
    const std::string text = brush_level(
        faces_text({face("[-2, 0, 0, 2]"), face("[3, 0, 0, 3]"), face("[0, -1, 0, 0]"), face("[0, 4, 0, 8]"),
                    face("[0, 0, -1, 1]"), face("[0, 0, 1, 1]", R"(, "material": "wood")")}));
    LoadReport report;
    auto level = load_level_string(text, "hand.json", &report);
    REQUIRE_MESSAGE(level.ok(), report.str());
    CHECK(report.diagnostics.empty());
    const brush::Brush& b = level->entities[1].as<BrushProps>().brush;
    CHECK(b.volume() == doctest::Approx(8.0));
    CHECK(b.faces()[3].plane.normal == DVec3(0, 1, 0));
    CHECK(b.faces()[3].plane.distance == 2.0);
    CHECK(b.faces()[0].attributes.material == "concrete");
    CHECK(b.faces()[5].attributes.material == "wood");
    CHECK(b.faces()[0].attributes.scale == glm::dvec2(1, 1));
}

TEST_CASE("the world brush is the entity's brush turned by its rotation and moved to its position") {
    Level level;
    Entity& e = level.add(EntityType::Brush, {10, 2, -5});
    e.rotation = {90, 0, 0}; // yaw 90: local -z faces -x
    e.as<BrushProps>().brush = brush::make_box({-1, 0, -3}, {1, 2, 3}, {"tiles"}).value();
    auto world = world_brush(e);
    REQUIRE(world.ok());
    CHECK(world->bounds_min().x == doctest::Approx(7.0));
    CHECK(world->bounds_max().x == doctest::Approx(13.0));
    CHECK(world->bounds_min().z == doctest::Approx(-6.0));
    CHECK(world->bounds_max().z == doctest::Approx(-4.0));
    CHECK(world->bounds_min().y == doctest::Approx(2.0));
    CHECK(world->volume() == doctest::Approx(24.0));
    // The editor's box turns with the entity: its frame is the entity's, its extent the local brush's.
    const PlacedShape box = bounding_shape(e);
    CHECK(box.half == Vec3(1, 1, 3));
    CHECK(glm::length(box.centre() - Vec3(10, 3, -5)) < 1e-5f);
    CHECK_FALSE(world_brush(level.add(EntityType::Wall)).ok());
}

TEST_CASE("a brush whose world brush leaves the brush world is an error at its position") {
    LoadReport report = refused(brush_level(faces_text(box_faces()), "[70000, 0, 0]"));
    const Diagnostic* d = find_at(report, "entities[1].position");
    REQUIRE_MESSAGE(d, report.str());
    CHECK(d->error.message.find("brush 7 (\"Block\")") != std::string::npos);
    CHECK(d->error.where.line == 3);
}

TEST_CASE("bad brushes are errors at the face and field, naming the brush, with a fix") {
    struct Case {
        const char* what;
        std::vector<std::string> faces;
        const char* path;    // below entities[1].props.faces
        const char* message; // a piece of the message
    };
    auto with = [](size_t i, const std::string& replacement) {
        std::vector<std::string> faces = box_faces();
        faces[i] = replacement;
        return faces;
    };
    auto plus = [](const std::string& extra) {
        std::vector<std::string> faces = box_faces();
        faces.push_back(extra);
        return faces;
    };
    const std::vector<Case> cases = {
        {"three planes",
         {face("[1, 0, 0, 1]"), face("[0, 1, 0, 1]"), face("[0, 0, 1, 1]")},
         "",
         "at least 4 planes"},
        {"a NaN in a plane", with(2, face(R"([0, "nan", 0, 0])")), "[2].plane[1]", "not a finite number"},
        {"a plane of three numbers", with(1, face("[1, 0, 0]")), "[1].plane",
         "expected an array of 4 numbers"},
        {"no plane", with(4, R"({"material": "wood"})"), "[4].plane", "missing required field"},
        {"a zero normal", with(3, face("[0, 0, 0, 2]")), "[3].plane", "has no direction"},
        {"a plane beyond the world", with(3, face("[0, 1, 0, 1e9]")), "[3].plane[3]", "beyond the world"},
        {"a duplicate plane", plus(face("[0, 2, 0, 4]")), "[6]", "duplicates faces[3]"},
        {"an opposite plane (zero thickness)", with(3, face("[0, 1, 0, 0]")), "[3]", "zero thickness"},
        {"all planes parallel",
         {face("[0, 1, 0, 1]"), face("[0, 1, 0, 2]"), face("[0, 1, 0, 3]"), face("[0, 1, 0, 4]")},
         "[0]",
         "parallel"},
        {"unbounded",
         {face("[1, 0, 0, 1]"), face("[-1, 0, 0, 1]"), face("[0, 1, 0, 1]"), face("[0, -1, 0, 1]")},
         "[0]",
         "unbounded"},
        {"a plane that cuts nothing", plus(face("[0, 1, 0, 5]")), "[6]", ""},
        {"a zero texture scale", with(0, face("[-1, 0, 0, 1]", R"(, "scale": [0, 1])")), "[0].scale[0]",
         "zero or not finite"},
        {"a texture rotation out of range", with(0, face("[-1, 0, 0, 1]", R"(, "rotation": 1e5)")),
         "[0].rotation", "out of range"},
        {"an empty material", with(5, face("[0, 0, 1, 1]", R"(, "material": "")")), "[5].material",
         "material is empty"},
        {"a face that is not an object", with(5, "17"), "[5]", "expected brush face as an object"},
    };
    for (const Case& c : cases) {
        CAPTURE(std::string(c.what));
        const LoadReport report = refused(brush_level(faces_text(c.faces)));
        const std::string path = std::string("entities[1].props.faces") + c.path;
        const Diagnostic* d = find_at(report, path);
        REQUIRE_MESSAGE(d, report.str());
        CHECK(d->severity == Diagnostic::Severity::Error);
        CHECK(d->error.where.file == "brush.json");
        CHECK(d->error.where.line >= 3); // the faces start on line 3 of the file
        CHECK(d->error.where.column > 0);
        CHECK(d->error.message.find(c.message) != std::string::npos);
        CHECK(d->error.message.find("brush 7 (\"Block\")") != std::string::npos);
        CHECK_FALSE(d->error.hint.empty());
    }
}

TEST_CASE("faces that are not an array, and a million planes, are refused at once") {
    LoadReport report = refused(brush_level(R"({"plane": [0, 1, 0, 1]})"));
    REQUIRE(find_at(report, "entities[1].props.faces"));

    std::string million = "[0";
    for (int i = 1; i < 1000000; ++i) million += ",0";
    million += "]";
    const auto start = std::chrono::steady_clock::now();
    report = refused(brush_level(million));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const Diagnostic* d = find_at(report, "entities[1].props.faces");
    REQUIRE_MESSAGE(d, report.str());
    CHECK(d->error.message.find("1000000 faces is beyond the limit of 1024") != std::string::npos);
    CHECK(report.error_count() == 1); // no face was read
    MESSAGE("a faces list of 10^6 entries refused in " << seconds << " s");
    // The time is the document's parse and position map (the same for a million links); the brush reader
    // refuses the list by its size, reading no face. (A million real planes, 23 MB, is the same refusal.)
    CHECK(seconds < 20.0);
}

TEST_CASE("an unknown material is a warning tagged like an unknown texture, with a did-you-mean") {
    std::vector<std::string> faces = box_faces();
    faces[2] = face("[0, -1, 0, 0]", R"(, "material": "concret")");
    const std::string text = brush_level(faces_text(faces));
    LoadReport report;
    auto level = load_level_string(text, "typo.json", &report);
    REQUIRE_MESSAGE(level.ok(), report.str());
    REQUIRE(report.warning_count() == 1);
    const Diagnostic& d = report.diagnostics.front();
    CHECK(d.kind == Diagnostic::Kind::UnknownTexture);
    CHECK(d.suggestion == "concrete");
    CHECK(d.error.where.path == "entities[1].props.faces[2].material");
    CHECK(d.error.where.line == 6);
    CHECK(d.error.message.find("brush 7 (\"Block\"): texture \"concret\"") != std::string::npos);
}

TEST_CASE("a level of 1000 brushes saves and loads back exactly, and how long loading takes") {
    Level level;
    for (int i = 0; i < 1000; ++i) {
        Entity& e = level.add(EntityType::Brush, {float(i % 40) * 8.0f, float(i % 3), float(i / 40) * 8.0f});
        e.rotation = {float(i * 37 % 360) - 180.0f, float(i % 7) - 3.0f, 0.0f};
        std::vector<brush::Face> faces =
            brush::make_box({-2, 0, -2}, {2, 1 + (i % 5), 2}, {"concrete"}).value().faces();
        const DVec3 cut = glm::normalize(DVec3(i % 3 - 1, 3, i % 5 - 2));
        faces.push_back({{cut, 1.0 * cut.y}, {"metal", {0.25, 0}, {2, 2}, 30}}); // through y = 1 at x = z = 0
        e.as<BrushProps>().brush = brush::Brush::from_faces(faces, brush::RedundantPlanes::drop).value();
    }
    const std::string text = save_level_string(level);
    const auto start = std::chrono::steady_clock::now();
    LoadReport report;
    auto back = load_level_string(text, "brushes.json", &report);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    REQUIRE_MESSAGE(back.ok(), report.str());
    CHECK(report.diagnostics.empty());
    CHECK(*back == level);
    MESSAGE("1000 brushes (" << text.size() / 1024 << " KiB): loaded in " << seconds * 1e3 << " ms, "
                             << seconds * 1e6 / 1000 << " us per brush");
}

TEST_CASE(
    "hand-written planes of any direction settle after one save: load -> save -> load -> save is stable") {
    Rng rng(25);
    int settled = 0;
    for (int round = 0; round < 300; ++round) {
        // A box whose six planes are written with normals of random lengths, plus a random slanted cut:
        // normalising must give the same bits every time the file is read.
        auto scaled = [&](const char* n, double d) {
            const double k = 0.5 + rng.uniform_double() * 7.0;
            std::string text = "[";
            for (int i = 0; i < 3; ++i) text += jsonio::shortest_text((n[i] - '1') * k) + ", ";
            return face(text + jsonio::shortest_text(d * k) + "]");
        };
        std::vector<std::string> faces = {scaled("011", 1), scaled("211", 1), scaled("101", 0),
                                          scaled("121", 2), scaled("110", 1), scaled("112", 1)};
        // It cuts off the corner (1, 2, 1), through (0.5, 1.5, 0.5): every face keeps part of itself.
        const DVec3 n(rng.uniform_double() + 0.2, rng.uniform_double() + 0.2, rng.uniform_double() + 0.2);
        faces.push_back(face("[" + jsonio::shortest_text(n.x) + ", " + jsonio::shortest_text(n.y) + ", " +
                             jsonio::shortest_text(n.z) + ", " +
                             jsonio::shortest_text(glm::dot(n, DVec3(0.5, 1.5, 0.5))) + "]"));
        LoadReport report;
        auto first = load_level_string(brush_level(faces_text(faces)), "random.json", &report);
        REQUIRE_MESSAGE(first.ok(), report.str());
        const std::string saved = save_level_string(*first);
        auto second = load_level_string(saved, "saved.json");
        REQUIRE(second.ok());
        CHECK(*second == *first);
        settled += save_level_string(*second) == saved;
    }
    CHECK(settled == 300);
}
