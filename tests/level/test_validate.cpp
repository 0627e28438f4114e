// validate(): the semantic checks on in-memory levels that the editor runs live.
#include "level/level_io.h"
#include "level_builders.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>

using namespace ks::level;

namespace {
bool mentions(const LoadReport& report, const std::string& text) {
    return report.str().find(text) != std::string::npos;
}
} // namespace

TEST_CASE("validate accepts the shipped levels and a fresh level") {
    for (const char* name : {"main.json", "dojo.json"}) {
        auto level = load_level_file(ks::test::source_dir() / "levels" / name);
        REQUIRE(level.ok());
        CHECK(validate(*level, name).diagnostics.empty());
    }
    Level fresh;
    for (EntityType type : all_types()) fresh.add(type);
    CHECK(validate(fresh).diagnostics.empty());
}

TEST_CASE("validate finds NaN, infinity and out-of-range values in memory") {
    Level level = ks::test::level_with_every_type();
    level.entities[6].as<RobotProps>().health = std::numeric_limits<float>::quiet_NaN();
    level.entities[0].position.y = std::numeric_limits<float>::infinity();
    level.entities[1].as<FloorProps>().size.x = 1e30f;
    level.entities[2].as<StairProps>().steps = 0;
    level.entities[4].as<FloorLightProps>().light.color.g = 1.5f;
    level.entities[7].as<PickupProps>().kind.value = "armor";
    level.entities[0].as<WallProps>().texture.clear();
    level.settings.fog_density = -1;
    level.player_start.yaw = std::numeric_limits<float>::quiet_NaN();
    const LoadReport report = validate(level, "draft.json");
    CAPTURE(report.str());
    CHECK(report.error_count() == 9);
    CHECK(mentions(report, "draft.json: entities[6].props.health: value is NaN (not a finite number)"));
    CHECK(mentions(report, "entities[0].position[1]: value is inf (not a finite number)"));
    CHECK(mentions(report, "entities[1].props.size[0]: 1e+30 is out of range"));
    CHECK(mentions(report, "entities[2].props.steps: 0 is out of range (valid: 1 .. 200"));
    CHECK(mentions(report, "entities[4].props.color: green 1.5 is out of range (valid: 0 .. 1"));
    CHECK(mentions(report, "entities[7].props.kind: unknown kind \"armor\" (valid: health, ammo, shield)"));
    CHECK(mentions(report, "entities[0].props.texture: texture name is empty"));
    CHECK(mentions(report, "settings.fog_density: -1 is out of range"));
    CHECK(mentions(report, "player_start.yaw: value is NaN"));
    for (const Diagnostic& d : report.diagnostics) CHECK(d.error.where.line == 0); // no text, no positions
}

TEST_CASE("validate checks ids, next_id and the robot's eye radii") {
    Level level;
    level.add(EntityType::Wall, {}, "First");
    level.add(EntityType::Wall, {}, "Second");
    level.add(EntityType::Robot, {}, "Robot").as<RobotProps>().eye_radius_min = 40;
    level.entities[1].id = 1;
    level.entities[2].id = -3;
    level.next_id = 1;
    const LoadReport report = validate(level);
    CAPTURE(report.str());
    CHECK(report.error_count() == 4);
    CHECK(mentions(report, "entities[1].id: duplicate id 1 (also used by entities[0] \"First\")"));
    CHECK(mentions(report, "entities[2].id: id -3 is not positive"));
    CHECK(mentions(report, "next_id: next_id 1 is not above the largest id 1"));
    CHECK(mentions(report, "eye_radius_min 40 is larger than eye_radius_max 25"));
}

TEST_CASE("validate: the ends of each range are valid, just beyond is not") {
    Level level;
    level.add(EntityType::Wall);
    level.add(EntityType::Robot);
    auto& wall = level.entities[0].as<WallProps>();
    wall.size = {0.01f, 1e4f, 0.01f}; // 0.01 is not exact in float; the documented minimum must still pass
    auto& robot = level.entities[1].as<RobotProps>();
    robot.hit_probability = 1.0f;
    robot.health = 1.0f;
    CHECK(validate(level).diagnostics.empty());
    wall.size.x = std::nextafter(0.01f, 0.0f);
    robot.hit_probability = std::nextafter(1.0f, 2.0f);
    CHECK_MESSAGE(validate(level).error_count() == 2, validate(level).str());
}

TEST_CASE("loading reports semantic errors at their line and column") {
    const std::string text = "{\n"
                             "  \"format\": \"killswitch-level\",\n"
                             "  \"version\": 2,\n"
                             "  \"entities\": [\n"
                             "    {\"id\": 1, \"type\": \"robot\", \"position\": [0, 0, 0],\n"
                             "     \"props\": {\"hit_probability\": 2}}\n"
                             "  ]\n"
                             "}\n";
    LoadReport report;
    REQUIRE_FALSE(load_level_string(text, "probe.json", &report).ok());
    REQUIRE(report.diagnostics.size() == 1);
    const ks::Location& where = report.diagnostics[0].error.where;
    CHECK(where.file == "probe.json");
    CHECK(where.line == 6);
    CHECK(where.column == 16);
    CHECK(where.path == "entities[0].props.hit_probability");
}

TEST_CASE("many errors are all reported, in document order") {
    std::string text = "{\"format\": \"killswitch-level\", \"version\": 2, \"entities\": [\n";
    for (int i = 0; i < 120; ++i) {
        if (i) text += ",\n";
        text += "{\"id\": " + std::to_string(i + 1) +
                ", \"type\": \"door\", \"position\": [0, 0, 0], \"props\": {\"width\": -" +
                std::to_string(i) + "}}";
    }
    text += "\n]}";
    LoadReport report;
    auto level = load_level_string(text, "many.json", &report);
    REQUIRE_FALSE(level.ok());
    CHECK(report.error_count() == 120);
    for (size_t i = 1; i < report.diagnostics.size(); ++i)
        CHECK(report.diagnostics[i - 1].error.where.line < report.diagnostics[i].error.where.line);
    // The combined error stays readable: the first errors, then a count of the rest.
    CHECK(level.error().message.find("... and 70 more errors") != std::string::npos);
}

TEST_CASE("Windows line endings and a byte-order mark load, with the right positions") {
    const std::string text = "\xEF\xBB\xBF{\r\n"
                             "  \"format\": \"killswitch-level\",\r\n"
                             "  \"version\": 2,\r\n"
                             "  \"entities\": [{\"id\": 1, \"type\": \"wall\", \"position\": [0, 0, 0], "
                             "\"props\": {\"size\": [0, 1, 1]}}]\r\n"
                             "}\r\n";
    LoadReport report;
    REQUIRE_FALSE(load_level_string(text, "crlf.json", &report).ok());
    REQUIRE(report.diagnostics.size() == 1);
    CHECK(report.diagnostics[0].error.where.line == 4);
    CHECK(report.diagnostics[0].error.where.column == 84);
    CHECK(report.diagnostics[0].error.where.path == "entities[0].props.size[0]");
}
