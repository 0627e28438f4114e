// Groups, layers and prefabs in the real killswitch-editor window, with real X input (xdotool under Xvfb),
// as a designer uses them: select two walls, Ctrl+G, a click on one member selects both, a double click
// enters the group (one member selected), Esc leaves it, Ctrl+Shift+G dissolves it; add a layer in the
// Layers tab, move the selection there from the layer's context menu, hide it with its eye; click a
// prefab in the Prefabs tab, then in the viewport: a linked instance appears, and the inspector unlinks it;
// save a prefab from Edit > Save selection as prefab.... The editor reports its state
// in --status-file every frame; the test waits on that, never on time. Without a display or xdotool these
// tests fail: ./run.sh test provides both.
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
// A floor, two walls to the north-west and north-east, the control panel to the south.
const char* kStructureLevel = R"({
  "format": "killswitch-level",
  "version": 2,
  "name": "Structure input test",
  "player_start": {"position": [0, 0, 20], "yaw": 0},
  "next_id": 5,
  "entities": [
    {"id": 1, "type": "floor", "name": "Ground", "position": [0, 0, 0], "props": {"size": [60, 60]}},
    {"id": 2, "type": "wall", "name": "West", "position": [-15, 0, -12], "props": {"size": [8, 16, 0.5]}},
    {"id": 3, "type": "wall", "name": "East", "position": [15, 0, -12], "props": {"size": [8, 16, 0.5]}},
    {"id": 4, "type": "control_panel", "position": [0, 0, 22]}
  ]
})";

json ids(std::initializer_list<int> list) {
    return json(std::vector<int>(list));
}

// Ctrl held while clicking: the click toggles the entity into the selection.
void ctrl_click(Session& s, const json& point) {
    s.focus();
    s.xdo("keydown ctrl");
    s.wait("Ctrl seen", [](const json& j) { return j["input"]["ctrl"] == true; });
    s.click(point);
    s.frames(2);
    s.xdo("keyup ctrl");
    s.frames(2);
}

// Two clicks in quick succession at `point`: ImGui counts them as a double click when they land in
// different frames less than 0.3 s of its time apart. A slow frame can split them; then it is tried
// again (each single click only selects the group again, which changes nothing).
bool double_click_enters(Session& s, const json& point) {
    for (int attempt = 0; attempt < 5; ++attempt) {
        s.focus();
        s.move_to(point);
        s.xdo("click --repeat 2 --delay 90 1");
        const json st = s.frames(3);
        if (st["open_group"] != 0) return true;
    }
    return false;
}
} // namespace

TEST_CASE("editor structure input: Ctrl+G groups two walls, a click picks the group, a double click enters "
          "it, Esc leaves, Ctrl+Shift+G ungroups, with real X events") {
    test::EditorWindow editor(kStructureLevel, {"--view", "top", "--width", "1280", "--height", "720"});
    Session& s = editor.session();
    json st = s.wait("the walls on screen", [](const json& j) {
        return j["frame"] >= 2 && j["view"] == "Top" && j["screen"].contains("2") &&
               j["screen"].contains("3");
    });
    const json west = st["screen"]["2"], east = st["screen"]["3"];
    CHECK(st["groups"].empty());

    s.click(west);
    s.wait("the west wall selected", [](const json& j) { return j["selection"] == ids({2}); });
    ctrl_click(s, east);
    s.wait("both walls selected", [](const json& j) { return j["selection"].size() == 2; });
    s.key("ctrl+g");
    st = s.wait("one group of the two walls", [](const json& j) { return j["groups"].size() == 1; });
    CHECK(st["groups"][0]["entities"] == ids({2, 3}));
    CHECK(st["groups"][0]["prefab"] == "");
    const int group = st["groups"][0]["id"];
    CHECK(st["undo"] == 1);

    s.key("Escape"); // nothing entered: clears the selection
    s.wait("nothing selected", [](const json& j) { return j["selection"].empty(); });
    s.click(east);
    st = s.wait("a click on one member selects the group",
                [](const json& j) { return j["selection"].size() == 2; });
    CHECK(st["selected_groups"] == ids({group}));
    CHECK(st["open_group"] == 0);

    REQUIRE_MESSAGE(double_click_enters(s, east), "a double click did not enter the group");
    st = s.wait("inside the group, the east wall alone",
                [](const json& j) { return j["selection"] == ids({3}); });
    CHECK(st["open_group"] == group);
    s.click(west); // inside the group, a click picks one member
    s.wait("the west wall alone", [](const json& j) { return j["selection"] == ids({2}); });

    s.key("Escape");
    st = s.wait("left the group, the group selected",
                [](const json& j) { return j["open_group"] == 0 && j["selection"].size() == 2; });
    CHECK(st["selected_groups"] == ids({group}));
    s.key("ctrl+shift+g");
    st = s.wait("no groups", [](const json& j) { return j["groups"].empty(); });
    CHECK(st["undo"] == 2);
    s.key("ctrl+z");
    s.wait("the group back", [](const json& j) { return j["groups"].size() == 1; });
}

TEST_CASE("editor structure input: add a layer, move the selection to it from its context menu, hide it "
          "with its eye, with real X events") {
    test::EditorWindow editor(kStructureLevel, {"--view", "top", "--width", "1280", "--height", "720"});
    Session& s = editor.session();
    json st = s.wait("the Layers tab", [](const json& j) {
        return j["frame"] >= 2 && j["screen"].contains("2") && j["spots"].contains("tab.layers");
    });
    const json west = st["screen"]["2"];
    CHECK(st["layers"].empty());
    s.click(west);
    s.wait("the west wall selected", [](const json& j) { return j["selection"] == ids({2}); });

    s.click(st["spots"]["tab.layers"]);
    st = s.wait("the + Layer button", [](const json& j) { return j["spots"].contains("layers.add"); });
    s.click(st["spots"]["layers.add"]);
    st = s.wait("Default and Layer 1", [](const json& j) {
        return j["layers"].size() == 2 && j["spots"].contains("layer1.name") &&
               j["spots"].contains("layer1.eye");
    });
    CHECK(st["layers"][0]["name"] == "Default");
    CHECK(st["layers"][0]["count"] == 4);
    CHECK(st["layers"][1]["count"] == 0);

    s.focus();
    s.move_to(st["spots"]["layer1.name"]);
    s.xdo("click 3");
    st = s.wait("the layer's menu", [](const json& j) { return j["spots"].contains("layer_menu.move"); });
    s.click(st["spots"]["layer_menu.move"]);
    st = s.wait("the wall in Layer 1", [](const json& j) { return j["layers"][1]["count"] == 1; });
    CHECK(st["layers"][0]["count"] == 3);
    CHECK(st["hidden"].empty());

    s.click(st["spots"]["layer1.eye"]);
    st = s.wait("Layer 1 hidden", [](const json& j) { return j["layers"][1]["visible"] == false; });
    CHECK(st["hidden"] == ids({2}));
    s.key("ctrl+z");
    st = s.wait("shown again", [](const json& j) { return j["layers"][1]["visible"] == true; });
    CHECK(st["hidden"].empty());
}

TEST_CASE("editor structure input: click a prefab's thumbnail, then the viewport: a linked instance, with "
          "real X events") {
    test::EditorWindow editor(kStructureLevel, {"--view", "top", "--width", "1280", "--height", "720"});
    Session& s = editor.session();
    json st = s.wait("the Prefabs tab and the floor", [](const json& j) {
        return j["frame"] >= 2 && j["screen"].contains("1") && j["spots"].contains("tab.prefabs");
    });
    const json floor = st["screen"]["1"];
    s.click(st["spots"]["tab.prefabs"]);
    st = s.wait("the doorway's thumbnail", [](const json& j) {
        return j["spots"].contains("prefab:doorway") && j["prefab_thumbnails"] >= 3;
    });
    bool listed = false;
    for (const json& p : st["prefabs"])
        if (p["name"] == "doorway") listed = p["ok"] == true && p["entities"] == 4;
    CHECK(listed);

    s.click(st["spots"]["prefab:doorway"]);
    s.wait("placing the doorway", [](const json& j) { return j["placing_prefab"] == "doorway"; });
    s.click(floor);
    st = s.wait("a doorway instance", [](const json& j) { return j["groups"].size() == 1; });
    CHECK(st["groups"][0]["prefab"] == "doorway");
    CHECK(st["groups"][0]["entities"].size() == 4);
    CHECK(st["entities"] == 8);
    CHECK(st["placing_prefab"] == ""); // one placed: the tool is done (Shift keeps it)
    CHECK(st["selection"].size() == 4);
    CHECK(st["undo"] == 1);

    // The inspector shows the selected instance: Unlink makes it a plain group (one step).
    st = s.wait("the instance's Unlink button",
                [](const json& j) { return j["spots"].contains("group.unlink"); });
    s.click(st["spots"]["group.unlink"]);
    // The frame that ran the click drew the instance's buttons before it; the next one draws none.
    st = s.wait("a plain group, without the prefab buttons", [](const json& j) {
        return j["groups"][0]["prefab"] == "" && !j["spots"].contains("group.apply");
    });
    CHECK(st["undo"] == 2);
}

TEST_CASE("editor structure input: Edit > Save selection as prefab... refuses a bad name, saves, offers "
          "Replace for a name in use, with real X events") {
    test::require_window_test_tools();
    test::ScratchDir dir;
    const auto level_file = dir / "structure_input.json";
    std::ofstream(level_file) << kStructureLevel;
    const auto prefabs = dir / "my_prefabs";
    std::filesystem::create_directories(prefabs);
    std::ofstream(prefabs / "broken.json") << "{\"format\": \"killswitch-prefab\", \"version\": 1,";
    std::ofstream(dir / "setup.kss") << "prefab folder " << prefabs.string() << "\nselect 2 3\n";
    const auto status = dir / "status.json";
    const test::PrivateDisplay display;
    EditorProcess process(
        {"--level", level_file.string(), "--run", (dir / "setup.kss").string(), "--width", "1280", "--height",
         "720", "--status-file", status.string()},
        {"XDG_CONFIG_HOME=" + (dir / "config").string(), "XDG_DATA_HOME=" + (dir / "data").string()},
        display);
    Session s(status, process, display);
    auto open_prompt = [&] {
        json st = s.wait("the Edit menu", [](const json& j) { return j["spots"].contains("menu.edit"); });
        s.click(st["spots"]["menu.edit"]);
        st = s.wait("its Save as prefab item",
                    [](const json& j) { return j["spots"].contains("menu.save_prefab"); });
        s.click(st["spots"]["menu.save_prefab"]);
        return s.wait("the prompt", [](const json& j) {
            return j["prefab_prompt"]["open"] == true && j["spots"].contains("prefab_prompt.save");
        });
    };
    json st = s.wait("the two walls selected", [](const json& j) {
        return j["frame"] >= 2 && j["selection"] == ids({2, 3});
    });
    CHECK(st["prefab_folders"] == json::array({prefabs.string()}));
    // A broken file is listed with its error (the Prefabs tab shows it in red), never dropped.
    REQUIRE(st["prefabs"].size() == 1);
    CHECK(st["prefabs"][0]["name"] == "broken");
    CHECK(st["prefabs"][0]["ok"] == false);
    CHECK(st["prefabs"][0]["error"].get<std::string>().find("broken.json") != std::string::npos);
    s.click(st["spots"]["tab.prefabs"]);
    s.wait("the broken prefab's row", [](const json& j) { return j["spots"].contains("prefab:broken"); });
    open_prompt();
    s.type("Two Walls");
    st = s.wait("the name refused", [](const json& j) { return j["prefab_prompt"]["problem"] != ""; });
    s.key("ctrl+a");
    s.type("twin_walls");
    st = s.wait("the name accepted", [](const json& j) {
        return j["prefab_prompt"]["name"] == "twin_walls" && j["prefab_prompt"]["problem"] == "";
    });
    CHECK(st["prefab_prompt"]["exists"] == false);
    s.click(st["spots"]["prefab_prompt.title"]);
    s.type("Twin walls");
    s.click(st["spots"]["prefab_prompt.save"]);
    st = s.wait("saved as an instance",
                [](const json& j) { return j["prefab_prompt"]["open"] == false && j["groups"].size() == 1; });
    CHECK(st["groups"][0]["prefab"] == "twin_walls");
    CHECK(std::filesystem::exists(prefabs / "twin_walls.json"));
    CHECK(st["prefab_prompt"]["error"] == "");
    s.wait("its thumbnail in the Prefabs tab", [](const json& j) {
        return j["prefab_thumbnails"] == 1 && j["spots"].contains("prefab:twin_walls");
    });

    open_prompt(); // the instance is still selected: the same name is offered Replace
    s.type("twin_walls");
    st = s.wait("the name in use", [](const json& j) { return j["prefab_prompt"]["exists"] == true; });
    s.click(st["spots"]["prefab_prompt.save"]);
    st = s.wait("replaced", [](const json& j) { return j["prefab_prompt"]["open"] == false; });
    CHECK(st["prefab_prompt"]["error"] == "");
    CHECK(st["groups"].size() == 1);

    // Another editor changes the prefab on disk: the open level's instance follows it within the rescan's
    // two seconds, as one undo step, without a click.
    json prefab = json::parse(test::read_file(prefabs / "twin_walls.json"));
    for (json& e : prefab["entities"]) e["props"]["size"] = json::array({8, 12, 0.5});
    std::ofstream(prefabs / "twin_walls.json.tmp") << prefab.dump(2);
    std::filesystem::rename(prefabs / "twin_walls.json.tmp", prefabs / "twin_walls.json");
    st = s.wait("the instance follows the changed prefab", [](const json& j) {
        return j["undo_name"].get<std::string>().find("Update prefab instances (twin_walls)") == 0;
    });
    CHECK(st["groups"].size() == 1);
    CHECK(st["dirty"] == true);
}
