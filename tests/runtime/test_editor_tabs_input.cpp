// Every tab of the editor window opened from every other tab of its bar, with real X input (xdotool under
// Xvfb), on a fresh start and at two window sizes: the Level and Dojo tabs, the left column's Outliner,
// Layers and Prefabs, the inspector's Properties, Links and Objectives, the dojo's Keys, Curves, Blends and
// Events pages. Opening the Dojo from the Level tab once aborted the editor on an ImGui assertion (a
// zero-sized timeline before the preview's first render) and lost the designer's unsaved level: the first
// case makes an unsaved edit, opens the Dojo, comes back and finds the edit still there. The editor
// reports its state in --status-file every frame; the test waits on that, never on time.
#include "runtime/editor_session.h"
#include "runtime/screen_image.h"
#include "test_support.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <fstream>

using namespace ks;
using nlohmann::json;
using test::EditorProcess;
using Session = test::EditorSession;

namespace {
const char* kTabsLevel = R"({
  "format": "killswitch-level",
  "version": 2,
  "name": "Tabs input test",
  "player_start": {"position": [0, 0, 20], "yaw": 0},
  "next_id": 5,
  "entities": [
    {"id": 1, "type": "floor", "name": "Ground", "position": [0, 0, 0], "props": {"size": [60, 60]}},
    {"id": 2, "type": "wall", "name": "West", "position": [-15, 0, -12], "props": {"size": [8, 16, 0.5]}},
    {"id": 3, "type": "wall", "name": "East", "position": [15, 0, -12], "props": {"size": [8, 16, 0.5]}},
    {"id": 4, "type": "control_panel", "position": [0, 0, 22]}
  ]
})";

// The editor on kTabsLevel at width x height, in the Level tab or (start_in_dojo) the Dojo tab.
test::EditorWindow open_editor(int width, int height, bool start_in_dojo = false) {
    std::vector<std::string> args{
        "--view", "top", "--width", std::to_string(width), "--height", std::to_string(height)};
    if (start_in_dojo) args.push_back("--dojo");
    return test::EditorWindow(kTabsLevel, args);
}

// Where the tab `name` of a bar is drawn: "tab.NAME" in the level's spots, "page_NAME" in the dojo's.
json tab_spot(const json& st, const std::string& bar, const std::string& name) {
    if (bar == "dojo_page") return st["dojo"]["spots"]["page_" + name];
    return st["spots"]["tab." + name];
}

// Which tab of a bar the status says is shown.
json shown(const json& st, const std::string& bar) {
    if (bar == "dojo_page") return st["dojo"]["page"];
    return st[bar];
}

// Clicks through `tabs` in order, waiting each time until the editor shows the clicked tab and has drawn
// a few more frames with it (an assertion would have ended the process, and the wait with it).
void visit(Session& s, const std::string& bar, const std::vector<std::string>& tabs) {
    for (const std::string& name : tabs) {
        const json st = s.wait(("the " + name + " tab drawn").c_str(),
                               [&](const json& j) { return !tab_spot(j, bar, name).is_null(); });
        s.click(tab_spot(st, bar, name));
        s.wait(("the " + name + " tab shown").c_str(), [&](const json& j) { return shown(j, bar) == name; });
        const json after = s.frames(3);
        CHECK_MESSAGE(shown(after, bar) == name, bar << ": " << name << " did not stay shown");
    }
}

// A sequence through every ordered pair of `tabs` (a walk over the complete directed graph), from the
// first one, which is shown on a fresh start.
std::vector<std::string> every_pair(const std::vector<std::string>& tabs) {
    std::vector<std::string> walk;
    if (tabs.size() == 2) return {tabs[1], tabs[0]};
    if (tabs.size() == 3) // a b c: a>b b>c c>a a>c c>b b>a
        return {tabs[1], tabs[2], tabs[0], tabs[2], tabs[1], tabs[0]};
    // four: a>b b>a a>c c>a a>d d>b b>c c>b b>d d>c c>d d>a
    return {tabs[1], tabs[0], tabs[2], tabs[0], tabs[3], tabs[1],
            tabs[2], tabs[1], tabs[3], tabs[2], tabs[3], tabs[0]};
}

void every_tab_from_every_other(int width, int height) {
    test::EditorWindow editor = open_editor(width, height);
    Session& s = editor.session();
    json st = s.wait("the walls on screen", [](const json& j) {
        return j["frame"] >= 2 && j["tab"] == "level" && j["screen"].contains("2");
    });
    s.click(st["screen"]["2"]); // the inspector shows an entity's tabs
    s.wait("the west wall selected", [](const json& j) { return j["selection"] == json::array({2}); });

    visit(s, "left_tab", every_pair({"outliner", "layers", "prefabs"}));
    visit(s, "inspector_tab", every_pair({"properties", "links", "objectives"}));
    visit(s, "tab", {"dojo"}); // the Dojo opened from the Level tab: once an abort
    visit(s, "dojo_page", every_pair({"keys", "curves", "blends", "events"}));
    visit(s, "tab", {"level", "dojo", "level"});
    st = s.frames(2);
    CHECK(st["selection"] == json::array({2})); // the level's state came through the trips
    CHECK(editor.process().alive());
}
} // namespace

TEST_CASE("editor tabs input: the Dojo opened from the Level tab keeps the editor and the unsaved edit") {
    test::EditorWindow editor = open_editor(1280, 720);
    Session& s = editor.session();
    json st = s.wait("the walls on screen", [](const json& j) {
        return j["frame"] >= 2 && j["tab"] == "level" && j["screen"].contains("3");
    });
    const size_t entities = st["entities"];
    s.click(st["screen"]["3"]);
    s.wait("the east wall selected", [](const json& j) { return j["selection"] == json::array({3}); });
    s.key("Delete");
    st = s.wait("the east wall deleted, unsaved", [&](const json& j) {
        return j["entities"] == entities - 1 && j["dirty"] == true && j["undo"] == 1;
    });

    s.click(st["spots"]["tab.dojo"]);
    st = s.wait("the Dojo with its clips", [](const json& j) {
        return j["tab"] == "dojo" && j.contains("dojo") && j["dojo"]["spots"].contains("page_keys");
    });
    s.frames(5); // the preview renders, the timeline is drawn over it
    REQUIRE(editor.process().alive());

    st = s.wait("the Level tab's spot", [](const json& j) { return j["spots"].contains("tab.level"); });
    s.click(st["spots"]["tab.level"]);
    st = s.wait("back on the level", [](const json& j) { return j["tab"] == "level"; });
    CHECK(st["entities"] == entities - 1);
    CHECK(st["dirty"] == true);
    CHECK(st["undo"] == 1);
    CHECK(st["undo_name"] != "");
}

TEST_CASE("editor tabs input: every tab from every other at 1280x720") {
    every_tab_from_every_other(1280, 720);
}

TEST_CASE("editor tabs input: every tab from every other at 640x360") {
    every_tab_from_every_other(640, 360);
}

TEST_CASE("editor tabs input: the Level tab opened from a fresh start in the Dojo, and back") {
    test::EditorWindow editor = open_editor(1280, 720, true);
    Session& s = editor.session();
    s.wait("the Dojo on a fresh start", [](const json& j) {
        return j["frame"] >= 2 && j["tab"] == "dojo" && j["dojo"]["spots"].contains("page_keys");
    });
    visit(s, "tab", {"level", "dojo"});
    CHECK(editor.process().alive());
}
