// The surface materials a level may name (level/texture_names.h): read from assets/textures, checked when a
// level loads (a warning naming file, line, entity and field, with a did-you-mean), clean on the shipped
// levels; and which entity types keep pitch and roll (level/entity_shapes.h) against the shapes the game
// builds.
#include "core/paths.h"
#include "level/entity_shapes.h"
#include "level/level_io.h"
#include "level/model_entity.h"
#include "level/texture_names.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

using namespace ks;
using namespace ks::level;

namespace {
const char* kLevelWithTypo = R"({
  "format": "killswitch-level",
  "version": 2,
  "name": "Texture typo",
  "player_start": {"position": [0, 0, 0], "yaw": 0},
  "next_id": 4,
  "entities": [
    {"id": 1, "type": "floor", "name": "Ground", "position": [0, 0, 0], "props": {"texture": "tiles"}},
    {"id": 2, "type": "wall", "name": "North", "position": [0, 0, -10], "props": {"texture": "concret"}},
    {"id": 3, "type": "stair", "position": [5, 0, 0], "props": {"texture": "marble_xyz"}}
  ]
})";

bool has(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}
} // namespace

TEST_CASE("the known textures are the surface materials in assets/textures: a base colour and a height map") {
    const auto& names = shipped_texture_names();
    CHECK(names == surface_texture_names_in(paths::asset("textures")));
    CHECK(std::is_sorted(names.begin(), names.end()));
    for (const char* surface : {"concrete", "tiles", "wood", "ceiling", "metal", "dojo_floor"})
        CHECK(has(names, surface));
    // Model textures (no height map) and particle sprites are not level materials.
    for (const char* model : {"robot", "door", "rifle", "pickup_health", "fire"})
        CHECK_FALSE(has(names, model));

    test::ScratchDir dir;
    for (const char* file : {"brick_basecolor.png", "brick_height.png", "decal_basecolor.png", "notes.txt"})
        std::ofstream(dir / file) << "x";
    CHECK(surface_texture_names_in(dir.path()) == std::vector<std::string>{"brick"});
    CHECK(surface_texture_names_in(dir / "missing").empty());
}

TEST_CASE("a texture field is found by its name on every type that has one") {
    Level level;
    for (EntityType type : all_types()) level.add(type);
    int with_texture = 0;
    for (const Entity& e : level.entities) {
        const auto fields = texture_fields(e);
        with_texture += !fields.empty();
        for (const TextureField& f : fields) {
            // A brush's faces each name a material: "faces[i].material".
            CHECK((is_texture_field(f.field) ||
                   (e.type() == EntityType::Brush && f.field.ends_with("].material"))));
            CHECK(has(shipped_texture_names(), *f.name)); // every default names a shipped material
        }
    }
    CHECK(with_texture == 4); // wall, floor, stair, brush
}

TEST_CASE("loading warns about an unknown texture with file, line, entity, field and a did-you-mean") {
    LoadReport report;
    auto level = load_level_string(kLevelWithTypo, "typo.json", &report);
    REQUIRE_MESSAGE(level.ok(), report.str()); // a warning: the level still loads
    CAPTURE(report.str());
    REQUIRE(report.warning_count() == 2);
    CHECK(report.error_count() == 0);
    const Diagnostic& typo = report.diagnostics[0];
    CHECK(typo.severity == Diagnostic::Severity::Warning);
    CHECK(typo.kind == Diagnostic::Kind::UnknownTexture);
    CHECK(typo.suggestion == "concrete");
    CHECK(typo.error.where.file == "typo.json");
    CHECK(typo.error.where.line == 9);
    CHECK(typo.error.where.path == "entities[1].props.texture");
    CHECK(
        typo.error.message ==
        "wall 2 (\"North\"): texture \"concret\" is not a surface material in assets/textures; did you mean "
        "\"concrete\"?");
    CHECK(typo.error.hint.find("concrete, dojo_floor") != std::string::npos);
    const Diagnostic& far = report.diagnostics[1];
    CHECK(far.suggestion.empty()); // nothing close: the hint lists the materials
    CHECK(far.error.message.find("stair 3: texture \"marble_xyz\"") != std::string::npos);
    CHECK(far.error.where.path == "entities[2].props.texture");

    // validate() finds the same, without text positions; a known name is silent.
    level->entities[1].as<WallProps>().texture = "concrete";
    const LoadReport fixed = validate(*level);
    CHECK(fixed.warning_count() == 1);
    // An empty list (no assets found) checks nothing; an empty name is the format's error, not this one.
    DiagnosticSink sink("x.json");
    check_texture_names(*level, {}, sink);
    CHECK(sink.take_sorted().empty());
    level->entities[2].as<StairProps>().texture.clear();
    const LoadReport empty = validate(*level);
    CHECK(empty.warning_count() == 0);
    CHECK(empty.error_count() == 1);
}

TEST_CASE("the shipped levels name only shipped materials") {
    for (const char* name : {"main.json", "dojo.json"}) {
        LoadReport report;
        auto level = load_level_file(test::source_dir() / "levels" / name, &report);
        REQUIRE(level.ok());
        CHECK_MESSAGE(report.diagnostics.empty(), report.str());
        for (const Entity& e : level->entities)
            for (const TextureField& f : texture_fields(e)) CHECK(has(shipped_texture_names(), *f.name));
    }
}

TEST_CASE("the types that keep pitch and roll are those whose game body turns with them") {
    for (EntityType type : all_types()) {
        Entity e;
        e.props = default_props(type);
        e.rotation = {30.0f, 0.0f, 0.0f};
        const auto yawed = static_solid_shape(e);
        e.rotation = {30.0f, 20.0f, 10.0f};
        const auto tilted = static_solid_shape(e);
        // The game's body: the static solid where there is one (doors, robots and the rest stand upright),
        // a brush's world brush (its vertex centre moves when the pitch and roll turn it).
        bool body_turns = tilted && std::abs(glm::dot(tilted->rotation(), yawed->rotation())) < 0.9999f;
        if (type == EntityType::Brush) {
            const auto tilted_brush = world_brush(e);
            e.rotation = {30.0f, 0.0f, 0.0f};
            const auto yawed_brush = world_brush(e);
            REQUIRE((tilted_brush.ok() && yawed_brush.ok()));
            body_turns = glm::length(tilted_brush->vertex_centre() - yawed_brush->vertex_centre()) > 1e-3;
        }
        if (type == EntityType::Model) { // its collision brush (level/model_entity.h), the default box here
            e.as<ModelProps>().collision.value = "box";
            e.rotation = {30.0f, 20.0f, 10.0f};
            const auto tilted_model = model_collision(e);
            e.rotation = {30.0f, 0.0f, 0.0f};
            const auto yawed_model = model_collision(e);
            REQUIRE((tilted_model.ok() && yawed_model.ok() && tilted_model->size() == 1 &&
                     yawed_model->size() == 1));
            body_turns = glm::length(tilted_model->front().vertex_centre() -
                                     yawed_model->front().vertex_centre()) > 1e-3;
        }
        CAPTURE(type_name(type));
        CHECK(keeps_pitch_and_roll(type) == body_turns);
    }
}
