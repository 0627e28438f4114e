// The position map that lets problems found after parsing point at line:column.
#include "jsonio/position_map.h"

#include <doctest/doctest.h>

using namespace ks::jsonio;

TEST_CASE("position_of_offset counts lines and characters, not bytes") {
    const std::string text = "ab\ncd\n\xc3\xa9x"; // "é" is two bytes, one column
    CHECK(position_of_offset(text, 0).line == 1);
    CHECK(position_of_offset(text, 0).column == 1);
    CHECK(position_of_offset(text, 4).line == 2);
    CHECK(position_of_offset(text, 4).column == 2);
    const TextPosition after_accent = position_of_offset(text, 8);
    CHECK(after_accent.line == 3);
    CHECK(after_accent.column == 2);
    CHECK(position_of_offset(text, 1000).line == 3); // clamped
}

TEST_CASE("scan maps members to their keys and elements to their values") {
    const std::string text =
        "{\n  \"a\": 1,\n  \"list\": [10, {\"deep\": [1, 2]}],\n  \"s\": \"x,]}\\\"y\"\n}";
    const PositionMap map = PositionMap::scan(text);
    auto at = [&](const char* path) {
        const TextPosition p = map.find(path);
        return std::to_string(p.line) + ":" + std::to_string(p.column);
    };
    CHECK(at("") == "1:1");
    CHECK(at("a") == "2:3");
    CHECK(at("list") == "3:3");
    CHECK(at("list[0]") == "3:12");
    CHECK(at("list[1]") == "3:16");
    CHECK(at("list[1].deep") == "3:17");
    CHECK(at("list[1].deep[1]") == "3:29");
    CHECK(at("s") == "4:3"); // a string holding , ] } and \" does not confuse the scan
    // Missing paths fall back to their nearest known ancestor.
    CHECK(at("list[1].deep[7]") == "3:17");
    CHECK(at("list[1].missing") == "3:16");
    CHECK(at("nothing.here") == "1:1");
    CHECK(map.duplicate_keys().empty());
    CHECK(map.overflowing_numbers().empty());
}

TEST_CASE("scan finds duplicate keys and numbers that overflow a double") {
    const PositionMap map = PositionMap::scan("{\"a\": 1, \"b\": [1e999, -2E+400, 1e308], \"a\": 2}");
    REQUIRE(map.duplicate_keys().size() == 1);
    CHECK(map.duplicate_keys()[0].path == "a");
    CHECK(map.duplicate_keys()[0].first.column == 2);
    CHECK(map.duplicate_keys()[0].second.column == 40);
    REQUIRE(map.overflowing_numbers().size() == 2);
    CHECK(map.overflowing_numbers()[0].path == "b[0]");
    CHECK(map.overflowing_numbers()[0].token == "1e999");
    CHECK(map.overflowing_numbers()[1].token == "-2E+400");

    // Without an exponent only 309 digits or more overflow; the index path is "[n]" for any n.
    const std::string digits308 = "1" + std::string(307, '0'), digits320 = "9" + std::string(319, '0');
    std::string many = "[";
    for (int i = 0; i < 12; ++i) many += "0.5, ";
    many += digits308 + ", " + digits320 + ", -" + digits320 + "]";
    const PositionMap wide = PositionMap::scan(many);
    REQUIRE(wide.overflowing_numbers().size() == 2);
    CHECK(wide.overflowing_numbers()[0].path == "[13]");
    CHECK(wide.overflowing_numbers()[1].path == "[14]");
    CHECK(wide.overflowing_numbers()[1].token == "-" + digits320);
}

TEST_CASE("the lookup index is built from the map's own copy of the text, once, after a move") {
    PositionMap moved;
    {
        std::string text = "{\"a\": {\"b\": [1, 2]}, \"a\": 3}";
        PositionMap map = PositionMap::scan(text);
        text.assign(text.size(), 'x'); // the caller's buffer is gone before the first lookup
        moved = std::move(map);
    }
    CHECK(moved.duplicate_keys().size() == 1); // found by the first pass, not again by the index's
    CHECK(moved.find("a.b[1]").column == 17);
    CHECK(moved.find_value("a").column == 27); // the last occurrence, which the parser keeps
    CHECK(moved.find("a.b[1]").column == 17);  // a second lookup reuses the index
    CHECK(moved.duplicate_keys().size() == 1);
}

TEST_CASE("scan survives broken and hostile text") {
    const char* const broken[] = {"",
                                  "{",
                                  "[",
                                  "}",
                                  "]]]",
                                  "{\"a\"",
                                  "{\"a\": [1, 2",
                                  "[}",
                                  "{]",
                                  "\"unterminated",
                                  "{\"a\" 1 2 3}",
                                  "[,,,]",
                                  "{\"\\",
                                  "{{{{",
                                  "nul"};
    for (const char* text : broken) {
        CAPTURE(text);
        const PositionMap map = PositionMap::scan(text);
        CHECK(map.find("").line >= 0);
    }
    // Nesting far deeper than any level: no stack overflow.
    const std::string deep = std::string(200000, '[') + std::string(200000, ']');
    CHECK(PositionMap::scan(deep).find("").line == 1);
}

TEST_CASE("paths read the way designers write them") {
    CHECK(member_path("", "entities") == "entities");
    CHECK(element_path("entities", 12) == "entities[12]");
    CHECK(member_path(element_path("entities", 12), "props") == "entities[12].props");
}
