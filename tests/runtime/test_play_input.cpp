// A newcomer's play-through of `killswitch`, driven through its input the way a player drives it: click Play
// in the main menu, walk (W) over a pickup, E at a floor light and at a door, aim with the mouse, click to
// shoot a gas cylinder, Esc → pause menu → click Resume, walk to the control panel, E → the win screen.
// Twice: (a) real X events from xdotool against the window under Xvfb, waiting on the game's
// --status-file (never on the frame rate); (b) a deterministic --input-script by frame number, fed through
// the same handlers as GLFW's callbacks. Outcomes are read from the status file and the screenshot.
#include "runtime/play_session.h"
#include "runtime/screen_image.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <thread>

using namespace ks;
using ks::test::Status;
using ks::test::xdotool;

namespace {

// Polls the status file until `done` holds (or the process ends / `seconds` pass).
Status wait_for(test::GameProcess& game, const std::filesystem::path& status_file,
                const std::function<bool(const Status&)>& done, double seconds = 60.0) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    Status s;
    while (std::chrono::steady_clock::now() < end) {
        s = test::read_status(status_file);
        if (s.valid && done(s)) return s;
        if (!game.running()) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(30));
    }
    s.valid = false; // timed out: the caller reports s.text and the log
    return s;
}

// 0.0022 rad per pixel at sensitivity 1 (runtime/model/options.h), in degrees.
constexpr double kDegreesPerPixel = 0.0022 * 180.0 / 3.14159265358979;

} // namespace

TEST_CASE("play by script: menu click, walk, pickup, light, door, aim, shoot, pause/resume, win") {
    REQUIRE_MESSAGE(test::have_display(),
                    "no DISPLAY: play tests cannot run (./run.sh test runs them under xvfb-run)");
    test::ScratchDir dir;
    // The start faces 100 px of mouse look to the left of the corridor; the script's look turns it straight.
    const double start_yaw = 100.0 * kDegreesPerPixel;
    test::write_file(dir / "level.json", test::corridor_level_json(start_yaw));
    // Frames are 1/60 s (screenshot mode): 2 game steps each; walking covers 0.25 units per frame.
    test::write_file(dir / "play.txt", R"(# loading takes ~13 frames, then the main menu
20 click Play
23 look 100 0            # aim straight down the corridor (Play acts on frame 22)
24 key w down            # from z = 20: over the ammo at z = 16 ...
52 key w up              # ... and stop at z = 13, in reach of the floor light
54 key e tap             # light off
56 key w down            # on to the closed door (it stops the walk at z = 1.1)
100 key w up
102 key e tap            # the door opens in 0.5 s (30 frames)
140 mouse left click     # shoot the cylinder straight ahead through the doorway
150 key escape tap       # pause ...
160 click Resume         # ... and click Resume
170 key w down           # through the door to the control panel's reach
246 key w up
250 key e tap            # shut the simulation down: the win screen
)");
    const auto status_file = dir / "status.txt";
    const auto shot = dir / "end.png";
    auto run = test::run_command(test::scripted_env(dir) + (test::bin_dir() / "killswitch").string() +
                                 " --width 480 --height 270 --level " + (dir / "level.json").string() +
                                 " --input-script " + (dir / "play.txt").string() + " --status-file " +
                                 status_file.string() + " --screenshot " + shot.string() + " --frames 262");
    INFO(run.output);
    REQUIRE(run.exit_code == 0);
    const Status s = test::read_status(status_file);
    INFO(s.text);
    REQUIRE(s.valid);
    CHECK(s.screen == "won");
    CHECK(s.phase == "won");
    CHECK(s.pickups.at(10) == "taken");
    CHECK(s.ammo == 150 + 50 - 1); // the pickup, then one shot
    CHECK(s.shots == 1);
    CHECK(s.lights.at(11) == "off");
    CHECK(s.doors.at(12) == doctest::Approx(1.0));
    CHECK(s.cylinders.at(13) == "exploded");
    CHECK(std::abs(s.yaw) < 0.05); // the look turned the start's 12.6° exactly away
    CHECK(s.feet[2] < -15.0);      // walked through the doorway
    CHECK(std::abs(s.feet[0]) < 0.2);
    CHECK(s.health == doctest::Approx(100.0)); // the blast (radius 7) was 15 away
    CHECK(s.dropped_steps == 0);
    // The win panel is on screen: light panel, accent buttons.
    const auto img = test::load_png(shot);
    REQUIRE(img.width == 480);
    int light = 0;
    for (int y = img.height / 3; y < img.height * 2 / 3; ++y)
        for (int x = img.width / 3; x < img.width * 2 / 3; ++x) {
            const unsigned char* p = img.at(x, y);
            light += p[0] > 200 && p[1] > 205 && p[2] > 205 ? 1 : 0;
        }
    CHECK(light > img.width * img.height / 9 / 5);

    // The HUD follows: the ammo bar's orange part grows by 200/150 between the start (frame 24) and after the
    // pickup (frame 60), measured on the same script's screenshots.
    auto orange_extent = [&](int frames) {
        const auto png = dir / ("hud" + std::to_string(frames) + ".png");
        auto r = test::run_command(test::scripted_env(dir) + (test::bin_dir() / "killswitch").string() +
                                   " --width 480 --height 270 --level " + (dir / "level.json").string() +
                                   " --input-script " + (dir / "play.txt").string() + " --screenshot " +
                                   png.string() + " --frames " + std::to_string(frames));
        const auto hud = test::load_png(png);
        int widest = 0;
        // The top-left quarter holds the three bars; the ammo bar is the only orange one.
        for (int y = 0; y < hud.height / 4; ++y) {
            int first = -1, last = -1;
            for (int x = 0; x < hud.width / 2; ++x) {
                const unsigned char* p = hud.at(x, y);
                if (p[0] > 180 && p[1] > 100 && p[1] < 200 && p[2] < 90) {
                    if (first < 0) first = x;
                    last = x;
                }
            }
            if (first >= 0) widest = std::max(widest, last - first + 1);
        }
        return r.exit_code == 0 ? widest : -1;
    };
    const int at_start = orange_extent(24), after_pickup = orange_extent(60);
    MESSAGE("ammo bar orange: ", at_start, " px at 150, ", after_pickup, " px at 200");
    REQUIRE(at_start > 10);
    CHECK(static_cast<double>(after_pickup) / at_start == doctest::Approx(200.0 / 150.0).epsilon(0.06));

    // Deterministic: the same script gives the same game, step for step.
    const auto status_again = dir / "status2.txt";
    auto again = test::run_command(test::scripted_env(dir) + (test::bin_dir() / "killswitch").string() +
                                   " --width 480 --height 270 --level " + (dir / "level.json").string() +
                                   " --input-script " + (dir / "play.txt").string() + " --status-file " +
                                   status_again.string() + " --screenshot " + (dir / "end2.png").string() +
                                   " --frames 262");
    REQUIRE(again.exit_code == 0);
    CHECK(test::read_status(status_again).text == s.text);
}

TEST_CASE("play by script on levels/main.json: Play, walk to the first door, E opens it, Esc, Resume") {
    REQUIRE_MESSAGE(test::have_display(),
                    "no DISPLAY: run the window tests under xvfb-run (./run.sh test does)");
    test::ScratchDir dir;
    // --warp without --screen puts the player in room 1, 8 units before door 1, once the level has loaded.
    test::write_file(dir / "main.txt", R"(20 click Play
24 key w down
36 key w up
38 key e tap
72 key escape tap
80 click Resume
)");
    const auto status_file = dir / "status.txt";
    auto run = test::run_command(
        test::scripted_env(dir) + (test::bin_dir() / "killswitch").string() +
        " --width 320 --height 180 --level " + (test::source_dir() / "levels" / "main.json").string() +
        " --warp 0,0,-22,0,0 --input-script " + (dir / "main.txt").string() + " --status-file " +
        status_file.string() + " --screenshot " + (dir / "main.png").string() + " --frames 90");
    INFO(run.output);
    REQUIRE(run.exit_code == 0);
    const Status s = test::read_status(status_file);
    INFO(s.text);
    REQUIRE(s.valid);
    CHECK(s.screen == "playing");
    CHECK(s.captured);
    CHECK_FALSE(s.paused);
    CHECK(s.feet[2] == doctest::Approx(-25.0).epsilon(0.01)); // 12 frames of W: 3 units
    CHECK(s.doors.at(23) == doctest::Approx(1.0));            // door 1 open
    CHECK(s.doors.at(24) == doctest::Approx(0.0));            // door 2 untouched
    CHECK(s.caption == "Press E to close the door");
    CHECK(s.health == doctest::Approx(100.0));
}

TEST_CASE("play by script: a click on a button that is not there fails with the line and the screen") {
    REQUIRE_MESSAGE(test::have_display(),
                    "no DISPLAY: run the window tests under xvfb-run (./run.sh test does)");
    test::ScratchDir dir;
    test::write_file(dir / "level.json", test::corridor_level_json());
    test::write_file(dir / "bad.txt", "2 click Play\n");
    auto run = test::run_command(test::scripted_env(dir) + (test::bin_dir() / "killswitch").string() +
                                 " --width 320 --height 180 --level " + (dir / "level.json").string() +
                                 " --input-script " + (dir / "bad.txt").string() + " --screenshot " +
                                 (dir / "x.png").string() + " --frames 40");
    CHECK(run.exit_code == 1);
    CHECK(run.output.find("input script line 1") != std::string::npos);
    CHECK(run.output.find("no button 'Play' on the loading screen") != std::string::npos);
    // A malformed script is refused before the window opens.
    test::write_file(dir / "worse.txt", "10 key hyper down\n");
    auto bad =
        test::run_command((test::bin_dir() / "killswitch").string() + " --level " +
                          (dir / "level.json").string() + " --input-script " + (dir / "worse.txt").string());
    CHECK(bad.exit_code == 2);
    CHECK(bad.output.find("worse.txt:1") != std::string::npos);
    CHECK(bad.output.find("unknown key 'hyper'") != std::string::npos);
}

TEST_CASE("play with real X input (xdotool): the same play-through, waiting on the status file") {
    REQUIRE_MESSAGE(test::have_display(), "no DISPLAY: xdotool play test cannot run");
    REQUIRE_MESSAGE(test::have_xdotool(),
                    "xdotool not installed: real-input play test cannot run (run.sh installs it)");
    test::ScratchDir dir;
    test::write_file(dir / "level.json", test::corridor_level_json());
    const auto status_file = dir / "status.txt";
    // A display of its own: no other test's window can take the keyboard focus mid-walk.
    const test::PrivateDisplay display;
    const std::string where = display.name() + (display.own() ? " (own Xvfb)" : " (shared display)");
    MESSAGE("xdotool play on display ", where);
    auto xdo = [&](const std::string& args) { return xdotool(args, nullptr, display.name()); };
    test::GameProcess game({"--width", "480", "--height", "270", "--level", (dir / "level.json").string(),
                            "--status-file", status_file.string()},
                           dir / "log.txt", dir / "config", display.name());
    auto fail_info = [&](const Status& s) { return s.text + "\n--- log ---\n" + game.log(); };

    // The window, focused so that keys go to it (Xvfb has no window manager to do it).
    bool ok = false;
    // `search --sync` waits for the window forever; `timeout` bounds it if the game failed to start.
    const std::string window = test::run_command("env DISPLAY=" + display.name() +
                                                 " timeout 60 xdotool search --sync --onlyvisible --pid " +
                                                 std::to_string(game.pid()))
                                   .output;
    ok = !window.empty() && window.find_first_not_of("0123456789\n") == std::string::npos;
    INFO(game.log());
    INFO("xdotool search: ", window);
    REQUIRE(ok);
    const std::string w = window.substr(0, window.find('\n'));
    xdo("windowfocus --sync " + w);

    // Main menu: click Play where it is drawn.
    Status s = wait_for(game, status_file, [](const Status& st) { return st.buttons.count("Play") > 0; });
    INFO(fail_info(s));
    REQUIRE(s.valid);
    auto click_button = [&](const Status& st, const std::string& label) {
        const auto& b = st.buttons.at(label);
        xdo("mousemove --window " + w + " " + std::to_string(static_cast<int>((b.x0 + b.x1) / 2)) + " " +
            std::to_string(static_cast<int>((b.y0 + b.y1) / 2)));
        xdo("click 1");
    };
    click_button(s, "Play");
    s = wait_for(game, status_file, [](const Status& st) { return st.screen == "playing" && st.captured; });
    REQUIRE(s.valid);
    // Two more frames: the capture's X requests (pointer grab, raw motion) reach the server with the next
    // event poll; motion sent before that is not raw motion yet.
    const long long captured_frame = s.frame;
    s = wait_for(game, status_file, [&](const Status& st) { return st.frame >= captured_frame + 2; });
    REQUIRE(s.valid);

    // Mouse look: 100 px to the right turns right (yaw decreases) by 100 px worth, whatever the frame rate.
    const double yaw0 = s.yaw;
    xdo("mousemove_relative -- 100 0");
    s = wait_for(
        game, status_file, [&](const Status& st) { return std::abs(st.yaw - yaw0) > 1.0; }, 20.0);
    REQUIRE(s.valid);
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    s = test::read_status(status_file);
    CHECK(s.yaw - yaw0 == doctest::Approx(-100.0 * kDegreesPerPixel).epsilon(0.02));
    xdo("mousemove_relative -- -100 0");
    s = wait_for(
        game, status_file, [&](const Status& st) { return std::abs(st.yaw - yaw0) < 0.05; }, 20.0);
    REQUIRE(s.valid);

    // Walk over the ammo (held W), then on in taps until the floor light's caption shows: its reach is
    // ~4 units long, and a held key stops a frame or two after the caption shows, which at a few frames per
    // second could carry the player past it. A tap moves exactly one step (0.125 units) at any frame rate.
    xdo("keydown w");
    s = wait_for(game, status_file, [](const Status& st) { return st.pickups.at(10) == "taken"; });
    xdo("keyup w");
    CHECK(s.valid);
    CHECK(s.ammo == 200);
    auto light_caption = [](const Status& st) {
        return st.caption.find("toggle the light") != std::string::npos;
    };
    for (int tap = 0; tap < 120; ++tap) {
        s = test::read_status(status_file);
        if (s.valid && light_caption(s)) break;
        const long long frame = s.frame;
        xdo("key w");
        wait_for(
            game, status_file, [&](const Status& st) { return st.frame > frame + 1; }, 10.0);
    }
    s = test::read_status(status_file);
    INFO(s.text);
    REQUIRE(light_caption(s));
    xdo("key e");
    s = wait_for(
        game, status_file, [](const Status& st) { return st.lights.at(11) == "off"; }, 20.0);
    CHECK(s.valid);

    // On to the door; E opens it.
    xdo("keydown w");
    s = wait_for(game, status_file,
                 [](const Status& st) { return st.caption.find("open the door") != std::string::npos; });
    xdo("keyup w");
    REQUIRE(s.valid);
    xdo("key e");
    s = wait_for(game, status_file, [](const Status& st) { return st.doors.at(12) > 0.99; });
    REQUIRE(s.valid);
    CHECK(s.feet[2] > 0.9); // the closed door stopped the walk

    // Shoot the cylinder through the doorway.
    xdo("click 1");
    s = wait_for(
        game, status_file, [](const Status& st) { return st.cylinders.at(13) == "exploded"; }, 20.0);
    CHECK(s.valid);
    CHECK(s.shots == 1);
    CHECK(s.ammo == 199);

    // Esc → pause menu; click Resume.
    xdo("key Escape");
    s = wait_for(game, status_file,
                 [](const Status& st) { return st.screen == "paused" && st.buttons.count("Resume") > 0; });
    REQUIRE(s.valid);
    CHECK(s.paused);
    CHECK_FALSE(s.captured);
    click_button(s, "Resume");
    s = wait_for(game, status_file, [](const Status& st) { return st.screen == "playing" && !st.paused; });
    REQUIRE(s.valid);
    CHECK(s.shots == 1); // the click that resumed did not shoot

    // Through the door to the panel; E wins.
    xdo("keydown w");
    s = wait_for(game, status_file,
                 [](const Status& st) { return st.caption.find("shutdown") != std::string::npos; });
    xdo("keyup w");
    REQUIRE(s.valid);
    xdo("key e");
    s = wait_for(
        game, status_file, [](const Status& st) { return st.screen == "won"; }, 20.0);
    REQUIRE(s.valid);
    CHECK(s.buttons.count("Play Again") == 1);
    CHECK(s.health == doctest::Approx(100.0));
    // Quit from the menu (Main Menu, then Quit): the process ends by itself.
    click_button(s, "Main Menu");
    s = wait_for(game, status_file, [](const Status& st) { return st.buttons.count("Quit") > 0; });
    REQUIRE(s.valid);
    click_button(s, "Quit");
    CHECK(game.wait(30.0) == 0);
}

TEST_CASE("play with real X input (xdotool): shot dead by a robot, the fall, the death menu, Retry") {
    REQUIRE_MESSAGE((test::have_display() && test::have_xdotool()), "no DISPLAY or no xdotool: cannot run");
    test::ScratchDir dir;
    // One robot 10 units ahead, facing the player, that always hits and kills with one shot.
    test::write_file(dir / "duel.json", R"({
  "format": "killswitch-level", "version": 2, "name": "Duel",
  "player_start": {"position": [0, 0, 20], "yaw": 0},
  "entities": [
    {"id": 1, "type": "floor", "name": "Ground", "position": [0, 0, 0], "props": {"size": [60, 60]}},
    {"id": 2, "type": "robot", "name": "Sharpshooter", "position": [0, 0, 10], "rotation": [180, 0, 0],
     "props": {"damage": 1000, "hit_probability": 1, "cooldown": 0.2, "shooting_distance": 30,
               "eye_radius_min": 40, "eye_radius_max": 50}}
  ]
})");
    const test::PrivateDisplay display;
    auto xdo = [&](const std::string& args) { return xdotool(args, nullptr, display.name()); };
    const auto status_file = dir / "status.txt";
    test::GameProcess game({"--width", "480", "--height", "270", "--level", (dir / "duel.json").string(),
                            "--status-file", status_file.string()},
                           dir / "log.txt", dir / "config", display.name());
    const std::string window = test::run_command("env DISPLAY=" + display.name() +
                                                 " timeout 60 xdotool search --sync --onlyvisible --pid " +
                                                 std::to_string(game.pid()))
                                   .output;
    INFO(game.log());
    REQUIRE_FALSE(window.empty());
    const std::string w = window.substr(0, window.find('\n'));
    xdo("windowfocus --sync " + w);
    auto click_button = [&](const Status& st, const std::string& label) {
        const auto& b = st.buttons.at(label);
        xdo("mousemove --window " + w + " " + std::to_string(static_cast<int>((b.x0 + b.x1) / 2)) + " " +
            std::to_string(static_cast<int>((b.y0 + b.y1) / 2)));
        xdo("click 1");
    };
    Status s = wait_for(game, status_file, [](const Status& st) { return st.buttons.count("Play") > 0; });
    REQUIRE(s.valid);
    click_button(s, "Play");
    // The robot notices, raises its gun and fires: the death camera falls and rolls, then the menu.
    s = wait_for(game, status_file, [](const Status& st) { return st.screen == "dead"; });
    INFO(s.text);
    REQUIRE(s.valid);
    CHECK(s.phase == "dead");
    CHECK(s.health == doctest::Approx(0.0));
    CHECK(s.camera_roll == doctest::Approx(-90.0).epsilon(0.001));
    CHECK_FALSE(s.captured); // the mouse is given back for the menu
    REQUIRE(s.buttons.count("Retry") == 1);
    click_button(s, "Retry");
    s = wait_for(game, status_file, [](const Status& st) {
        return st.screen == "playing" && st.phase == "playing" && st.health > 99.0;
    });
    CHECK(s.valid);
    CHECK(s.camera_roll == doctest::Approx(0.0));
    CHECK(s.feet[2] == doctest::Approx(20.0).epsilon(0.01)); // back at the start
}
