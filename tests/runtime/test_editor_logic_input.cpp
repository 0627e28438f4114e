// Wiring level logic in the real killswitch-editor window with real X input (xdotool, under Xvfb), as a
// designer does: select a trigger, add a link in the inspector's Links tab, choose its event, pick its target
// by clicking an unnamed door in the viewport (a wall is refused; Esc and a right click cancel), choose the
// action, save, check the file, undo; and in the Objectives tab add an objective, put a robot on its kill
// list by picking it, give it an on_complete link that wins the level, save and undo. The editor reports its
// state and where its widgets are in --status-file every frame; the test waits on that, never on time. A
// screenshot test checks the selected trigger's link arrows are drawn.
#include "level/level_io.h"
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
// A floor, a trigger, an unnamed door, a wall (takes no action) and an unnamed robot.
const char* kLogicLevel = R"({
  "format": "killswitch-level",
  "version": 2,
  "name": "Logic input test",
  "player_start": {"position": [0, 0, 15], "yaw": 0},
  "next_id": 6,
  "entities": [
    {"id": 1, "type": "floor", "name": "Ground", "position": [0, 0, 0], "props": {"size": [40, 40]}},
    {"id": 2, "type": "trigger", "name": "Entry", "position": [-10, 0, 0], "props": {"size": [6, 4, 6]}},
    {"id": 3, "type": "door", "position": [10, 0, 0]},
    {"id": 4, "type": "wall", "name": "Block", "position": [0, 0, -12], "props": {"size": [8, 16, 0.5]}},
    {"id": 5, "type": "robot", "position": [0, 0, 10]}
  ]
})";
constexpr int kTrigger = 2, kDoor = 3, kWall = 4, kRobot = 5;

json links(const json& status) {
    return status.contains("primary") ? status["primary"]["links"] : json::array();
}

// Clicks the widget at spot `name`. An edit made by the viewport (a pick) moves the inspector's widgets
// only in the frame after (the inspector is drawn before the viewport's input): wait for that frame, so
// the spot is where the widget is now.
void click_spot(Session& s, const std::string& name) {
    s.frames(2);
    const json st = s.wait(name.c_str(), [&](const json& j) { return test::has_spot(j, name); });
    s.click(st["spots"][name]);
}

// Undoes one step with Ctrl+Z (EditorSession::key releases it before the key repeat could undo a second).
json undo_one(Session& s) {
    const size_t target = s.frames(1)["undo"].get<size_t>() - 1;
    s.key("ctrl+z");
    s.wait("an undo", [&](const json& j) { return j["undo"] <= target; });
    return s.frames(1);
}

// Opens the combo at spot `combo` and clicks its entry `item`.
void choose(Session& s, const std::string& combo, const std::string& item) {
    click_spot(s, combo);
    const json st = s.wait(("the entry " + item + " of " + combo).c_str(),
                           [&](const json& j) { return test::has_spot(j, "combo:" + item); });
    s.click(st["spots"]["combo:" + item]);
}

} // namespace

TEST_CASE("editor logic input: add a link, choose its event, pick its target in the viewport, choose the "
          "action, save and undo with real X events") {
    test::require_window_test_tools();
    test::ScratchDir dir;
    const auto level_file = test::write_file(dir / "logic_input.json", kLogicLevel);
    const auto status = dir / "status.json";
    const test::PrivateDisplay display;
    EditorProcess editor({"--level", level_file.string(), "--view", "top", "--inspector", "links", "--width",
                          "1280", "--height", "720", "--status-file", status.string()},
                         {"XDG_CONFIG_HOME=" + (dir / "config").string()}, display);
    Session s(status, editor, display);
    json st = s.wait("first frames", [](const json& j) { return j["frame"] >= 2 && j["view"] == "Top"; });

    // Select the trigger with a click; its Links tab offers "+ Add link".
    s.click(st["screen"][std::to_string(kTrigger)]);
    st = s.wait("the trigger selected and its Add link button", [](const json& j) {
        return j["selection"] == json::array({kTrigger}) && test::has_spot(j, "link_add");
    });
    const size_t undo0 = st["undo"];
    click_spot(s, "link_add");
    st = s.wait("a link added", [](const json& j) { return links(j).size() == 1; });
    CHECK(st["undo"] == undo0 + 1);
    CHECK(links(st)[0]["event"] == "on_enter"); // the trigger's first event
    CHECK(links(st)[0]["target"] == "");

    // The event combo offers the trigger's events only.
    click_spot(s, "link0.event");
    st = s.wait("the event list", [](const json& j) { return test::has_spot(j, "combo:on_exit"); });
    CHECK_FALSE(test::has_spot(st, "combo:on_death")); // a robot's event, not a trigger's
    s.click(st["spots"]["combo:on_exit"]);
    st = s.wait("the event chosen", [](const json& j) { return links(j)[0]["event"] == "on_exit"; });
    CHECK(st["undo"] == undo0 + 2);

    // Pick mode: Esc cancels, a right click cancels, a wall is refused, the unnamed door is taken and named.
    click_spot(s, "link0.pick");
    s.wait("pick mode", [](const json& j) { return j["pick"]["active"] == true; });
    s.key("Escape");
    st = s.wait("pick cancelled by Esc", [](const json& j) { return j["pick"]["active"] == false; });
    CHECK(st["selection"] == json::array({kTrigger})); // Esc ended the pick, not the selection
    click_spot(s, "link0.pick");
    st = s.wait("pick mode again", [](const json& j) { return j["pick"]["active"] == true; });
    s.focus();
    s.move_to(st["screen"][std::to_string(kRobot)]);
    s.xdo("click 3");
    st =
        s.wait("pick cancelled by a right click", [](const json& j) { return j["pick"]["active"] == false; });
    click_spot(s, "link0.pick");
    st = s.wait("pick mode a third time", [](const json& j) { return j["pick"]["active"] == true; });
    s.click(st["screen"][std::to_string(kWall)]);
    st = s.wait("the wall refused", [](const json& j) {
        return j["pick"]["message"].get<std::string>().find("takes no action") != std::string::npos;
    });
    CHECK(st["pick"]["active"] == true); // still picking
    CHECK(links(st)[0]["target"] == "");
    CHECK(st["undo"] == undo0 + 2);
    s.click(st["screen"][std::to_string(kDoor)]);
    st = s.wait("the door picked", [](const json& j) { return links(j)[0]["target"] != ""; });
    CHECK(links(st)[0]["target"] == "door_1"); // named on pick, from its type
    CHECK(links(st)[0]["action"] == "open");   // the door takes the new link's action
    CHECK(st["pick"]["active"] == false);
    CHECK(st["undo"] == undo0 + 3); // naming the door and setting the target: one step
    CHECK(st["selection"] == json::array({kTrigger}));

    st = s.wait("the link's arrow", [](const json& j) { return j["link_arrows"] == 1; });

    // The action combo offers the door's actions.
    choose(s, "link0.action", "toggle");
    st = s.wait("the action chosen", [](const json& j) { return links(j)[0]["action"] == "toggle"; });
    CHECK(st["undo"] == undo0 + 4);

    // Dragging the delay is one step however far it goes.
    st = s.frames(2);
    s.drag(st["spots"]["link0.delay"], 60.0f, 0.0f, 6);
    st = s.wait("the delay dragged", [](const json& j) {
        return links(j)[0]["delay"].get<float>() > 0.5f && j["input"]["active_item"] == false;
    });
    CHECK(st["undo"] == undo0 + 5);
    const float delay = links(st)[0]["delay"];

    s.key("ctrl+s");
    st = s.wait("saved", [](const json& j) { return j["dirty"] == false; });
    {
        auto saved = level::load_level_file(level_file);
        REQUIRE_MESSAGE(saved.ok(), (saved.ok() ? std::string() : saved.error().str()));
        const level::Entity* trigger = saved->find(kTrigger);
        REQUIRE(trigger);
        REQUIRE(trigger->links.size() == 1);
        CHECK(trigger->links[0] == level::Link{"on_exit", "door_1", "toggle", delay, false});
        CHECK(saved->find(kDoor)->name == "door_1");
    }

    // Undo: the delay, the action, then the pick (target and the door's name together).
    st = undo_one(s);
    CHECK(links(st)[0]["delay"] == 0.0f);
    CHECK(links(st)[0]["action"] == "toggle");
    st = undo_one(s);
    CHECK(links(st)[0]["action"] == "open");
    CHECK(links(st)[0]["target"] == "door_1");
    st = undo_one(s);
    CHECK(links(st)[0]["target"] == "");
    CHECK(links(st)[0]["event"] == "on_exit");
    CHECK(st["undo"] == undo0 + 2);
    s.click(st["screen"][std::to_string(kDoor)]);
    st = s.wait("the door selected", [](const json& j) { return j["selection"] == json::array({kDoor}); });
    CHECK(st["primary"]["name"] == ""); // unnamed again
}

TEST_CASE("editor logic input: add an objective, pick a robot for its kill list, give it a link that wins "
          "the level, save and undo with real X events") {
    test::require_window_test_tools();
    test::ScratchDir dir;
    const auto level_file = test::write_file(dir / "logic_input.json", kLogicLevel);
    const auto status = dir / "status.json";
    const test::PrivateDisplay display;
    EditorProcess editor({"--level", level_file.string(), "--view", "top", "--inspector", "objectives",
                          "--width", "1280", "--height", "720", "--status-file", status.string()},
                         {"XDG_CONFIG_HOME=" + (dir / "config").string()}, display);
    Session s(status, editor, display);
    json st = s.wait("the Objectives tab", [](const json& j) { return test::has_spot(j, "objective_add"); });
    CHECK(st["objectives"].empty());
    click_spot(s, "objective_add");
    st = s.wait("an objective added", [](const json& j) { return j["objectives"].size() == 1; });
    CHECK(st["objectives"][0]["id"] == "objective_1");
    const size_t undo0 = st["undo"];

    // Its kill list: Pick, then the unnamed robot in the viewport.
    click_spot(s, "objective0.kill_pick");
    st = s.wait("pick mode", [](const json& j) { return j["pick"]["purpose"] == "kill"; });
    s.click(st["screen"][std::to_string(kDoor)]); // a door cannot be killed
    st = s.wait("the door refused", [](const json& j) {
        return j["pick"]["message"].get<std::string>().find("cannot be killed") != std::string::npos;
    });
    s.click(st["screen"][std::to_string(kRobot)]);
    st = s.wait("the robot on the kill list",
                [](const json& j) { return j["objectives"][0]["kill"].size() == 1; });
    CHECK(st["objectives"][0]["kill"][0] == "robot_1");
    CHECK(st["undo"] == undo0 + 1);

    // An on_complete link to the level: choosing the target picks an action the level takes (win).
    click_spot(s, "objective0.link_add");
    st = s.wait("a link added", [](const json& j) { return j["objectives"][0]["links"].size() == 1; });
    choose(s, "objective0.link0.target", "level");
    st = s.wait("the target chosen",
                [](const json& j) { return j["objectives"][0]["links"][0]["target"] == "level"; });
    CHECK(st["objectives"][0]["links"][0]["action"] == "win");
    CHECK(st["objectives"][0]["links"][0]["event"] == "on_complete");

    s.key("ctrl+s");
    s.wait("saved", [](const json& j) { return j["dirty"] == false; });
    {
        auto saved = level::load_level_file(level_file);
        REQUIRE_MESSAGE(saved.ok(), (saved.ok() ? std::string() : saved.error().str()));
        REQUIRE(saved->objectives.size() == 1);
        const level::Objective& o = saved->objectives[0];
        CHECK(o.id == "objective_1");
        CHECK(o.kill == std::vector<std::string>{"robot_1"});
        REQUIRE(o.links.size() == 1);
        CHECK(o.links[0] == level::Link{"on_complete", "level", "win", 0.0f, false});
        CHECK(saved->find(kRobot)->name == "robot_1");
    }
    st = undo_one(s); // the target
    CHECK(st["objectives"][0]["links"][0]["target"] == "");
    st = undo_one(s); // the link
    CHECK(st["objectives"][0]["links"].empty());
    CHECK(st["objectives"][0]["kill"].size() == 1);
    st = undo_one(s); // the kill pick, with the robot's name
    CHECK(st["undo"] == undo0);
    CHECK(st["objectives"][0]["kill"].empty());
    CHECK(st["objectives"][0]["links"].empty());
}

TEST_CASE(
    "killswitch-editor draws the selected trigger's outgoing links as bright arrows, and none without a "
    "selection; --inspector takes only its three tabs") {
    test::require_window_test_tools();
    test::ScratchDir dir;
    const std::string editor = (test::bin_dir() / "killswitch-editor").string();
    const auto level = test::source_dir() / "tests/data/levels/logic_hall.json";
    std::ofstream(dir / "select.kss") << "select 13\n";
    std::ofstream(dir / "none.kss") << "select none\n";
    auto shot = [&](const char* name, const char* script) {
        const auto png = dir / (std::string(name) + ".png");
        const auto run =
            test::run_command(editor + " --level " + level.string() + " --run " + (dir / script).string() +
                              " --camera 15,17,-1,40,-40 --inspector links" +
                              " --width 1280 --height 720 --frames 4 --screenshot " + png.string());
        INFO(run.output);
        REQUIRE(run.exit_code == 0);
        return test::load_png(png);
    };
    const test::Image selected = shot("selected", "select.kss"), none = shot("none", "none.kss");
    REQUIRE_FALSE(selected.rgb.empty());
    REQUIRE_FALSE(none.rgb.empty());
    // The outgoing arrows and their labels are (255, 200, 60); the lights' ranges are paler, the gizmo
    // red, green and blue.
    auto outgoing = [](const unsigned char* p) {
        return p[0] > 235 && p[1] > 175 && p[1] < 220 && p[2] < 100;
    };
    auto count = [&](const test::Image& img) {
        int n = 0;
        for (int y = 60; y < 550; ++y) // the viewport
            for (int x = 250; x < 950; ++x) n += outgoing(img.at(x, y));
        return n;
    };
    const int bright = count(selected), unselected = count(none);
    INFO("outgoing-arrow pixels with the trigger selected " << bright << ", without " << unselected);
    CHECK(bright > 150);
    CHECK(bright > 20 * std::max(unselected, 1));

    const auto bad =
        test::run_command(editor + " --inspector nope --frames 1 --screenshot " + (dir / "bad.png").string());
    CHECK(bad.exit_code == 2);
    CHECK(bad.output.find("--inspector 'nope': expected properties, links or objectives") !=
          std::string::npos);
}
