// Finding a JSON path's value in the text the way the parser reads the document (what clip errors point at).
#include "jsonio/position_map.h"

#include <doctest/doctest.h>

#include <string>

using namespace ks::jsonio;

TEST_CASE("JSON paths locate their values in the text") {
    const std::string text = "{\n  \"a\": [1, {\"b\": \"x\"}],\n  \"a\": {\"c\": [true, null]}\n}";
    CHECK(locate(text, JsonPath{}).line == 1);
    auto pos = locate(text, JsonPath{} / "a" / "c");
    CHECK(pos.line == 3); // duplicate keys: the last one, as the parser keeps it
    CHECK(pos.column == 14);
    CHECK(locate(text, (JsonPath{} / "a" / "c")[1]).column == 21);
    CHECK(locate(text, JsonPath{} / "zzz").line == 0);
    CHECK(locate(text, (JsonPath{} / "a")[0]).line == 0); // "a" is an object now
    CHECK(((JsonPath{} / "clips")[2] / "phases").str() == "clips[2].phases");
}

TEST_CASE("find_value gives values, find gives keys and falls back to ancestors") {
    const std::string text = "{\"outer\": {\"list\": [[1, 2], {\"k\": \"v\"}]}}";
    const PositionMap map = PositionMap::scan(text);
    CHECK(map.find_value("outer").column == 11);
    CHECK(map.find("outer").column == 2);
    CHECK(map.find_value("outer.list[0][1]").column == 25);
    CHECK(map.find_value("outer.list[1].k").column == 35);
    CHECK(map.find("outer.list[1].k").column == 30);
    CHECK(map.find_value("outer.list[2]").line == 0);
    CHECK(map.find_value("outer.missing").line == 0);
    CHECK(map.find("outer.missing").column == 2);
}

TEST_CASE("positions count UTF-8 characters and treat CRLF line ends like LF") {
    const std::string text =
        "{\r\n  \"na\xc3\xafve\": \"\xe2\x82\xac\xf0\x9f\x98\x80\",\r\n  \"next\": [true]\r\n}";
    const PositionMap map = PositionMap::scan(text);
    CHECK(map.find("na\xc3\xafve").line == 2);
    CHECK(map.find("na\xc3\xafve").column == 3);
    CHECK(map.find_value("na\xc3\xafve").column == 12);
    // "\r" is a character like any other, but never starts a line.
    CHECK(map.find("next").line == 3);
    CHECK(map.find("next").column == 3);
    CHECK(map.find_value("next[0]").column == 12);
    CHECK(position_of_offset(text, text.size()).line == 4);
    CHECK(position_of_offset(text, text.size()).column == 2);
}

TEST_CASE("location_at carries the position and path into an Error's Location") {
    const ks::Location where = location_at("a.json", {3, 7}, "clips[0].name");
    CHECK(where.str() == "a.json:3:7: clips[0].name");
    CHECK(location_at("a.json", {}).str() == "a.json");
}
