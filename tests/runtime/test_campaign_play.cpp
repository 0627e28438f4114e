// The campaign, the custom level list and the level logic's HUD, played through `killswitch`'s input by
// --input-script (the same handlers as GLFW's callbacks, frame by frame, so each run is deterministic) and
// read back from its --status-file and screenshots. The test campaign (tests/data/campaign/) has two tiny
// levels with the control panel beside the player start; the first has a dormant target robot straight
// ahead and two objectives (destroy it, then use the terminal). These tests need a display: without one they
// fail (./run.sh test runs them under xvfb-run).
#include "runtime/play_session.h"
#include "runtime/screen_image.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <fstream>
#include <functional>
#include <sstream>

using namespace ks;
namespace fs = std::filesystem;

namespace {

// The lines of a status file starting with `key` and a space, without the key.
std::vector<std::string> lines(const std::string& text, const std::string& key) {
    std::vector<std::string> found;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (line.rfind(key + " ", 0) == 0) found.push_back(line.substr(key.size() + 1));
    return found;
}

std::string line(const std::string& text, const std::string& key) {
    const auto found = lines(text, key);
    return found.empty() ? "<no " + key + " line>" : found.front();
}

// A data root of the test's own (KS_DATA_DIR): the real assets, and a levels/ folder holding the test
// campaign as levels/campaign.json (so the main menu's Campaign button plays it), `levels` of it and the real
// dojo.json.
struct TestDataRoot {
    test::ScratchDir dir;
    explicit TestDataRoot(std::initializer_list<const char*> levels = {"one.json", "two.json"}) {
        fs::create_directories(dir / "data" / "levels");
        fs::create_directory_symlink(test::source_dir() / "assets", dir / "data" / "assets");
        fs::copy_file(test::data_dir() / "campaign" / "campaign.json",
                      dir / "data" / "levels" / "campaign.json");
        fs::copy_file(test::source_dir() / "levels" / "dojo.json", dir / "data" / "levels" / "dojo.json");
        for (const char* name : levels)
            fs::copy_file(test::data_dir() / "campaign" / name, dir / "data" / "levels" / name);
        fs::create_directories(dir / "xdg-data");
    }
    fs::path root() const { return dir / "data"; }
};

// "env DISPLAY=… XDG_CONFIG_HOME=… XDG_DATA_HOME=… [KS_DATA_DIR=…] killswitch --width 480 --height 270": an X
// server of the test process's own, and the options and the user's levels folder kept in scratch folders.
std::string killswitch(const test::ScratchDir& dir, const fs::path& xdg_data,
                       const std::string& data_root = "") {
    static const test::PrivateDisplay display;
    return "env DISPLAY=" + display.name() + " XDG_CONFIG_HOME=" + (dir / "config").string() +
           " XDG_DATA_HOME=" + xdg_data.string() + (data_root.empty() ? "" : " KS_DATA_DIR=" + data_root) +
           " " + (test::bin_dir() / "killswitch").string() + " --width 480 --height 270 ";
}

struct Run {
    test::CommandResult command;
    std::string status;
    test::Image image;
};

Run run_script(const std::string& command, const test::ScratchDir& dir, const std::string& name,
               const std::string& script, int frames) {
    test::write_file(dir / (name + ".txt"), script);
    const fs::path status = dir / (name + ".status"), shot = dir / (name + ".png");
    Run r;
    r.command = test::run_command(command + "--input-script " + (dir / (name + ".txt")).string() +
                                  " --status-file " + status.string() + " --screenshot " + shot.string() +
                                  " --frames " + std::to_string(frames));
    if (fs::exists(status)) r.status = test::read_file(status);
    if (r.command.exit_code == 0) r.image = test::load_png(shot);
    return r;
}

using PixelTest = std::function<bool(const unsigned char*)>;
// Pixels in the rectangle (fractions of the image) that pass `test`.
int count(const test::Image& img, double x0, double y0, double x1, double y1, const PixelTest& test) {
    int n = 0;
    for (int y = static_cast<int>(y0 * img.height); y < static_cast<int>(y1 * img.height); ++y)
        for (int x = static_cast<int>(x0 * img.width); x < static_cast<int>(x1 * img.width); ++x)
            n += test(img.at(x, y)) ? 1 : 0;
    return n;
}
bool near(const unsigned char* p, int r, int g, int b, int tolerance = 30) {
    return std::abs(p[0] - r) <= tolerance && std::abs(p[1] - g) <= tolerance &&
           std::abs(p[2] - b) <= tolerance;
}

// Level one: aim down at the target robot (56 px of mouse look is 7.1 degrees), shoot it, wait for its
// objective, then E at the terminal beside the start. `start` is the frame the level is playing from.
std::string level_one_script(int start) {
    return std::to_string(start + 10) + " look 0 56\n" + std::to_string(start + 15) + " mouse left click\n" +
           std::to_string(start + 160) + " key e tap\n";
}

} // namespace

TEST_CASE(
    "campaign by script: Campaign, level 1 won, summary with its stats, Next Level, level 2, complete") {
    REQUIRE_MESSAGE(test::have_display(), "no DISPLAY: run the GL tests under xvfb-run (./run.sh test does)");
    TestDataRoot data;
    const test::ScratchDir& dir = data.dir;
    const std::string command = killswitch(dir, dir / "xdg-data", data.root().string()) + "--level " +
                                (data.root() / "levels" / "two.json").string() + " ";
    // Loading takes ~14 frames: the menu is up by frame 20; level one plays from about frame 36.
    const std::string script =
        "20 click Campaign\n" + level_one_script(40) + "215 click Next Level\n250 key e tap\n";

    const Run summary = run_script(command, dir, "summary", script, 212);
    INFO(summary.command.output);
    INFO(summary.status);
    REQUIRE(summary.command.exit_code == 0);
    CHECK(line(summary.status, "screen") == "summary");
    CHECK(line(summary.status, "campaign") == "1 2 one.json First Light");
    // seconds, robots destroyed, robots in the level, shots, hits, title
    const auto results = lines(summary.status, "campaign_result");
    REQUIRE(results.size() == 1);
    std::istringstream result(results[0]);
    double seconds = 0;
    int killed = 0, robots = 0, shots = 0, hits = 0;
    std::string title;
    result >> seconds >> killed >> robots >> shots >> hits;
    std::getline(result >> std::ws, title);
    CHECK(seconds > 2.0);
    CHECK(seconds < 3.5);
    CHECK(killed == 1);
    CHECK(robots == 1);
    CHECK(shots == 1);
    CHECK(hits == 1);
    CHECK(title == "First Light");
    CHECK(summary.status.find("button") != std::string::npos);
    CHECK_FALSE(lines(summary.status, "button").empty());
    // On screen: the light panel with three white stat tiles and the accent Next Level button.
    REQUIRE(summary.image.width == 480);
    CHECK(count(summary.image, 0.25, 0.4, 0.75, 0.65, [](const unsigned char* p) {
              return p[0] > 248 && p[1] > 248 && p[2] > 248;
          }) > 480 * 270 / 60);
    CHECK(count(summary.image, 0.25, 0.6, 0.55, 0.8,
                [](const unsigned char* p) { return near(p, 41, 171, 226); }) > 200);

    // The first run saved its progress (level one won): without the save, Campaign starts afresh again
    // instead of offering Continue (test_play_controls.cpp covers Continue).
    std::filesystem::remove(dir / "xdg-data" / "killswitch" / "campaign_save.json");
    const Run done = run_script(command, dir, "complete", script, 262);
    INFO(done.command.output);
    INFO(done.status);
    REQUIRE(done.command.exit_code == 0);
    CHECK(line(done.status, "screen") == "campaign_complete");
    CHECK(line(done.status, "campaign") == "2 2 two.json Second Wind");
    const auto both = lines(done.status, "campaign_result");
    REQUIRE(both.size() == 2);
    CHECK(both[0] == results[0]); // the same run, step for step
    CHECK(both[1].find(" 0 0 0 0 Second Wind") != std::string::npos);
    CHECK(line(done.status, "campaign_total").find(" 1 1 1 1 Test run") != std::string::npos);
    CHECK(line(done.status, "level_name") == "Test level two");
}

TEST_CASE("campaign by script: a campaign file that does not load leaves the menu up with its error") {
    REQUIRE_MESSAGE(test::have_display(), "no DISPLAY: run the GL tests under xvfb-run (./run.sh test does)");
    TestDataRoot data;
    test::write_file(data.root() / "levels" / "campaign.json",
                     "{\"name\": \"Broken\", \"levels\": [{\"file\": \"onee.json\", \"title\": \"Typo\"}]}");
    const std::string command = killswitch(data.dir, data.dir / "xdg-data", data.root().string()) +
                                "--level " + (data.root() / "levels" / "two.json").string() + " ";
    const Run run = run_script(command, data.dir, "broken", "20 click Campaign\n", 30);
    INFO(run.command.output);
    INFO(run.status);
    REQUIRE(run.command.exit_code == 0);
    CHECK(line(run.status, "screen") == "menu");
    CHECK(line(run.status, "campaign") == "-");
    const std::string error = line(run.status, "error");
    CHECK(error.find("Could not start the campaign: ") == 0);
    CHECK(error.find("levels[0].file: level file \"onee.json\" not found") != std::string::npos);
    CHECK(error.find("did you mean \"one.json\"?") != std::string::npos);
}

TEST_CASE("campaign by script: dying offers Retry, which plays the same level of the campaign again") {
    REQUIRE_MESSAGE(test::have_display(), "no DISPLAY: run the GL tests under xvfb-run (./run.sh test does)");
    test::ScratchDir dir;
    const std::string command = killswitch(dir, dir / "xdg-data") + "--campaign " +
                                (test::data_dir() / "campaign" / "campaign.json").string() +
                                " --screen death ";
    const Run retried = run_script(command, dir, "retry", "5 click Retry\n", 40);
    INFO(retried.command.output);
    INFO(retried.status);
    REQUIRE(retried.command.exit_code == 0);
    CHECK(line(retried.status, "screen") == "playing");
    CHECK(line(retried.status, "phase") == "playing");
    CHECK(line(retried.status, "health") == "100.0");
    CHECK(line(retried.status, "campaign") == "1 2 one.json First Light");
    CHECK(lines(retried.status, "campaign_result").empty());
}

TEST_CASE(
    "custom level list: shipped and user levels by name, a broken file shows its error, a click plays") {
    REQUIRE_MESSAGE(test::have_display(), "no DISPLAY: run the GL tests under xvfb-run (./run.sh test does)");
    TestDataRoot data({"one.json"}); // campaign.json and dojo.json are there too, and not listed
    const test::ScratchDir& dir = data.dir;
    const fs::path user = dir / "xdg-data" / "killswitch" / "levels";
    fs::create_directories(user);
    std::string mine = test::read_file(test::data_dir() / "campaign" / "two.json");
    mine.replace(mine.find("Test level two"), 14, "My own level");
    test::write_file(user / "mine.json", mine);
    test::write_file(user / "broken.json",
                     "{\"format\": \"killswitch-level\", \"version\": 2, \"entities\": [\n  {\"id\": 1,}]}");
    const std::string command = killswitch(dir, dir / "xdg-data", data.root().string()) + "--level " +
                                (data.root() / "levels" / "one.json").string() + " ";

    const Run list = run_script(command, dir, "list", "20 click Custom level\u2026\n", 26);
    INFO(list.command.output);
    INFO(list.status);
    REQUIRE(list.command.exit_code == 0);
    CHECK(line(list.status, "screen") == "custom_levels");
    const auto levels = lines(list.status, "custom_level");
    const auto has = [&](const std::string& entry) {
        return std::find(levels.begin(), levels.end(), entry) != levels.end();
    };
    CHECK(levels.size() == 3);
    CHECK(has("0 ok one.json Test level one"));
    CHECK(has("1 ok mine.json My own level"));
    CHECK(has("1 error broken.json broken"));
    for (const std::string& entry : levels) {
        CHECK(entry.find("dojo.json") == std::string::npos);
        CHECK(entry.find("campaign.json") == std::string::npos);
    }
    // The broken file's row is drawn in red instead of a button; the good ones are buttons.
    CHECK_FALSE(lines(list.status, "button").empty());
    CHECK(list.status.find(" My own level\n") != std::string::npos);
    CHECK(count(list.image, 0.2, 0.2, 0.8, 0.85,
                [](const unsigned char* p) { return near(p, 180, 35, 35, 40); }) > 20);

    const Run play =
        run_script(command, dir, "play", "20 click Custom level\u2026\n30 click My own level\n", 60);
    INFO(play.command.output);
    INFO(play.status);
    REQUIRE(play.command.exit_code == 0);
    CHECK(line(play.status, "screen") == "playing");
    CHECK(line(play.status, "level_name") == "My own level");
    CHECK(line(play.status, "level_file") == (user / "mine.json").string());
    CHECK(line(play.status, "campaign") == "-");
}

TEST_CASE("HUD: the objective list, the message line, the Locked caption and the objective banner") {
    REQUIRE_MESSAGE(test::have_display(), "no DISPLAY: run the GL tests under xvfb-run (./run.sh test does)");
    test::ScratchDir dir;
    const std::string hall = (test::data_dir() / "levels" / "logic_hall.json").string();
    const fs::path status = dir / "hall.status", shot = dir / "hall.png";
    auto run = test::run_command(killswitch(dir, dir / "xdg-data") + "--level " + hall +
                                 " --screen play --frames 20 " + "--status-file " + status.string() +
                                 " --screenshot " + shot.string());
    INFO(run.output);
    REQUIRE(run.exit_code == 0);
    const std::string text = test::read_file(status);
    INFO(text);
    CHECK(lines(text, "objective") ==
          std::vector<std::string>{"0 current clear_hall Clear the hall",
                                   "1 open shutdown Shut down the simulation at the control panel"});
    CHECK(line(text, "message") == "Find the control panel");
    const test::Image hud = test::load_png(shot);
    // Top right: the dark objective panel with its accent header; upper middle: the message's accent edge.
    CHECK(count(hud, 0.6, 0.0, 1.0, 0.25, [](const unsigned char* p) { return p[0] + p[1] + p[2] < 120; }) >
          1500);
    CHECK(count(hud, 0.6, 0.0, 1.0, 0.12, [](const unsigned char* p) { return near(p, 70, 190, 240, 45); }) >
          15);
    CHECK(count(hud, 0.25, 0.1, 0.5, 0.3, [](const unsigned char* p) { return near(p, 41, 171, 226, 30); }) >
          20);
    CHECK(count(hud, 0.3, 0.12, 0.7, 0.3,
                [](const unsigned char* p) { return p[0] > 240 && p[1] > 240 && p[2] > 240; }) > 100);

    // At the locked exit the caption says so.
    const fs::path locked = dir / "locked.status";
    auto at_door = test::run_command(killswitch(dir, dir / "xdg-data") + "--level " + hall +
                                     " --screen play --warp 0,0,-25,0,0 --frames 3 --status-file " +
                                     locked.string() + " --screenshot " + (dir / "locked.png").string());
    REQUIRE(at_door.exit_code == 0);
    CHECK(line(test::read_file(locked), "caption") == "Locked");

    // The target robot shot down: its objective ticked, the next one current, the banner up.
    const std::string command = killswitch(dir, dir / "xdg-data") + "--campaign " +
                                (test::data_dir() / "campaign" / "campaign.json").string() + " ";
    const Run banner = run_script(command, dir, "banner",
                                  test::read_file(test::data_dir() / "campaign" / "play_through.txt"), 75);
    INFO(banner.command.output);
    INFO(banner.status);
    REQUIRE(banner.command.exit_code == 0);
    CHECK(lines(banner.status, "objective") ==
          std::vector<std::string>{"0 done target Destroy the target robot",
                                   "1 current shutdown Shut down the simulation at the terminal"});
    CHECK(line(banner.status, "objective_flash") == "Destroy the target robot");
    // The banner's green title across the upper middle, the ticked box's green at the top right.
    CHECK(count(banner.image, 0.25, 0.2, 0.75, 0.4,
                [](const unsigned char* p) { return near(p, 120, 235, 150, 40); }) > 60);
    CHECK(count(banner.image, 0.5, 0.0, 1.0, 0.2,
                [](const unsigned char* p) { return near(p, 40, 170, 70, 40); }) > 15);
}
