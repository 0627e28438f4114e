// The Models tab in the real killswitch-editor window with real X input (xdotool under Xvfb), as a designer
// uses it: open the tab, drag a model's thumbnail onto the top view and let go (a model entity naming the
// file stands where it was let go, selected, one undo step), Ctrl+Z; then click the thumbnail and click in
// the view (click-then-place, one step). A shelf far out makes the framed top view small enough that the
// viewport draws it at a coarser level of detail, as the game would (scene.coarse_models). The editor reports
// its state in --status-file every frame; the test waits on that, never on time. Without a display or xdotool
// it fails: ./run.sh test provides both.
#include "runtime/editor_session.h"
#include "test_support.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cmath>

using namespace ks;
using nlohmann::json;
using Session = test::EditorSession;

namespace {
const char* kModelsLevel = R"({
  "format": "killswitch-level",
  "version": 2,
  "name": "Models input test",
  "player_start": {"position": [0, 0, 20], "yaw": 0},
  "next_id": 3,
  "entities": [
    {"id": 1, "type": "floor", "name": "Ground", "position": [0, 0, 0], "props": {"size": [60, 60]}},
    {"id": 2, "type": "model", "name": "Far shelf", "position": [2000, 0, 2000],
     "props": {"file": "archive_shelf.gltf", "collision": "box"}}
  ]
})";
// A shipped model (assets/models), first in the tab's list by name.
const std::string kShelf = "archive_shelf.gltf";

// The viewport's picture at (fx, fy) of its width and height, in window coordinates.
json viewport_point(const json& st, float fx, float fy) {
    const json& v = st["viewport"];
    return json{v[0].get<float>() + v[2].get<float>() * fx, v[1].get<float>() + v[3].get<float>() * fy};
}

float distance(const json& a, const json& b) {
    return std::hypot(a[0].get<float>() - b[0].get<float>(), a[1].get<float>() - b[1].get<float>());
}
} // namespace

TEST_CASE("editor models input: drag a thumbnail onto the view, undo, then click-then-place") {
    test::EditorWindow editor(kModelsLevel, {"--view", "top", "--width", "1280", "--height", "720"});
    Session& s = editor.session();
    json st = s.wait("the Models tab's button", [](const json& j) {
        return j["frame"] >= 2 && j["tab"] == "level" && test::has_spot(j, "tab.models");
    });
    // The far shelf is a few pixels across: drawn at a coarser level of detail, as the game would draw it.
    CHECK(st["scene"]["coarse_models"].get<int>() >= 1);
    s.click(st["spots"]["tab.models"]);
    st = s.wait("the shelf's thumbnail", [](const json& j) { return test::has_spot(j, "model:" + kShelf); });
    const std::size_t entities = st["entities"], undo = st["undo"];

    // Drag: from the thumbnail to a third of the way across the view, let go there.
    const json from = st["spots"]["model:" + kShelf];
    const json to = viewport_point(st, 0.35f, 0.4f);
    s.drag(from, to[0].get<float>() - from[0].get<float>(), to[1].get<float>() - from[1].get<float>(), 8);
    st = s.wait("the dropped model placed",
                [&](const json& j) { return j["entities"] == entities + 1 && j["undo"] == undo + 1; });
    REQUIRE(st["selection"].size() == 1);
    const std::string id = std::to_string(st["selection"][0].get<int>());
    REQUIRE(st["screen"].contains(id));
    CHECK(distance(st["screen"][id], to) < 40.0f); // where it was let go (snapped to the grid)
    CHECK(st["placing_model"] == "");              // a drop does not arm the click-then-place
    CHECK(st["dropping_model"] == "");

    s.key("ctrl+z");
    st = s.wait("the drop undone in one step", [&](const json& j) { return j["undo"] == undo; });
    CHECK(st["entities"] == entities);

    // Click-then-place: the thumbnail arms it, a click in the view places it.
    s.click(st["spots"]["model:" + kShelf]);
    st = s.wait("the shelf armed", [](const json& j) { return j["placing_model"] == kShelf; });
    const json there = viewport_point(st, 0.65f, 0.6f);
    s.click(there);
    st = s.wait("the clicked model placed",
                [&](const json& j) { return j["entities"] == entities + 1 && j["undo"] == undo + 1; });
    const std::string placed = std::to_string(st["selection"][0].get<int>());
    REQUIRE(st["screen"].contains(placed));
    CHECK(distance(st["screen"][placed], there) < 40.0f);
    CHECK(editor.process().alive());
}
