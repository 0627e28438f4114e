// The malformed-file corpus (tests/data/levels/bad/): each file must give one clear report naming file,
// place and fix -- never a crash, never a silent success. Table: file -> expected error count and text.
#include "core/log.h"
#include "jsonio/bad_documents.h"
#include "level/level_io.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <set>

using namespace ks::level;

namespace {

struct BadFile {
    const char* file;
    int errors;   // exact number of errors expected (warnings are listed in `expected` when they matter)
    int warnings; // exact number of warnings
    std::vector<std::string> expected; // substrings of the report, usually "line:column: path: words"
};

const std::vector<BadFile>& corpus() {
    static const std::vector<BadFile> table = {
        {"empty.json", 1, 0, {"empty.json:1:1: file is empty", "killswitch-level"}},
        {"whitespace_only.json", 1, 0, {"file is empty"}},
        {"truncated.json",
         1,
         0,
         {"truncated.json:7:90: file ends early (truncated?)", "unexpected end of input"}},
        {"binary_garbage.json",
         1,
         0,
         {"binary_garbage.json:1:1: file is not a text file (byte 0x89 at offset 0)"}},
        {"invalid_utf8.json", 1, 0, {"invalid_utf8.json:4:15: file is not a text file (byte 0xff"}},
        {"syntax_error.json", 1, 0, {"syntax_error.json:5:39: JSON syntax error", "expected '}'"}},
        {"trailing_comma.json", 1, 0, {"trailing_comma.json:6:3: JSON syntax error", "unexpected ']'"}},
        {"not_an_object.json",
         1,
         0,
         {"not_an_object.json:1:1: expected the level as a JSON object", "found an array"}},
        {"deep_nesting.json", 1, 0, {"deep_nesting.json:1:121: nested deeper than 64 levels"}},
        {"wrong_format.json", 1, 0, {":2:3: format: not a Killswitch level", "\"unity-scene\""}},
        {"missing_format.json", 1, 0, {"format: missing required field \"format\""}},
        {"missing_version.json", 1, 0, {"version: missing required field \"version\""}},
        {"version_not_a_number.json", 1, 0, {":3:3: version: version must be a whole number"}},
        {"newer_version.json",
         1,
         0,
         {":3:3: version: this level was made by a newer Killswitch (format version 7", "update Killswitch"}},
        {"missing_entities.json", 1, 0, {"entities: missing required field \"entities\""}},
        {"missing_required_fields.json",
         3,
         0,
         {":6:5: entities[0].id: missing required field \"id\"",
          ":7:5: entities[1].type: missing required field \"type\"", "valid types: wall, floor, stair",
          ":8:5: entities[2].position: missing required field \"position\""}},
        {"unknown_type.json",
         2,
         0,
         {":7:15: entities[1].type: unknown entity type \"gas_cylindre\"", "did you mean \"gas_cylinder\"?",
          ":8:15: entities[2].type: unknown entity type \"barrel\"", "control_panel"}},
        {"wrong_types.json",
         7,
         0,
         {":9:7: entities[0].position: expected an array of 3 numbers [x, y, z], found an array of 2",
          ":10:17: entities[0].props.size: expected an array of 3 numbers",
          ":10:34: entities[0].props.texture: expected a string, found the number 7",
          ":16:17: entities[1].props.ceiling: expected true or false, found the string \"yes\"",
          ":22:17: entities[2].props.steps: 2.5 is not a whole number",
          ":27:7: entities[3].name: expected a string",
          ":29:7: entities[3].props: expected props as an object"}},
        {"nan_and_inf_strings.json",
         3,
         0,
         {":11:9: entities[0].props.health: \"NaN\" is not a finite number",
          ":12:9: entities[0].props.velocity: \"-Infinity\" is not a finite number",
          ":18:20: entities[1].position[0]: \"nan\" is not a finite number", "valid: 1 .. 100000"}},
        {"number_in_quotes.json",
         1,
         0,
         {":10:17: entities[0].props.health: number written as a string \"100\"", "remove the quotes"}},
        {"overflow_1e999.json",
         2,
         0,
         {":11:18: entities[0].props.size[0]: number 1e999 overflows to infinity",
          ":17:23: entities[1].position[1]: number -2e400 overflows"}},
        {"huge_sizes_1e308.json",
         2,
         0,
         {":11:18: entities[0].props.size[0]: 1e+308 is too large (beyond a 32-bit float)",
          ":19:18: entities[1].props.size[0]: 1e+30 is out of range", "valid: 0.01 .. 10000 units"}},
        {"negative_size.json",
         2,
         0,
         {":11:18: entities[0].props.size[0]: -5 is out of range",
          ":19:9: entities[1].props.radius: 0 is out of range (valid: 0.05 .. 10 units"}},
        {"absurd_position.json",
         2,
         0,
         {":9:20: entities[0].position[0]: 10000000 is out of range",
          ":10:23: entities[0].rotation[1]: 100000 is out of range (valid: -3600 .. 3600 deg"}},
        {"duplicate_ids.json",
         1,
         0,
         {":8:6: entities[2].id: duplicate id 3 (also used by entities[1] \"Wall\")", "unused id such as 4"}},
        {"negative_id.json",
         2,
         0,
         {":6:6: entities[0].id: id -4 is not positive", ":7:6: entities[1].id: 1.5 is not a whole number"}},
        {"next_id_too_small.json",
         1,
         0,
         {":5:3: next_id: next_id 2 is not above the largest id 5", "set next_id to 6"}},
        {"out_of_range.json",
         3,
         0,
         {":6:5: settings.gravity: 10 is out of range (valid: -1000 .. 0 units/s^2",
          ":14:9: entities[0].props.hit_probability: 1.5 is out of range (valid: 0 .. 1",
          ":22:9: entities[1].props.steps: 0 is out of range (valid: 1 .. 200"}},
        {"bad_colour.json",
         3,
         0,
         {":6:5: settings.fog_color: bad colour \"red\"", "\"#rrggbb\"",
          ":14:9: entities[0].props.color: bad colour \"#ggcc80\"",
          ":22:9: entities[1].props.color: expected a colour string, found the number 16777215"}},
        {"bad_pickup_kind.json",
         1,
         0,
         {":11:9: entities[0].props.kind: unknown kind \"armor\" (valid: health, ammo, shield)"}},
        {"duplicate_key.json", 1, 0, {":10:7: entities[0].position: duplicate key (also at line 9:7)"}},
        {"robot_eye_radii.json",
         1,
         0,
         {":11:9: entities[0].props.eye_radius_min: eye_radius_min 30 is larger than eye_radius_max 25"}},
        // A patrol read whole or not at all: the bad point drops the route, so the far point is not reached.
        {"robot_patrol.json",
         3,
         0,
         {":14:56: entities[1].props.patrol.points[3][0]: robot 12 (\"guard\"): \"nan\" is not a finite "
          "number",
          ":15:11: entities[1].props.patrol.mode: robot 12 (\"guard\"): unknown patrol mode \"pingpong\" "
          "(did you mean \"ping_pong\"? valid: loop, ping_pong)",
          ":16:11: entities[1].props.patrol.wait: robot 12 (\"guard\"): patrol wait -1 is out of range "
          "(valid: 0 .. 600 s"}},
        {"zero_sun_direction.json", 1, 0, {":6:5: settings.sun_direction: sun_direction is zero"}},
        {"entity_not_object.json",
         2,
         0,
         {":7:5: entities[1]: expected an entity as an object {...}, found the number 5",
          ":8:5: entities[2]: expected an entity as an object {...}, found the string \"wall\""}},
        {"entities_not_array.json",
         1,
         0,
         {":4:3: entities: expected \"entities\" to be an array [...], found an object"}},
        {"settings_not_object.json",
         2,
         0,
         {":4:3: settings: expected settings as an object {...}, found an array",
          ":5:43: player_start.yaw: expected a number, found the string \"north\""}},
        // Unknown fields are warnings: the level still loads.
        {"unknown_fields.json",
         0,
         3,
         {"warning: ", ":5:3: author: unknown field \"author\" is ignored",
          ":11:7: entities[0].colour: unknown field \"colour\"",
          ":13:9: entities[0].props.colour: unknown field \"colour\" is ignored (did you mean \"color\"?"}},
    };
    return table;
}

std::filesystem::path bad_dir() {
    return ks::test::data_dir() / "levels" / "bad";
}

} // namespace

TEST_CASE("every file in the bad-level corpus gives the expected report") {
    for (const BadFile& entry : corpus()) {
        CAPTURE(entry.file);
        LoadReport report;
        auto level = load_level_file(bad_dir() / entry.file, &report);
        const std::string text = report.str();
        CAPTURE(text);
        CHECK(level.ok() == (entry.errors == 0));
        CHECK(report.error_count() == entry.errors);
        CHECK(report.warning_count() == entry.warnings);
        for (const std::string& expected : entry.expected)
            CHECK_MESSAGE(text.find(expected) != std::string::npos, expected);
        for (const Diagnostic& d : report.diagnostics) {
            // Every diagnostic names the file and says what would be valid.
            CHECK(d.error.where.file.find(entry.file) != std::string::npos);
            CHECK_FALSE(d.error.hint.empty());
        }
        if (!level.ok()) {
            // The combined error lists every error that the report holds.
            const std::string combined = level.error().str();
            for (const Diagnostic& d : report.diagnostics)
                if (d.severity == Diagnostic::Severity::Error)
                    CHECK(combined.find(d.error.message) != std::string::npos);
        }
    }
}

TEST_CASE("the corpus table covers every file in the folder") {
    std::set<std::string> listed;
    for (const BadFile& entry : corpus()) listed.insert(entry.file);
    std::set<std::string> present;
    for (const auto& file : std::filesystem::directory_iterator(bad_dir()))
        present.insert(file.path().filename().string());
    CHECK(listed == present);
}

TEST_CASE("a missing file is one clear error") {
    LoadReport report;
    auto level = load_level_file(bad_dir() / "no_such_level.json", &report);
    REQUIRE_FALSE(level.ok());
    CHECK(level.error().str().find("no_such_level.json") != std::string::npos);
    CHECK(level.error().message == "file not found");
    CHECK(report.error_count() == 1);
}

TEST_CASE("warnings go to the log when no report is asked for") {
    ks::log::Capture capture;
    auto level = load_level_file(bad_dir() / "unknown_fields.json");
    CHECK(level.ok());
    CHECK(capture.count(ks::log::Level::Warn) == 3);
    CHECK(capture.text().find("unknown field \"author\"") != std::string::npos);
}

TEST_CASE("every bad document is refused with its line:column, as in every file kind") {
    for (const ks::test::BadDocument& bad : ks::test::bad_documents()) {
        CAPTURE(bad.name);
        LoadReport report;
        auto level = load_level_string(bad.text, "bad.json", &report);
        REQUIRE_FALSE(level.ok());
        const std::string text = report.str();
        CAPTURE(text);
        CHECK(text.find("bad.json" + bad.place + bad.message) != std::string::npos);
    }
}

TEST_CASE("a 300-character text in \"\u00e9\" is within a 500-character limit; 501 characters are not") {
    std::string text;
    for (int i = 0; i < 300; ++i) text += "\xc3\xa9";
    auto level_with = [](const std::string& message) {
        return "{\"format\": \"killswitch-level\", \"version\": 2, \"entities\": [{\"id\": 1, \"type\": "
               "\"message\", \"position\": [0, 0, 0], \"props\": {\"text\": \"" +
               message + "\"}}]}";
    };
    LoadReport report;
    auto ok = load_level_string(level_with(text), "accents.json", &report);
    CHECK_MESSAGE(ok.ok(), report.str());
    std::string long_text;
    for (int i = 0; i < 501; ++i) long_text += "\xc3\xa9";
    auto too_long = load_level_string(level_with(long_text), "accents.json", &report);
    REQUIRE_FALSE(too_long.ok());
    CHECK(report.str().find("text of 501 characters is too long") != std::string::npos);
}
