// Older versions are migrated; entities travel as JSON for copy/paste with the loader's checks.
#include "level/level_io.h"
#include "level/level_migrate.h"
#include "level_builders.h"
#include "test_support.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cmath>

using namespace ks::level;

TEST_CASE("the migration table has one step per older version, in order") {
    REQUIRE(migrations().size() == static_cast<size_t>(kFormatVersion));
    for (size_t i = 0; i < migrations().size(); ++i) {
        CHECK(migrations()[i].from_version == static_cast<int>(i));
        CHECK(static_cast<bool>(migrations()[i].apply));
        CHECK(std::string(migrations()[i].summary).size() > 10);
    }
}

TEST_CASE("a version 0 file loads through both migrations and saves as the current version") {
    LoadReport report;
    auto level =
        load_level_file(ks::test::data_dir() / "levels" / "good" / "version0_migration.json", &report);
    REQUIRE_MESSAGE(level.ok(), report.str());
    CHECK(report.error_count() == 0);
    REQUIRE(report.warning_count() == 2);
    CHECK(report.str().find("version 0 -> 1") != std::string::npos);
    CHECK(report.str().find("version 1 -> 2") != std::string::npos);
    REQUIRE(level->entities.size() == 2);
    CHECK(level->entities[0].rotation == ks::Vec3(90, 0, 0));
    CHECK(level->entities[1].rotation == ks::Vec3(-90, 0, 0));
    CHECK(level->entities[1].as<RobotProps>().health == 50.0f);
    const std::string saved = save_level_string(*level);
    CHECK(saved.find("\"version\": 4,") != std::string::npos);
    CHECK(saved.find("\"objects\"") == std::string::npos);
    LoadReport again;
    REQUIRE(load_level_string(saved, "upgraded.json", &again).ok());
    CHECK(again.diagnostics.empty());
}

TEST_CASE("a version 2 file loads unchanged and without a warning, and saves as the current version") {
    const auto path = ks::test::data_dir() / "levels" / "good" / "version2_migration.json";
    LoadReport report;
    auto level = load_level_file(path, &report);
    REQUIRE_MESSAGE(level.ok(), report.str());
    CHECK_MESSAGE(report.diagnostics.empty(), report.str());
    REQUIRE(level->entities.size() == 2);
    CHECK(level->entities[1].type() == EntityType::Wall);
    nlohmann::ordered_json doc = nlohmann::ordered_json::parse(ks::test::read_file(path));
    const nlohmann::ordered_json before = doc;
    CHECK(migrate(doc, 2).empty());
    CHECK(doc == before); // the step leaves the document as it was
    const std::string saved = save_level_string(*level);
    CHECK(saved.find("\"version\": 4,") != std::string::npos);
    LoadReport again;
    auto reloaded = load_level_string(saved, "v3.json", &again);
    REQUIRE(reloaded.ok());
    CHECK(again.diagnostics.empty());
    CHECK(*reloaded == *level);
}

TEST_CASE("migration 0 -> 1 renames in place and leaves unrelated keys alone") {
    nlohmann::ordered_json doc = nlohmann::ordered_json::parse(
        R"({"format": "killswitch-level", "version": 0, "objects": [{"id": 1, "yaw": 30, "x": 1}, 5], "tail": true})");
    migrations()[0].apply(doc);
    CHECK(
        doc.dump() ==
        R"({"format":"killswitch-level","version":0,"entities":[{"id":1,"x":1,"rotation":[30,0,0]},5],"tail":true})");
    CHECK(migrate(doc, 0).size() == 2); // 0 -> 1 -> 2; 2 -> 3 changes nothing and is not reported
    nlohmann::ordered_json current = nlohmann::ordered_json::parse(R"({"version": 2})");
    CHECK(migrate(current, kFormatVersion).empty());
}

TEST_CASE("entity_to_json and entity_from_json round-trip every type") {
    const Level level = ks::test::level_with_every_type();
    for (const Entity& entity : level.entities) {
        CAPTURE(type_name(entity.type()));
        const nlohmann::json json = entity_to_json(entity);
        CHECK(json["type"] == std::string(type_name(entity.type())));
        auto back = entity_from_json(json, "clipboard");
        REQUIRE_MESSAGE(back.ok(), back.error().str());
        CHECK(*back == entity);
    }
}

TEST_CASE("entity_from_json applies the loader's checks and names the context") {
    nlohmann::json json = entity_to_json(ks::test::level_with_every_type().entities[6]); // the robot
    json["props"]["health"] = std::nan(""); // nlohmann can hold a NaN even though JSON text cannot
    json["props"]["velocity"] = -5;         // out of range
    json["props"]["colour"] = "#ffffff";    // unknown field: a warning
    LoadReport report;
    auto entity = entity_from_json(json, "clipboard", &report);
    REQUIRE_FALSE(entity.ok());
    CHECK(report.error_count() == 2);
    CHECK(report.warning_count() == 1);
    const std::string text = report.str();
    CHECK(text.find("clipboard: props.health: number is not finite") != std::string::npos);
    CHECK(text.find("clipboard: props.velocity: -5 is out of range") != std::string::npos);
    CHECK(entity.error().str().find("clipboard") != std::string::npos);

    auto not_object = entity_from_json(nlohmann::json::array({1, 2}), "paste");
    REQUIRE_FALSE(not_object.ok());
    CHECK(not_object.error().str().find("expected an entity as an object") != std::string::npos);
    nlohmann::json unknown = {{"id", 3}, {"type", "turret"}, {"position", {0, 0, 0}}};
    auto unknown_type = entity_from_json(unknown, "paste");
    REQUIRE_FALSE(unknown_type.ok());
    CHECK(unknown_type.error().str().find("unknown entity type \"turret\"") != std::string::npos);
    // Strings that are not UTF-8 (possible in memory) give a message, not an exception.
    nlohmann::json bad_utf8 = {{"id", 3}, {"type", std::string("wa\xffll")}, {"position", {0, 0, 0}}};
    CHECK_FALSE(entity_from_json(bad_utf8, "paste").ok());
}

TEST_CASE("version: 1.0 is version 1, 1.5 and huge numbers are not versions") {
    auto with_version = [](const std::string& v) {
        return "{\"format\": \"killswitch-level\", \"version\": " + v + ", \"entities\": []}";
    };
    CHECK(load_level_string(with_version("1.0"), "v.json").ok());
    LoadReport report;
    CHECK_FALSE(load_level_string(with_version("1.5"), "v.json", &report).ok());
    CHECK(report.str().find("version must be a whole number, found 1.5") != std::string::npos);
    CHECK_FALSE(load_level_string(with_version("18446744073709551615"), "v.json", &report).ok());
    CHECK(report.str().find("newer Killswitch") != std::string::npos);
    CHECK_FALSE(load_level_string(with_version("-1"), "v.json", &report).ok());
    CHECK(report.str().find("not a valid format version") != std::string::npos);
}
