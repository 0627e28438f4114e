// What the player sees, checked on screenshots of `killswitch`: the death fall rolls the camera onto the
// soldier's left side (the ground fills the left of the picture), and the game view and the render-only
// view (--camera, render::LevelScene) draw a robot facing the same way.
#include "runtime/play_session.h"
#include "runtime/screen_image.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <cmath>
#include <fstream>

using namespace ks;

namespace {

test::Image shoot(const test::ScratchDir& dir, const std::string& name, const std::string& args,
                  std::string* output = nullptr) {
    const auto file = dir / (name + ".png");
    auto run = test::run_command(
        "env XDG_CONFIG_HOME=" + (dir / "config").string() + " " + (test::bin_dir() / "killswitch").string() +
        " --width 480 --height 270 --frames 3 --screenshot " + file.string() + " " + args);
    if (output) *output = run.output;
    if (run.exit_code != 0) {
        MESSAGE(run.output);
        return {};
    }
    return test::load_png(file);
}

double mean_luma(const test::Image& img, double x0, double x1, double y0, double y1) {
    double sum = 0.0;
    long n = 0;
    for (int y = static_cast<int>(y0 * img.height); y < static_cast<int>(y1 * img.height); ++y)
        for (int x = static_cast<int>(x0 * img.width); x < static_cast<int>(x1 * img.width); ++x) {
            const unsigned char* p = img.at(x, y);
            sum += 0.3 * p[0] + 0.59 * p[1] + 0.11 * p[2];
            ++n;
        }
    return n ? sum / n : 0.0;
}

// Mean absolute difference of two same-sized images over a rectangle (fractions of the size).
double difference(const test::Image& a, const test::Image& b, double x0, double x1, double y0, double y1) {
    double sum = 0.0;
    long n = 0;
    for (int y = static_cast<int>(y0 * a.height); y < static_cast<int>(y1 * a.height); ++y)
        for (int x = static_cast<int>(x0 * a.width); x < static_cast<int>(x1 * a.width); ++x) {
            for (int c = 0; c < 3; ++c) sum += std::abs(int(a.at(x, y)[c]) - int(b.at(x, y)[c]));
            ++n;
        }
    return n ? sum / n : 0.0;
}

// An open floor under one lamp, nothing else: after the fall the only ground in view is at one side.
const char* kOpenFloor = R"({
  "format": "killswitch-level", "version": 2, "name": "Open floor",
  "player_start": {"position": [0, 0, 0], "yaw": 0},
  "entities": [
    {"id": 1, "type": "floor", "name": "Ground", "position": [0, 0, 0], "props": {"size": [400, 400]}},
    {"id": 2, "type": "top_light", "name": "Lamp", "position": [-4, 12, 0], "props": {"range": 60}}
  ]
})";

} // namespace

TEST_CASE("death camera: the fall rolls the view onto the left side (ground on the left of the picture)") {
    REQUIRE_MESSAGE(test::have_display(), "no DISPLAY: view tests cannot run");
    test::ScratchDir dir;
    test::write_file(dir / "open.json", kOpenFloor);
    const auto status = dir / "status.txt";
    // Standing, looking 45° up (where the fall's pitch ends): only sky on both sides.
    const auto standing = shoot(
        dir, "standing", "--level " + (dir / "open.json").string() + " --warp 0,0,0,0,45 --screen play");
    std::string out;
    const auto dead = shoot(
        dir, "dead",
        "--level " + (dir / "open.json").string() + " --screen death --status-file " + status.string(), &out);
    INFO(out);
    REQUIRE(standing.width == 480);
    REQUIRE(dead.width == 480);
    const auto s = test::read_status(status);
    INFO(s.text);
    CHECK(s.screen == "dead");
    CHECK(s.camera_roll == doctest::Approx(-90.0).epsilon(0.001));
    // Rolled onto the left side: the lit floor fills the left edge, the right edge is sky (and the lamp,
    // which is up, is at the top right). Upright at the same pitch the two edges are both sky. Rows 30–70 %
    // avoid the HUD (top left) and the rifle (bottom right) in the standing picture, and the lamp.
    const double dead_left = mean_luma(dead, 0.0, 0.08, 0.3, 0.7),
                 dead_right = mean_luma(dead, 0.92, 1.0, 0.3, 0.7);
    const double standing_left = mean_luma(standing, 0.0, 0.08, 0.3, 0.7),
                 standing_right = mean_luma(standing, 0.92, 1.0, 0.3, 0.7);
    MESSAGE("edge brightness: dead left ", dead_left, " right ", dead_right, "; standing left ",
            standing_left, " right ", standing_right);
    CHECK(dead_left > dead_right + 10.0);
    CHECK(std::abs(standing_left - standing_right) < 3.0);
}

TEST_CASE("robot facing: the game view and the render-only view draw a level's robot the same way") {
    REQUIRE_MESSAGE(test::have_display(), "no DISPLAY: view tests cannot run");
    test::ScratchDir dir;
    // Both views at 60° field of view (the render-only view's), eye at (0, 3, 7), looking 12° down at a
    // robot that faces the camera (yaw 180 faces +z). It does not notice the player (eye radii 0).
    std::filesystem::create_directories(dir / "config" / "killswitch");
    test::write_file(dir / "config" / "killswitch" / "options.json",
                     R"({"format": "killswitch-options", "version": 1, "fov_degrees": 60})");
    auto level = [&](const char* name, int yaw) {
        const auto path = dir / name;
        test::write_file(path, std::string(R"({
  "format": "killswitch-level", "version": 2, "name": "One robot",
  "player_start": {"position": [0, 0, 7], "yaw": 0},
  "entities": [
    {"id": 1, "type": "floor", "name": "Ground", "position": [0, 0, 0], "props": {"size": [60, 60]}},
    {"id": 2, "type": "top_light", "name": "Lamp", "position": [0, 10, 4], "props": {"range": 40}},
    {"id": 3, "type": "robot", "name": "Robot", "position": [0, 0, 0], "rotation": [)") +
                                   std::to_string(yaw) + R"(, 0, 0],
     "props": {"eye_radius_min": 0, "eye_radius_max": 0}}
  ]
})");
        return path.string();
    };
    const auto facing = level("facing.json", 180);
    const auto turned = level("turned.json", 90);
    const auto render_facing =
        shoot(dir, "render_facing", "--level " + facing + " --camera 0,3,7,0,-12 --no-hud");
    const auto render_turned =
        shoot(dir, "render_turned", "--level " + turned + " --camera 0,3,7,0,-12 --no-hud");
    const auto game_facing =
        shoot(dir, "game_facing", "--level " + facing + " --screen play --warp 0,0,7,0,-12");
    const auto game_turned =
        shoot(dir, "game_turned", "--level " + turned + " --screen play --warp 0,0,7,0,-12");
    REQUIRE(render_facing.width == 480);
    REQUIRE(render_turned.width == 480);
    REQUIRE(game_facing.width == 480);
    REQUIRE(game_turned.width == 480);
    // The robot's part of the picture (the rifle is lower right, the HUD at the bottom, in the game view).
    auto robot_area = [](const test::Image& a, const test::Image& b) {
        return difference(a, b, 0.38, 0.62, 0.15, 0.75);
    };
    const double same_yaw_facing = robot_area(render_facing, game_facing);
    const double same_yaw_turned = robot_area(render_turned, game_turned);
    const double quarter_turn = robot_area(render_facing, render_turned); // what a 90° mismatch looks like
    MESSAGE("robot area difference: facing ", same_yaw_facing, ", turned ", same_yaw_turned,
            ", a quarter turn ", quarter_turn);
    CHECK(quarter_turn > 2.0);
    CHECK(same_yaw_facing < 0.6 * quarter_turn); // measured ~0.4: the game poses its robots (idle clip)
    CHECK(same_yaw_turned < 0.6 * quarter_turn);
}
