// The game's view draws a far robot at a coarser level of detail than a near one (runtime/app/world_view.cpp
// through render::pick_model_level; the levels are the asset generator's, docs/assets.md), seen in the
// status file's "view draws N triangles T" of `killswitch`.
#include "runtime/screen_image.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <sstream>
#include <string>

using namespace ks;

namespace {

// A floor, a lamp and one robot `distance` units straight ahead of the player, who stands still.
std::string one_robot_at(double distance) {
    return R"({
  "format": "killswitch-level", "version": 2, "name": "One robot",
  "player_start": {"position": [0, 0, 0], "yaw": 0},
  "entities": [
    {"id": 1, "type": "floor", "name": "Ground", "position": [0, 0, 0], "props": {"size": [300, 300]}},
    {"id": 2, "type": "top_light", "name": "Lamp", "position": [0, 10, -4], "props": {"range": 40}},
    {"id": 3, "type": "robot", "name": "Robot", "position": [0, 0, )" +
           std::to_string(-distance) + R"(], "rotation": [180, 0, 0],
     "props": {"eye_radius_min": 0, "eye_radius_max": 0}}
  ]
})";
}

// The triangles the last frame drew, from the status file; -1 when the game did not say.
long long triangles_drawn(const test::ScratchDir& dir, double distance) {
    const auto level =
        test::write_file(dir / ("robot_" + std::to_string(int(distance)) + ".json"), one_robot_at(distance));
    const auto status = dir / "status.txt";
    std::filesystem::remove(status);
    const auto run = test::run_command(
        "env XDG_CONFIG_HOME=" + (dir / "config").string() + " " + (test::bin_dir() / "killswitch").string() +
        " --width 480 --height 270 --frames 12 --screen play --level " + level.string() + " --status-file " +
        status.string() + " --screenshot " + (dir / "shot.png").string());
    if (run.exit_code != 0) {
        MESSAGE(run.output);
        return -1;
    }
    std::istringstream in(test::read_file(status));
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string view, draws_word, triangles_word;
        long long draws = 0, triangles = -1;
        if (words >> view >> draws_word >> draws >> triangles_word >> triangles && view == "view" &&
            draws_word == "draws" && triangles_word == "triangles")
            return triangles;
    }
    return -1;
}

} // namespace

TEST_CASE("the game draws a far robot at a coarser level of detail than a near one") {
    REQUIRE_MESSAGE(test::have_display(), "no DISPLAY: view tests cannot run");
    test::ScratchDir dir;
    const long long near = triangles_drawn(dir, 4.0);
    const long long far = triangles_drawn(dir, 80.0);
    MESSAGE("triangles drawn: robot 4 units away " << near << ", 80 units away " << far);
    REQUIRE(near > 0);
    REQUIRE(far > 0);
    // The robot in full is 6 076 triangles, its coarsest level 1 056 (assets/models/robot.lods.json); the
    // rest of the view (floor, lamp, rifle) is the same in both.
    CHECK(near - far >= 4000);
}
