// Saving is deterministic and exact: load -> save -> load -> save is byte-identical, floats print in their
// shortest round-trip form, and the text layout is the documented one.
#include "core/files.h"
#include "jsonio/number_text.h"
#include "level/level_io.h"
#include "level_builders.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <cstring>

using namespace ks::level;

namespace {

Level load_ok(const std::string& text, const char* name = "test.json") {
    LoadReport report;
    auto level = load_level_string(text, name, &report);
    REQUIRE_MESSAGE(level.ok(), report.str());
    CHECK_MESSAGE(report.diagnostics.empty(), report.str());
    return std::move(level).value();
}

} // namespace

TEST_CASE("floats print in their shortest round-trip form") {
    using ks::jsonio::float_to_double;
    using ks::jsonio::format_number;
    CHECK(format_number(float_to_double(0.8f)) == "0.8");
    CHECK(format_number(float_to_double(0.1f)) == "0.1");
    CHECK(format_number(float_to_double(13.264f)) == "13.264");
    CHECK(format_number(float_to_double(-78.6863f)) == "-78.6863");
    CHECK(format_number(float_to_double(100.0f)) == "100");
    CHECK(format_number(float_to_double(-0.0f)) == "0");
    CHECK(format_number(float_to_double(1e-7f)) == "1e-07");
    CHECK(format_number(std::nan("")) == "null");
    CHECK(format_number(INFINITY) == "null");
    // Exact for every float shape: the printed text reads back to the same float.
    for (float f :
         {FLT_MAX, -FLT_MAX, FLT_MIN, FLT_TRUE_MIN, 0.3f, 1.0f / 3.0f, 16777217.0f, 2.5e-38f, 123456.79f}) {
        const std::string text = format_number(float_to_double(f));
        CHECK_MESSAGE(static_cast<float>(std::strtod(text.c_str(), nullptr)) == f, text);
    }
    ks::Rng rng(7);
    for (int i = 0; i < 100000; ++i) {
        std::uint32_t bits = rng.next_u32();
        float f;
        std::memcpy(&f, &bits, sizeof f);
        if (!std::isfinite(f)) continue;
        const std::string text = format_number(float_to_double(f));
        REQUIRE_MESSAGE(static_cast<float>(std::strtod(text.c_str(), nullptr)) == (f == 0 ? 0.0f : f), text);
    }
}

TEST_CASE("the saved text has the documented layout") {
    const std::string text = save_level_string(ks::test::level_with_every_type());
    REQUIRE(!text.empty());
    CHECK(text.back() == '\n');
    CHECK(text.find("\n\n") == std::string::npos);
    CHECK(text.rfind("{\n  \"format\": \"killswitch-level\",\n  \"version\": 4,\n  \"name\": ", 0) == 0);
    // Key order: the format's, not alphabetical.
    const char* const order[] = {"\"format\"",     "\"version\"",      "\"name\"",
                                 "\"settings\"",   "\"player_start\"", "\"next_id\"",
                                 "\"objectives\"", "\"links\"",        "\"entities\""};
    size_t at = 0;
    for (const char* key : order) {
        const size_t found = text.find(key, at);
        CHECK_MESSAGE(found != std::string::npos, key);
        at = found;
    }
    CHECK(text.find("      \"id\": 1,\n      \"type\": \"wall\",\n      \"name\": \"Wall\",\n      "
                    "\"position\": [1, 2, 3],") != std::string::npos);
    CHECK(text.find("\"size\": [7.5, 11, 0.25]") != std::string::npos);
    CHECK(text.find("\"color\": \"#ffcc80\"") != std::string::npos);
    CHECK(text.find("\"intensity\": 0.8,") != std::string::npos);
    CHECK(text.find('\t') == std::string::npos);
}

TEST_CASE("a level with every type and non-default values survives save and load exactly") {
    const Level level = ks::test::level_with_every_type();
    const std::string text = save_level_string(level);
    const Level back = load_ok(text);
    CHECK(back == level);
    CHECK(save_level_string(back) == text);
    CHECK(validate(level).diagnostics.empty());
}

TEST_CASE("a new level with all defaults survives save and load exactly") {
    Level level;
    for (EntityType type : all_types()) level.add(type);
    const Level back = load_ok(save_level_string(level));
    CHECK(back == level);
}

TEST_CASE("random valid levels: save(load(save(L))) == save(L) and load(save(L)) == L") {
    ks::Rng rng(2024);
    for (int round = 0; round < 150; ++round) {
        CAPTURE(round);
        const Level level = ks::test::random_level(rng, static_cast<int>(rng.below(40)));
        REQUIRE_MESSAGE(validate(level).diagnostics.empty(), validate(level).str());
        const std::string text = save_level_string(level);
        const Level back = load_ok(text);
        CHECK(back == level);
        CHECK(save_level_string(back) == text);
    }
}

TEST_CASE("a hand-written file settles after one save") {
    // Keys out of order, numbers as designers type them, fields left to defaults.
    const std::string messy = R"({"entities": [
        {"props": {"light": 1, "intensity": 0.80000001, "color": "#FFCC80"}, "position": [1E1, -0.0, 5.0],
         "type": "floor_light", "id": 7, "rotation": [45.000000001, 0, 0]},
        {"type": "wall", "id": 2, "position": [0, 0, 0], "name": "W\u00e9st \"wall\""}],
      "version": 2, "format": "killswitch-level", "settings": {"sun_direction": [0, -2, 0]}})";
    LoadReport report;
    auto first = load_level_string(messy, "messy.json", &report);
    REQUIRE_MESSAGE(first.ok(), report.str());
    CHECK(report.warning_count() == 1); // "light" is not a field
    const std::string saved = save_level_string(*first);
    CHECK(saved.find("\"intensity\": 0.8,") != std::string::npos);
    CHECK(saved.find("\"position\": [10, 0, 5]") != std::string::npos);
    CHECK(saved.find("\"color\": \"#ffcc80\"") != std::string::npos);
    CHECK(saved.find("\"sun_direction\": [0, -1, 0]") != std::string::npos);
    CHECK(saved.find("\"next_id\": 8") != std::string::npos);
    CHECK(saved.find(R"("name": "Wést \"wall\"")") != std::string::npos);
    const Level second = load_ok(saved);
    CHECK(second == *first);
    CHECK(save_level_string(second) == saved);
}

TEST_CASE("saving never throws over bad in-memory data") {
    Level level;
    Entity& e = level.add(EntityType::Robot, {0, 0, 0}, "Bad \xff\xfe name");
    e.as<RobotProps>().health = NAN;
    e.position.x = INFINITY;
    const std::string text = save_level_string(level); // the editor saves drafts; validation is separate
    CHECK(text.find("\"health\": null") != std::string::npos);
    CHECK(text.find("[null, 0, 0]") != std::string::npos);
    LoadReport report;
    CHECK_FALSE(load_level_string(text, "draft.json", &report).ok());
    CHECK(report.str().find("entities[0].props.health: expected a number, found null") != std::string::npos);
}

TEST_CASE("save_level_file writes atomically and reports failures") {
    ks::test::ScratchDir dir;
    const auto path = dir / "level.json";
    const Level level = ks::test::level_with_every_type();
    REQUIRE(save_level_file(path, level).ok());
    const std::string first = ks::test::read_file(path);
    CHECK(first == save_level_string(level));

    Level changed = level;
    changed.name = "Changed";
    ks::files::inject_fault(ks::files::Fault::ShortWrite);
    auto failed = save_level_file(path, changed);
    ks::files::inject_fault(ks::files::Fault::None);
    CHECK_FALSE(failed.ok());
    CHECK(ks::test::read_file(path) == first); // the old file is intact

    auto loaded = load_level_file(path);
    REQUIRE(loaded.ok());
    CHECK(*loaded == level);
}
