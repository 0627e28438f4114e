// The player start, the texture browser and brush faces in the real killswitch-editor window, with real X
// input (xdotool under Xvfb), as a designer uses them: click the player start in the top view, drag it with
// the gizmo's x arrow and turn it with the yaw ring (each drag one undo step), Ctrl+Z; open the texture
// browser from the selected wall's texture field, search, click a thumbnail (the wall's texture changes, one
// undo step), close it, Ctrl+Z; type into the wall's size (Enter sets and leaves the field, Esc drops only
// the typing, Tab moves on, nothing logged while typing), Ctrl+D, and quick taps of Ctrl+D, an arrow, E and
// Delete; Ctrl+Shift+click a brush's top face, Fit (one step), Ctrl+Z, drag its texture (one step), Ctrl+Z.
// The editor reports its state in --status-file every frame; the test waits on that, never on time. Without
// a display or xdotool these tests fail: ./run.sh test provides both.
#include "level/level_io.h"
#include "runtime/editor_session.h"
#include "runtime/screen_image.h"
#include "test_support.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

using namespace ks;
using nlohmann::json;
using test::EditorProcess;
using Session = test::EditorSession;

namespace {
// A floor, a wall of concrete to the north, the control panel; the player start in the open, facing -z.
const char* kObjectsLevel = R"({
  "format": "killswitch-level",
  "version": 2,
  "name": "Objects input test",
  "player_start": {"position": [6, 0, 8], "yaw": 0},
  "next_id": 4,
  "entities": [
    {"id": 1, "type": "floor", "name": "Ground", "position": [0, 0, 0], "props": {"size": [40, 40]}},
    {"id": 2, "type": "wall", "name": "North", "position": [0, 0, -12], "props": {"size": [20, 16, 0.5]}},
    {"id": 3, "type": "control_panel", "position": [-10, 0, -6]}
  ]
})";
constexpr int kObjectsWall = 2;

Vec3 start_position(const json& status) {
    const json& p = status["player_start"]["position"];
    return {p[0].get<float>(), p[1].get<float>(), p[2].get<float>()};
}
} // namespace

TEST_CASE("editor objects input: click the player start in the top view, drag it and turn it with the gizmo, "
          "undo with real X events") {
    test::require_window_test_tools();
    test::ScratchDir dir;
    const auto level_file = test::write_file(dir / "objects_input.json", kObjectsLevel);
    const auto status = dir / "status.json";
    const test::PrivateDisplay display;
    EditorProcess editor({"--level", level_file.string(), "--view", "top", "--width", "1280", "--height",
                          "720", "--status-file", status.string()},
                         {"XDG_CONFIG_HOME=" + (dir / "config").string()}, display);
    Session s(status, editor, display);
    json st = s.wait("the player start on screen", [](const json& j) {
        return j["frame"] >= 2 && j["view"] == "Top" && j["player_start"].contains("screen");
    });
    CHECK(st["player_start"]["selected"] == false);

    s.click(st["player_start"]["screen"]);
    st = s.wait("the player start selected by a click", [](const json& j) {
        return j["player_start"]["selected"] == true && j.contains("gizmo_handles") &&
               j["gizmo_handles"].contains("x");
    });
    CHECK(st["selection"] == json::array({-1}));
    const size_t undo_before = st["undo"];

    // The x arrow, 90 pixels to the right: east, snapped to the 1-unit grid, one step.
    s.drag(st["gizmo_handles"]["x"], 90.0f, 0.0f, 3);
    st = s.wait("the move drag ended",
                [&](const json& j) { return j["dragging"] == false && j["undo"] == undo_before + 1; });
    const Vec3 moved = start_position(st);
    CHECK(moved.x > 6.0f + 3.0f);
    CHECK(moved.x == std::round(moved.x));
    CHECK(moved.z == 8.0f);
    CHECK(st["player_start"]["selected"] == true);

    // E: the rotate gizmo, the yaw ring only (the player start turns about y). Its start point lies south
    // of the centre in the top view (+z); dragging it to the east point is a quarter turn counterclockwise
    // seen from above: yaw +90.
    s.key("e");
    st = s.wait("the yaw ring", [](const json& j) {
        return j["gizmo"] == "Rotate" && j.contains("gizmo_handles") && j["gizmo_handles"].contains("ring_y");
    });
    CHECK_FALSE(st["gizmo_handles"].contains("ring_x"));
    CHECK_FALSE(st["gizmo_handles"].contains("ring_z"));
    const json ring = st["gizmo_handles"]["ring_y"], centre = st["gizmo_handles"]["centre"];
    const float r = ring[1].get<float>() - centre[1].get<float>();
    REQUIRE(r > 20.0f);
    s.drag(ring, r, -r, 6);
    st = s.wait("the turn ended",
                [&](const json& j) { return j["dragging"] == false && j["undo"] == undo_before + 2; });
    CHECK(st["player_start"]["yaw"].get<float>() == doctest::Approx(90.0f));
    CHECK(start_position(st) == moved); // alone, it turns in place

    s.key("ctrl+z");
    st = s.wait("the turn undone", [&](const json& j) { return j["undo"] == undo_before + 1; });
    CHECK(st["player_start"]["yaw"].get<float>() == 0.0f);
    s.key("ctrl+z");
    st = s.wait("the move undone", [&](const json& j) { return j["undo"] == undo_before; });
    CHECK(start_position(st) == Vec3(6, 0, 8));
    s.key("ctrl+s");
    s.wait("saved", [](const json& j) { return j["dirty"] == false; });
    auto saved = level::load_level_file(level_file);
    REQUIRE(saved);
    CHECK(saved->player_start == level::PlayerStart{Vec3(6, 0, 8), 0.0f});
}

namespace {
// The typed fields and quick taps on the selected wall (the texture test's editor, after it saved).
void typed_fields_and_taps(Session& s) {
    json st = s.wait("the wall's fields", [](const json& j) {
        return j["frame"] >= 2 && j.contains("primary") && j["spots"].contains("field.size.1") &&
               j["spots"].contains("field.rotation.0") && j["spots"].contains("inspector.duplicate");
    });
    CHECK(st["primary"]["fields"]["size"] == "20,16,0.5");
    const size_t undo_before = st["undo"], errors_before = st["error_lines"];
    // Ctrl+click types into a number (its text selected, so typing replaces it). Ctrl is held until a
    // frame has seen it, and let go once the field is being typed into.
    auto type_into = [&](const std::string& spot) {
        s.focus();
        s.move_to(s.last()["spots"][spot]);
        s.xdo("keydown ctrl");
        s.wait("Ctrl seen", [](const json& j) { return j["input"]["ctrl"] == true; });
        s.xdo("click 1");
        s.wait("typing into the field", [](const json& j) { return j["input"]["text_input"] == true; });
        s.xdo("keyup ctrl");
        return s.wait("Ctrl let go", [](const json& j) { return j["input"]["ctrl"] == false; });
    };

    // Enter, Esc and Tab as quick taps (press and release back to back): seen for one frame, never held
    // long enough for ImGui's key repeat to Tab twice on a slow frame.
    auto tap = [&](const std::string& key) {
        s.focus();
        s.xdo("key --delay 0 " + key);
    };

    // The height to "0.5": on the way "0" and "0." are below the field's 0.01 (and were set, refused and
    // logged red at every key); nothing is set or logged until Enter.
    type_into("field.size.1");
    s.type("0.5");
    st = s.frames(2);
    CHECK(st["primary"]["fields"]["size"] == "20,16,0.5");
    CHECK(st["undo"] == undo_before);
    tap("Return");
    st = s.wait("Enter set it and left the field", [](const json& j) {
        return j["primary"]["fields"]["size"] == "20,0.5,0.5" && j["input"]["text_input"] == false &&
               j["input"]["active_item"] == false;
    });
    CHECK(st["undo"] == undo_before + 1);
    CHECK(st["error_lines"] == errors_before);

    // Straight after Enter, a quick Ctrl+D tap (press and release back to back, between two frames)
    // duplicates: the copy is one grid step along x, selected.
    s.focus();
    s.xdo("key --delay 0 ctrl+d");
    st =
        s.wait("the copy", [&](const json& j) { return j["entities"] == 4 && j["undo"] == undo_before + 2; });
    const int copy = st["primary"]["id"];
    CHECK(copy != kObjectsWall);
    CHECK(st["primary"]["position"] == json::array({1, 0, -12}));
    CHECK(st["primary"]["fields"]["size"] == "20,0.5,0.5");

    // Esc drops what is being typed, and only that: the value set before stays, and so does the selection.
    type_into("field.size.1");
    s.type("7");
    tap("Escape");
    st = s.wait("Esc left the field", [](const json& j) { return j["input"]["text_input"] == false; });
    CHECK(st["primary"]["fields"]["size"] == "20,0.5,0.5");
    CHECK(st["undo"] == undo_before + 2);
    CHECK(st["selection"] == json::array({copy}));

    // Tab sets the width and moves on to the height; Enter sets the height.
    type_into("field.size.0");
    s.type("3");
    tap("Tab");
    st = s.wait("the width set, typing the height", [](const json& j) {
        return j["primary"]["fields"]["size"] == "3,0.5,0.5" && j["input"]["text_input"] == true;
    });
    s.type("2");
    tap("Return");
    st = s.wait("the height set", [](const json& j) {
        return j["primary"]["fields"]["size"] == "3,2,0.5" && j["input"]["text_input"] == false;
    });
    CHECK(st["undo"] == undo_before + 4);
    CHECK(st["error_lines"] == errors_before);

    // Quick taps: two of the right arrow 40 ms apart (often within one frame) nudge twice, E
    // switches to the rotate gizmo, Delete deletes.
    s.focus();
    s.xdo("key --delay 40 Right Right"); // 0 ms apart, GLFW takes the second for key repeat
    s.wait("nudged twice", [](const json& j) {
        return j["primary"]["position"] == json::array({3, 0, -12});
    });
    s.xdo("key --delay 0 e");
    s.wait("rotate mode", [](const json& j) { return j["gizmo"] == "Rotate"; });
    s.xdo("key --delay 0 Delete");
    st = s.wait("deleted", [](const json& j) { return j["entities"] == 3; });
    CHECK(st["undo"] == undo_before + 6);
}
} // namespace

// One editor with the wall selected for both the texture browser and the typed fields (one setup, one
// launch): the typed fields run on the level the texture part saved (the wall is wood, still selected).
TEST_CASE(
    "editor objects input: the wall's texture from the browser (search, click a thumbnail, close, undo, "
    "save); typed fields (Enter sets and leaves the field, Esc cancels only the typing, Tab moves on, no "
    "errors while typing), Ctrl+D's copy one grid step along x, quick taps never lost") {
    test::require_window_test_tools();
    test::ScratchDir dir;
    const auto level_file = test::write_file(dir / "objects_input.json", kObjectsLevel);
    std::ofstream(dir / "select.kss") << "select " << kObjectsWall << "\n";
    const auto status = dir / "status.json";
    const test::PrivateDisplay display;
    EditorProcess editor({"--level", level_file.string(), "--run", (dir / "select.kss").string(), "--width",
                          "1280", "--height", "720", "--status-file", status.string()},
                         {"XDG_CONFIG_HOME=" + (dir / "config").string()}, display);
    Session s(status, editor, display);
    json st = s.wait("the wall's texture field", [](const json& j) {
        return j["frame"] >= 2 && j.contains("primary") && j["spots"].contains("inspector.texture");
    });
    CHECK(st["primary"]["texture"] == "concrete");
    CHECK(st["texture_browser"]["open"] == false);
    const size_t undo_before = st["undo"];

    s.click(st["spots"]["inspector.texture"]);
    st = s.wait("the browser open with every material", [](const json& j) {
        return j["texture_browser"]["open"] == true && j["spots"].contains("texture:concrete") &&
               j["texture_browser"]["shown"].size() >= 6;
    });
    const auto all = st["texture_browser"]["shown"].get<std::vector<std::string>>();
    CHECK(std::find(all.begin(), all.end(), "wood") != all.end());

    s.click(st["spots"]["texture_search"]);
    s.type("wo");
    st = s.wait("the search narrowed to wood", [](const json& j) {
        return j["texture_browser"]["query"] == "wo" &&
               j["texture_browser"]["shown"] == json::array({"wood"}) && j["spots"].contains("texture:wood");
    });
    CHECK_FALSE(st["spots"].contains("texture:concrete"));

    s.click(st["spots"]["texture:wood"]);
    st = s.wait("the wall is wood", [](const json& j) { return j["primary"]["texture"] == "wood"; });
    CHECK(st["undo"] == undo_before + 1);
    CHECK(st["texture_browser"]["open"] == true); // stays open to try another

    s.click(st["spots"]["texture_close"]);
    st = s.wait("the browser closed", [](const json& j) { return j["texture_browser"]["open"] == false; });
    s.key("ctrl+z");
    st = s.wait("the texture undone", [](const json& j) { return j["primary"]["texture"] == "concrete"; });
    CHECK(st["undo"] == undo_before);
    s.key("ctrl+y");
    s.wait("the texture redone", [](const json& j) { return j["primary"]["texture"] == "wood"; });
    s.key("ctrl+s");
    s.wait("saved", [](const json& j) { return j["dirty"] == false; });
    auto saved = level::load_level_file(level_file);
    REQUIRE(saved);
    CHECK(saved->find(kObjectsWall)->as<level::WallProps>().texture == "wood");
    typed_fields_and_taps(s);
}

TEST_CASE("editor objects input: Ctrl+Shift+click picks a brush's top face in the top view, Fit fits the "
          "texture, Ctrl+Z undoes it with the face still selected; a drag moves the texture, one step") {
    test::require_window_test_tools();
    test::ScratchDir dir;
    const auto level_file = test::write_file(dir / "faces_input.json", R"({
  "format": "killswitch-level",
  "version": 2,
  "name": "Faces input test",
  "player_start": {"position": [8, 0, 8], "yaw": 0},
  "next_id": 2,
  "entities": [{"id": 1, "type": "brush", "name": "Block", "position": [0, 0, 0]}]
})");
    const auto status = dir / "status.json";
    const test::PrivateDisplay display;
    EditorProcess editor({"--level", level_file.string(), "--view", "top", "--width", "1280", "--height",
                          "720", "--status-file", status.string()},
                         {"XDG_CONFIG_HOME=" + (dir / "config").string()}, display);
    Session s(status, editor, display);
    json st = s.wait("the brush on screen", [](const json& j) {
        return j["frame"] >= 2 && j["view"] == "Top" && j["screen"].contains("1");
    });
    CHECK(st["faces"]["selected"].empty());
    s.focus();
    s.xdo("keydown ctrl+shift");
    s.wait("Ctrl+Shift seen",
           [](const json& j) { return j["input"]["ctrl"] == true && j["input"]["shift"] == true; });
    s.click(st["screen"]["1"]);
    s.frames(2);
    s.xdo("keyup ctrl+shift");
    st = s.wait("the top face picked", [](const json& j) {
        return j["faces"]["selected"].size() == 1 && j["spots"].contains("face.fit");
    });
    CHECK(st["faces"]["selected"][0]["entity"] == 1);
    CHECK(st["selection"].empty()); // faces are picked beside the entity selection
    const size_t undo_before = st["undo"];

    s.click(st["spots"]["face.fit"]);
    st = s.wait("the texture fitted", [&](const json& j) { return j["undo"] == undo_before + 1; });
    CHECK(st["faces"]["selected"][0]["scale"] == json::array({4.0, 4.0})); // the default brush's 4 x 4 top
    s.key("ctrl+z");
    st = s.wait("the fit undone", [&](const json& j) { return j["undo"] == undo_before; });
    CHECK(st["faces"]["selected"].size() == 1);
    CHECK(st["faces"]["selected"][0]["scale"] == json::array({1.0, 1.0}));

    // A drag on the selected face moves its texture live (Snap on: whole grid steps), one step; Ctrl+Z.
    s.drag(st["screen"]["1"], 120.0f, 0.0f, 6);
    st = s.wait("the texture dragged", [&](const json& j) {
        return j["undo"] == undo_before + 1 && j["texture_drag"] == "" &&
               j["faces"]["selected"][0]["offset"] != json::array({0.0, 0.0});
    });
    const double shifted = st["faces"]["selected"][0]["offset"][0].get<double>();
    CHECK(shifted == std::round(shifted));
    CHECK(st["selection"].empty()); // a drag on a selected face is not a box select
    s.key("ctrl+z");
    st = s.wait("the drag undone", [&](const json& j) { return j["undo"] == undo_before; });
    CHECK(st["faces"]["selected"][0]["offset"] == json::array({0.0, 0.0}));
}
