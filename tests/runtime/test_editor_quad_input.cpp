// The 4-up view and the Analyze action in the real killswitch-editor window, with real X input (xdotool,
// under Xvfb): Numpad 0 splits the viewport into top, front, side and perspective panes; a click selects in
// an orthographic pane, the gizmo drags in another, a box select works in a third, each pane becoming the
// active one; idle panes are not drawn again; the panes follow a window resize and still pick; Numpad 0
// goes back to one view; there the draw tool drags a box, the clip tool cuts it, the vertex tool drags
// one of its corners, the measuring tool measures its width, and a second box is subtracted from it through
// the Brush menu. The Analyze button plays the level with the bot in the background, saves the report
// beside the level and marks it stale after an edit. The editor reports its state in --status-file every
// frame; the test waits on that.
#include "game/playtest_report.h"
#include "runtime/editor_session.h"
#include "runtime/screen_image.h"
#include "test_support.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <numbers>

using namespace ks;
using nlohmann::json;
using test::EditorProcess;
using Session = test::EditorSession;

namespace {
// A floor, a wall to the north, the control panel and a robot to the west of the player start.
const char* kQuadLevel = R"({
  "format": "killswitch-level",
  "version": 2,
  "name": "Quad input test",
  "player_start": {"position": [0, 0, 15], "yaw": 0},
  "next_id": 5,
  "entities": [
    {"id": 1, "type": "floor", "name": "Ground", "position": [0, 0, 0], "props": {"size": [40, 40]}},
    {"id": 2, "type": "wall", "name": "North", "position": [0, 0, -20], "props": {"size": [40, 16, 0.5]}},
    {"id": 3, "type": "control_panel", "name": "Panel", "position": [0, 0, -15]},
    {"id": 4, "type": "robot", "name": "Guard", "position": [-10, 0, 5]}
  ]
})";
constexpr int kQuadRobot = 4;

// The robot's centre on screen in pane `pane` (window pixels).
json in_pane(const json& status, int pane) {
    return status["panes"][pane]["screen"][std::to_string(kQuadRobot)];
}

// The four panes are the same size and tile the viewport without overlapping.
void check_tiling(const json& st) {
    REQUIRE(st["panes"].size() == 4);
    const json& vp = st["viewport_area"];
    for (int i = 0; i < 4; ++i) {
        const json& r = st["panes"][i]["rect"];
        CHECK(r[2] == st["panes"][0]["rect"][2]);
        CHECK(r[3] == st["panes"][0]["rect"][3]);
        CHECK(r[0].get<float>() >= vp[0].get<float>() - 1.0f);
        CHECK(r[0].get<float>() + r[2].get<float>() <= vp[0].get<float>() + vp[2].get<float>() + 1.0f);
        CHECK(r[1].get<float>() + r[3].get<float>() <= vp[1].get<float>() + vp[3].get<float>() + 1.0f);
        CHECK(r[2].get<float>() > 0.45f * vp[2].get<float>());
    }
    CHECK(st["panes"][1]["rect"][0].get<float>() > st["panes"][0]["rect"][0].get<float>());
    CHECK(st["panes"][2]["rect"][1].get<float>() > st["panes"][0]["rect"][1].get<float>());
}
} // namespace

TEST_CASE("editor 4-up view: select, drag the gizmo and box select in different panes, resize, with real "
          "X events") {
    test::require_window_test_tools();
    test::ScratchDir dir;
    const auto level_file = test::write_file(dir / "quad_input.json", kQuadLevel);
    const auto status = dir / "status.json";
    const test::PrivateDisplay display;
    EditorProcess editor({"--level", level_file.string(), "--width", "1280", "--height", "720",
                          "--status-file", status.string()},
                         {"XDG_CONFIG_HOME=" + (dir / "config").string()}, display);
    Session s(status, editor, display);
    json st = s.wait("first frames", [](const json& j) { return j["frame"] >= 2; });
    CHECK(st["quad"] == false);

    s.key("KP_0");
    st = s.wait("the 4-up view", [](const json& j) { return j["quad"] == true && j["panes"].size() == 4; });
    CHECK(st["panes"][0]["view"] == "Top");
    CHECK(st["panes"][1]["view"] == "Front");
    CHECK(st["panes"][2]["view"] == "Side");
    CHECK(st["panes"][3]["view"] == "Perspective");
    check_tiling(st);
    for (int pane = 0; pane < 4; ++pane)
        CHECK(st["panes"][pane]["screen"].contains(std::to_string(kQuadRobot)));
    // Idle panes keep their pictures: nothing is drawn again while nothing changes.
    const json idle = s.frames(3)["panes"];
    st = s.frames(3);
    for (int pane = 0; pane < 4; ++pane) CHECK(st["panes"][pane]["renders"] == idle[pane]["renders"]);

    // A click on the robot in the top pane selects it, and makes the top pane the active one.
    s.click(in_pane(st, 0));
    st = s.wait("the robot selected in the top pane", [](const json& j) {
        return j["selection"] == json::array({kQuadRobot}) && j["active_pane"] == 0;
    });
    CHECK(st["view"] == "Top");

    // In the front pane: a click selects again (after Esc), then the gizmo's x arrow drags it east.
    s.key("Escape");
    st = s.wait("selection cleared", [](const json& j) { return j["selection"].empty(); });
    s.click(in_pane(st, 1));
    st = s.wait("the robot selected in the front pane", [](const json& j) {
        return j["selection"] == json::array({kQuadRobot}) && j["active_pane"] == 1 &&
               j.contains("gizmo_handles");
    });
    CHECK(st["view"] == "Front");
    const float x0 = st["primary"]["position"][0];
    const size_t undo0 = st["undo"];
    s.drag(st["gizmo_handles"]["x"], 80.0f, 0.0f);
    st = s.wait("the gizmo drag in the front pane",
                [&](const json& j) { return j["dragging"] == false && j["undo"] == undo0 + 1; });
    CHECK(st["primary"]["position"][0].get<float>() > x0 + 2.0f);
    CHECK(st["active_pane"] == 1);
    for (int pane = 0; pane < 4; ++pane) // the robot moved in every pane's picture
        CHECK(st["panes"][pane]["renders"].get<int>() > idle[pane]["renders"].get<int>());
    s.key("ctrl+z");
    st = s.wait("the drag undone", [&](const json& j) { return j["undo"] == undo0; });
    CHECK(st["primary"]["position"][0].get<float>() == x0);

    // A box select in the side pane: a rectangle around the robot only.
    s.key("Escape");
    st = s.wait("selection cleared again", [](const json& j) { return j["selection"].empty(); });
    const json robot_side = in_pane(st, 2);
    s.drag(json{robot_side[0].get<float>() - 25.0f, robot_side[1].get<float>() - 25.0f}, 50.0f, 50.0f);
    st = s.wait("the robot box-selected in the side pane", [](const json& j) {
        return j["selection"] == json::array({kQuadRobot}) && j["active_pane"] == 2;
    });

    // The panes follow the window when it is resized, and still pick.
    s.focus();
    const std::string window = s.xdo("search --onlyvisible --pid " + std::to_string(st["pid"].get<long>()));
    const json before = st["panes"][0]["rect"];
    s.xdo("windowsize " + window.substr(0, window.find('\n')) + " 1100 640");
    st = s.wait("the panes resized",
                [&](const json& j) { return j["panes"].size() == 4 && j["panes"][0]["rect"] != before; });
    check_tiling(st);
    CHECK(st["panes"][0]["rect"][2].get<float>() < before[2].get<float>());
    s.key("Escape");
    st = s.wait("selection cleared after the resize", [](const json& j) { return j["selection"].empty(); });
    s.click(in_pane(st, 0));
    st = s.wait("the robot selected in the resized top pane", [](const json& j) {
        return j["selection"] == json::array({kQuadRobot}) && j["active_pane"] == 0;
    });

    // Numpad 0 again: one view, the active pane's.
    s.key("KP_0");
    st = s.wait("back to one view", [](const json& j) { return j["quad"] == false; });
    CHECK(st["view"] == "Top");
    CHECK(st["panes"].empty());

    // The draw tool (B): a box dragged in the top view, its size shown live, placed as one undo step.
    s.key("Escape");
    s.key("b");
    st = s.wait("the draw tool", [](const json& j) { return j["tool"]["active"] == "draw"; });
    const size_t entities = st["entities"], undo_draw = st["undo"];
    const json robot = st["screen"][std::to_string(kQuadRobot)], panel = st["screen"]["3"];
    const json start{(robot[0].get<float>() + panel[0].get<float>()) * 0.5f + 30.0f,
                     (robot[1].get<float>() + panel[1].get<float>()) * 0.5f};
    s.move_to(start);
    s.press();
    s.xdo("mousemove " + s.at(json{start[0].get<float>() + 90.0f, start[1].get<float>() + 70.0f}));
    st = s.wait("the box's live dimensions", [](const json& j) {
        return j["tool"]["draw"]["stage"] == "dragging" && j["tool"]["draw"].contains("dimensions") &&
               j["tool"]["draw"]["dimensions"][0].get<double>() > 0.0 &&
               j["tool"]["draw"]["dimensions"][2].get<double>() > 0.0;
    });
    CHECK(st["tool"]["labels"].size() >= 4); // width x depth x height, and the three edges
    const double width = st["tool"]["draw"]["dimensions"][0];
    s.xdo("mouseup 1");
    st = s.wait("the box placed", [&](const json& j) {
        return j["entities"] == entities + 1 && j["undo"] == undo_draw + 1 &&
               j["tool"]["draw"]["stage"] == "idle";
    });
    CHECK(st["undo_name"] == "Place box brush");
    REQUIRE(st["selection"].size() == 1);

    // The clip tool (C): two clicks across the new box in the top view, Keep (front), Apply.
    s.key("c");
    st = s.wait("the clip tool", [](const json& j) { return j["tool"]["active"] == "clip"; });
    const float across = start[0].get<float>() + 45.0f;
    s.click(json{across, start[1].get<float>() + 20.0f});
    s.wait("one clip point", [](const json& j) { return j["tool"]["clip"]["points"] == 1; });
    s.click(json{across, start[1].get<float>() + 50.0f});
    st = s.wait("the clip plane previewed", [](const json& j) {
        return j["tool"]["clip"]["points"] == 2 && j["tool"]["clip"].contains("plane") &&
               j["tool"]["problem"] == "";
    });
    CHECK(std::abs(st["tool"]["clip"]["plane"][0].get<double>()) == doctest::Approx(1.0)); // across x
    st = s.frames(2); // the bar drops its problem line and fits itself to the rest a frame later
    s.click(st["spots"]["tool.keep"]); // the bar's Keep button, as Tab does
    st = s.wait("keep front", [](const json& j) { return j["tool"]["clip"]["keep"] == "front"; });
    s.click(st["spots"]["tool.apply"]); // the bar's Apply button, as Enter does
    st = s.wait("the box clipped", [&](const json& j) { return j["undo"] == undo_draw + 2; });
    CHECK(st["undo_name"] == "Clip brushes");
    CHECK(st["entities"] == entities + 1);
    CHECK(st["tool"]["clip"]["points"] == 0);
    CHECK(width > 0.0);

    // The vertex tool (V): the clipped box's bottom-right corner on screen dragged outward, one undo step.
    s.key("v");
    st = s.wait("the vertex tool's handles", [](const json& j) {
        return j["tool"]["active"] == "vertex" && j["tool"]["vertex"].contains("screen") &&
               !j["tool"]["vertex"]["screen"].empty();
    });
    json corner;
    for (const json& h : st["tool"]["vertex"]["screen"])
        if (!h["split"].get<bool>() &&
            (corner.is_null() || h["screen"][0].get<float>() + h["screen"][1].get<float>() >
                                     corner[0].get<float>() + corner[1].get<float>() + 0.5f))
            corner = h["screen"];
    REQUIRE_FALSE(corner.is_null());
    s.move_to(corner);
    s.press();
    s.xdo("mousemove " + s.at(json{corner[0].get<float>() + 40.0f, corner[1].get<float>() + 30.0f}));
    st = s.wait("the vertex drag previewed", [](const json& j) {
        return j["tool"]["vertex"]["dragging"] == true && j["tool"]["vertex"]["moved"] == 1 &&
               j["tool"]["problem"] == "";
    });
    s.xdo("mouseup 1");
    st = s.wait("the vertex moved", [&](const json& j) { return j["undo"] == undo_draw + 3; });
    CHECK(st["undo_name"] == "Move vertices");
    CHECK(st["tool"]["vertex"]["selected"].size() == 1);
    CHECK(st["tool"]["vertex"]["dragging"] == false);
    s.key("Escape"); // drops the handle selection, then leaves the tool
    s.wait("no vertex selected", [](const json& j) { return j["tool"]["vertex"]["selected"].empty(); });
    s.key("Escape");
    s.wait("no tool", [](const json& j) { return j["tool"]["active"] == "none"; });

    // The measuring tool (M): the two grid points the box was dragged between, along x: the box's width.
    s.key("m");
    s.wait("the measuring tool", [](const json& j) { return j["tool"]["active"] == "measure"; });
    s.click(start);
    s.click(json{start[0].get<float>() + 90.0f, start[1].get<float>()});
    st = s.wait("a measurement", [](const json& j) { return j["tool"].contains("measure"); });
    // A point may snap onto the box's top (a face under the cursor) and the other onto the grid below: the
    // rise angle says so, and the run along the ground is the width.
    const double distance = st["tool"]["measure"]["distance"], rise = st["tool"]["measure"]["angle"];
    CHECK(distance * std::cos(rise * std::numbers::pi / 180.0) == doctest::Approx(width).epsilon(0.001));
    s.key("Escape");
    s.key("Escape");
    s.wait("no tool", [](const json& j) { return j["tool"]["active"] == "none"; });

    // Subtract: a second box drawn across the first, then Brush > Subtract from the menu bar.
    s.key("b");
    s.wait("the draw tool again", [](const json& j) { return j["tool"]["active"] == "draw"; });
    const json cut_from{start[0].get<float>() + 15.0f, start[1].get<float>() + 15.0f};
    s.move_to(cut_from);
    s.press();
    s.move_to(json{cut_from[0].get<float>() + 60.0f, cut_from[1].get<float>() + 40.0f});
    s.xdo("mouseup 1");
    st = s.wait("the cutter placed", [&](const json& j) { return j["undo"] == undo_draw + 4; });
    REQUIRE(st["selection"].size() == 1);
    const size_t before_cut = st["entities"];
    s.key("Escape");
    st = s.wait("the draw tool left", [](const json& j) { return j["tool"]["active"] == "none"; });
    s.click(st["spots"]["menu.brush"]);
    st = s.wait("the Brush menu", [](const json& j) { return j["spots"].contains("brush.subtract"); });
    s.click(st["spots"]["brush.subtract"]);
    st = s.wait("subtracted", [&](const json& j) { return j["undo"] == undo_draw + 5; });
    CHECK(st["undo_name"] == "Subtract brushes");
    CHECK(st["entities"].get<size_t>() > before_cut - 1); // the cutter gone, the box in pieces around it
}

TEST_CASE("editor Analyze: the bot's runs in the background, the report beside the level, stale after an "
          "edit, with real X events") {
    test::require_window_test_tools();
    test::ScratchDir dir;
    const auto level_file = test::write_file(dir / "quad_input.json", kQuadLevel);
    const auto status = dir / "status.json";
    const test::PrivateDisplay display;
    EditorProcess editor({"--level", level_file.string(), "--runs", "3", "--view", "top", "--width", "1280",
                          "--height", "720", "--status-file", status.string()},
                         {"XDG_CONFIG_HOME=" + (dir / "config").string()}, display);
    Session s(status, editor, display);
    json st =
        s.wait("the Analyze button", [](const json& j) { return j["spots"].contains("analysis_start"); });
    CHECK(st["analysis"]["runs"] == 3);
    CHECK_FALSE(st["analysis"].contains("report"));

    s.click(st["spots"]["analysis_start"]);
    st = s.wait("the report", [](const json& j) { return j["analysis"].contains("report"); });
    CHECK(st["analysis"]["running"] == false);
    CHECK(st["analysis"]["report"]["completed"] == 3);
    CHECK(st["analysis"]["report"]["requested"] == 3);
    CHECK(st["analysis"]["stale"] == false);
    const auto beside = dir / "quad_input.playtest.json";
    CHECK(st["analysis"]["file"] == beside.string());
    auto report = game::load_playtest_report(beside);
    REQUIRE_MESSAGE(report, (report ? "" : report.error().str()));
    CHECK(report->runs.size() == 3);
    CHECK(report->level_hash == st["analysis"]["report"]["level_hash"]);

    // An edit makes the report stale; undoing it makes it current again.
    s.click(st["screen"][std::to_string(kQuadRobot)]);
    s.wait("the robot selected", [](const json& j) { return j["selection"] == json::array({kQuadRobot}); });
    s.key("Right");
    st = s.wait("the report stale after a nudge",
                [](const json& j) { return j["analysis"]["stale"] == true; });
    s.key("ctrl+z");
    st =
        s.wait("current again after the undo", [](const json& j) { return j["analysis"]["stale"] == false; });
}
