// The level file's editor section (level/editor_data_io.h): layers, groups, prefab links, hidden and locked
// entities round-trip byte for byte; files without it are unchanged; every mistake in it is a warning that
// names its JSON path, never an error that stops the level loading.
#include "level/editor_data_io.h"
#include "level/level_io.h"

#include <doctest/doctest.h>

#include <string>

using namespace ks;
using namespace ks::level;

namespace {
std::string level_text(const std::string& editor_section) {
    std::string text = R"({
  "format": "killswitch-level", "version": 2, "name": "Editor data",
  "player_start": {"position": [0, 0, 0], "yaw": 0}, "next_id": 5,
  "entities": [
    {"id": 1, "type": "floor", "position": [0, 0, 0]},
    {"id": 2, "type": "wall", "position": [0, 0, -10]},
    {"id": 3, "type": "wall", "position": [0, 0, 10]},
    {"id": 4, "type": "door", "position": [0, 0, 10]}
  ])";
    if (!editor_section.empty()) text += ",\n  \"editor\": " + editor_section;
    return text + "\n}";
}

Level load_ok(const std::string& text, LoadReport* report = nullptr) {
    auto level = load_level_string(text, "editor.json", report);
    REQUIRE_MESSAGE(level, (level ? "" : level.error().str()));
    return *level;
}

bool mentions(const LoadReport& report, const std::string& path, const std::string& words) {
    for (const Diagnostic& d : report.diagnostics)
        if (d.severity == Diagnostic::Severity::Warning && d.error.str().find(path) != std::string::npos &&
            d.error.str().find(words) != std::string::npos)
            return true;
    return false;
}
} // namespace

TEST_CASE("the editor section round-trips: layers, nested groups, a prefab instance, hide and lock") {
    Level level = load_ok(level_text(""));
    CHECK(level.editor.empty());
    EditorData& data = level.editor;
    data.layers = {{"Default", true, false, {1}}, {"Walls", false, true, {2, 3}}};
    data.active_layer = 1;
    Group door{1,      "Doorway", Vec3(0, 0, 10), 90.0f,
               {3, 4}, {},        true,           {"doorway", {4, 0, 3}, {{"name"}, {}, {}}}};
    Group outer{2, "East wing", Vec3(1, 2, 3), 0.0f, {2}, {1}, false, {}};
    data.groups = {door, outer};
    data.next_group_id = 3;
    data.hidden = {1};
    data.locked = {2};
    const std::string saved = save_level_string(level);
    LoadReport report;
    Level again = load_ok(saved, &report);
    CHECK(report.diagnostics.empty());
    CHECK(again.editor == level.editor);
    CHECK(again == level);
    CHECK(save_level_string(again) == saved);
}

TEST_CASE("a level without editor data saves no editor section, so shipped files keep their bytes") {
    Level level = load_ok(level_text(""));
    CHECK(save_level_string(level).find("\"editor\"") == std::string::npos);
    level.editor.hidden = {2};
    CHECK(save_level_string(level).find("\"editor\"") != std::string::npos);
}

TEST_CASE("mistakes in the editor section are warnings naming the path; the level still loads") {
    LoadReport report;
    const Level level = load_ok(level_text(R"({
      "layers": [{"name": "A", "entities": [1, 2, 99]}, {"name": "B", "entities": [2, 3], "colour": 1},
                 {"name": "", "entities": [4]}, 7],
      "active_layer": 9,
      "groups": [{"id": 1, "entities": [3, 4], "groups": [2]}, {"id": 2, "entities": [4, 1], "groups": [1]},
                 {"id": 1, "entities": [2]}, {"name": "no id"},
                 {"id": 5, "entities": [2], "position": [0, "x", 0], "yaw": "left",
                  "prefab": {"name": "doorway", "members": [2, 77], "overrides": [["name"]]}}],
      "hidden": [1, -3, "two"],
      "locked": [42],
      "sparkle": true
    })"),
                                &report);
    CHECK_FALSE(report.has_errors());
    INFO(report.str());
    CHECK(mentions(report, "editor.layers[0].entities", "entity 99 does not exist"));
    CHECK(mentions(report, "editor.layers[1].entities", "entity 2 is already in an earlier layer"));
    CHECK(mentions(report, "editor.layers[1].colour", "unknown field"));
    CHECK(mentions(report, "editor.layers[2].name", "needs a name"));
    CHECK(mentions(report, "editor.layers[3]", "expected a layer as an object"));
    CHECK(mentions(report, "editor.active_layer", "expected"));
    CHECK(mentions(report, "editor.groups[1].entities", "entity 4 is already in another group"));
    CHECK(mentions(report, "editor.groups[2].id", "used twice"));
    CHECK(mentions(report, "editor.groups[3].id", "needs an id"));
    CHECK(mentions(report, "editor.groups[4].position[1]", "expected a number, found the string \"x\""));
    CHECK(mentions(report, "editor.groups[4].prefab.overrides", "one list of field names per member"));
    CHECK(mentions(report, "editor.hidden[1]", "expected an id"));
    CHECK(mentions(report, "editor.hidden[2]", "expected an id"));
    CHECK(mentions(report, "editor.locked", "entity 42 does not exist"));
    CHECK(mentions(report, "editor.sparkle", "unknown field"));
    CHECK(mentions(report, "editor.groups", "inside each other"));

    const EditorData& data = level.editor;
    REQUIRE(data.layers.size() == 2);
    CHECK(data.layers[0].entities == std::vector<int>{1, 2});
    CHECK(data.layers[1].entities == std::vector<int>{3});
    CHECK(data.active_layer == 0);
    REQUIRE(data.groups.size() == 3); // ids 1, 2, 5
    CHECK(data.groups[1].entities == std::vector<int>{1});
    const int links = static_cast<int>(data.groups[0].groups.size() + data.groups[1].groups.size());
    CHECK(links == 1); // the loop 1 <-> 2 is cut once
    CHECK(data.groups[2].has_prefab);
    CHECK(data.groups[2].prefab.members == std::vector<int>{2, 0}); // 77 is gone: deleted from the instance
    CHECK(data.groups[2].prefab.overrides.size() == 2);
    CHECK(data.next_group_id == 6);
    CHECK(data.hidden == std::vector<int>{1});
    CHECK(data.locked.empty());
}

TEST_CASE("an editor section that is not an object is one warning") {
    LoadReport report;
    const Level level = load_ok(level_text("[1, 2]"), &report);
    CHECK(report.warning_count() == 1);
    CHECK(mentions(report, "editor", "expected the editor section as an object"));
    CHECK(level.editor.empty());
}
