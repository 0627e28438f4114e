// Entities (edit_entities.h): multi-selection field edits and revert, duplicate, copy and paste.
#include "editor_test_util.h"
#include "model/edit_entities.h"
#include "model/edit_layers.h"
#include "model/edit_selection.h"
#include "model/edit_transforms.h"

#include <nlohmann/json.hpp>

#include <cmath>

using namespace ks;
using namespace ks::editor;
using level::EntityType;

TEST_CASE("properties: multi-selection edits common fields; revert to default") {
    Editor ed;
    int fl = *place(ed, EntityType::FloorLight, {0, 0, 0});
    int tl = *place(ed, EntityType::TopLight, {0, 16, 0});
    int robot = *place(ed, EntityType::Robot, {0, 0, 0});
    REQUIRE(select(ed, {fl, tl}).ok());
    auto common = common_fields(selected_entities(ed));
    std::vector<std::string> names;
    for (const auto& f : common) names.push_back(f.name);
    CHECK(names ==
          std::vector<std::string>{"name", "position", "rotation", "color", "intensity", "range", "on"});
    REQUIRE(set_field_text(ed, "color", "#ff8000").ok());
    REQUIRE(set_field_text(ed, "on", "false").ok());
    for (int id : {fl, tl}) {
        auto color = get_entity_field(*ed.level().find(id), "color");
        CHECK(format_field_value(*color) == "#ff8000");
        CHECK(std::get<bool>(*get_entity_field(*ed.level().find(id), "on")) == false);
    }
    // A field only some selected entities have: the others are an error, nothing changes.
    REQUIRE(select(ed, {fl, robot}).ok());
    CHECK_FALSE(set_field_text(ed, "cone_angle", "20").ok());
    CHECK(ed.level().find(fl)->as<level::FloorLightProps>().cone_angle == 35.0f);

    REQUIRE(select(ed, {fl, tl}).ok());
    REQUIRE(revert_field(ed, "color").ok());
    REQUIRE(revert_field(ed, "on").ok());
    CHECK(ed.level().find(fl)->as<level::FloorLightProps>() == level::FloorLightProps{});
    CHECK(ed.level().find(tl)->as<level::TopLightProps>() == level::TopLightProps{});

    // Choices only take their options.
    int pickup = *place(ed, EntityType::Pickup, {0, 0, 0});
    (void)pickup;
    auto bad = set_field_text(ed, "kind", "armor");
    REQUIRE_FALSE(bad.ok());
    CHECK(bad.error().hint.find("health, ammo, shield") != std::string::npos);
    REQUIRE(set_field_text(ed, "kind", "shield").ok());
}

TEST_CASE("duplicate gives new ids after next_id, offset by one grid step along x, and selects the copies") {
    Editor ed;
    ed.grid().step = 2.0f;
    int a = *place(ed, EntityType::Robot, {0, 0, 0}, 0, "R1");
    int b = *place(ed, EntityType::Pickup, {4, 0, 0});
    REQUIRE(select(ed, {b, a}).ok());
    REQUIRE(duplicate(ed).ok());
    REQUIRE(ed.level().entities.size() == 4);
    const auto& copy_a = ed.level().entities[2];
    const auto& copy_b = ed.level().entities[3];
    CHECK(copy_a.id == 3); // level order, not selection order
    CHECK(copy_b.id == 4);
    CHECK(copy_a.name == "R1");
    CHECK(copy_a.position == Vec3(2, 0, 0)); // one step along x only: y and z are kept
    CHECK(copy_b.position == Vec3(6, 0, 0));
    CHECK(ed.level().next_id == 5);
    CHECK(ed.doc().selection == std::vector<int>{3, 4});
    CHECK(ed.history().undo_name() == "Duplicate 2 entities");
}

TEST_CASE("copy/paste: JSON text with fresh ids, between levels, and bad clipboards reported") {
    Editor source;
    int r = *place(source, EntityType::Robot, {3, 0, 4}, 90, "Guard");
    REQUIRE(set_field(source, "health", FieldValue(300.0)).ok());
    int g = *place(source, EntityType::GasCylinder, {6, 0, 4});
    REQUIRE(select(source, {r, g}).ok());
    const std::string text = copy(source);
    CHECK(text.find("killswitch-clipboard") != std::string::npos);

    Editor target; // another level
    for (int i = 0; i < 5; ++i) (void)place(target, EntityType::Pickup, {float(i), 0, 0});
    REQUIRE(paste_text(target, text).ok());
    REQUIRE(target.level().entities.size() == 7);
    const auto& pasted = target.level().entities[5];
    CHECK(pasted.id == 6);
    CHECK(pasted.name == "Guard");
    CHECK(pasted.position == Vec3(3, 0, 4));
    CHECK(pasted.rotation.x == 90.0f);
    CHECK(pasted.as<level::RobotProps>().health == 300.0f);
    CHECK(target.level().entities[6].id == 7);
    CHECK(target.doc().selection == std::vector<int>{6, 7});
    REQUIRE(target.undo());
    CHECK(target.level().entities.size() == 5);
    CHECK(target.level().next_id == 6);

    // Pasting in the same level twice gives distinct ids each time.
    REQUIRE(paste(source).ok());
    REQUIRE(paste(source).ok());
    CHECK(source.level().entities.size() == 6);
    CHECK(source.level().next_id == 7);

    // A single entity's JSON also pastes.
    REQUIRE(
        paste_text(target, nlohmann::json(level::entity_to_json(source.level().entities[0])).dump()).ok());

    const size_t steps = target.history().undo_count();
    auto not_json = paste_text(target, "hello");
    REQUIRE_FALSE(not_json.ok());
    CHECK(not_json.error().hint.find("Ctrl+C") != std::string::npos);
    CHECK_FALSE(paste_text(target, "[]").ok());
    auto bad_entity = paste_text(
        target, R"({"killswitch-clipboard":1,"entities":[{"type":"robot","position":[0,0,"x"]}]})");
    REQUIRE_FALSE(bad_entity.ok());
    CHECK(bad_entity.error().str().find("clipboard") != std::string::npos);
    CHECK(target.history().undo_count() == steps);
}
