// The controls through the real game (--input-script): menus driven by a synthetic gamepad (d-pad, A, B)
// and by the keyboard (arrows, Enter, Esc), play with the pad (stick walk, trigger shot, Start pause),
// a key rebound on Options > Controls (saved, swapped on conflict, then used in play, Reset to defaults),
// and Campaign > Continue from a saved run under XDG_DATA_HOME (a corrupt save reported and kept).
#include "runtime/play_session.h"
#include "runtime/screen_image.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <fstream>

using namespace ks;
using ks::test::Status;

namespace {
struct Run {
    test::CommandResult result;
    Status status;
};

Run play(const test::ScratchDir& dir, const std::string& script, int frames, const std::string& extra = "") {
    test::write_file(dir / "script.txt", script);
    const auto status_file = dir / "status.txt";
    std::filesystem::remove(status_file);
    Run r;
    r.result = test::run_command(test::scripted_env(dir) + (test::bin_dir() / "killswitch").string() +
                                 " --width 480 --height 270 --level " + (dir / "level.json").string() +
                                 extra + " --input-script " + (dir / "script.txt").string() +
                                 " --status-file " + status_file.string() + " --screenshot " +
                                 (dir / "shot.png").string() + " --frames " + std::to_string(frames));
    r.status = test::read_status(status_file);
    return r;
}

bool has_line(const Status& s, const std::string& line) {
    return s.text.find(line + "\n") != std::string::npos;
}
} // namespace

TEST_CASE("controls: the main menu by gamepad and by keyboard; B and Esc go back") {
    REQUIRE_MESSAGE(test::have_display(),
                    "no DISPLAY: run the window tests under xvfb-run (./run.sh test does)");
    test::ScratchDir dir;
    test::write_file(dir / "level.json", test::corridor_level_json());
    // The d-pad highlights the first button, then moves down the menu; A opens what is highlighted.
    Run r = play(dir, "20 pad ddown tap\n24 pad ddown tap\n28 pad ddown tap\n", 32);
    INFO(r.result.output);
    INFO(r.status.text);
    REQUIRE(r.result.exit_code == 0);
    CHECK(r.status.screen == "menu");
    CHECK(has_line(r.status, "pad connected 1 look 1.00 dead_zone 0.15"));
    // The first button (Campaign) has the focus from the start; three downs: Play, Dojo, Options.
    CHECK(has_line(r.status, "focus Options"));
    // A on the highlighted button, then B comes back to the menu.
    r = play(dir, "20 pad ddown tap\n24 pad ddown tap\n28 pad ddown tap\n32 pad a tap\n", 36);
    const std::string opened = r.status.screen;
    CHECK(opened == "options");
    r = play(dir, "20 pad ddown tap\n24 pad ddown tap\n28 pad ddown tap\n32 pad a tap\n36 pad b tap\n", 40);
    CHECK(r.status.screen == "menu");
    // The same with the keyboard: Down, Enter, then Esc (held a frame each: ImGui 1.86 reads keys once a
    // frame).
    const std::string keys = "20 key down down\n21 key down up\n24 key down down\n25 key down up\n"
                             "28 key down down\n29 key down up\n32 key enter down\n33 key enter up\n";
    r = play(dir, keys, 36);
    CHECK(r.status.screen == opened);
    r = play(dir, keys + "36 key escape tap\n", 40);
    CHECK(r.status.screen == "menu");
}

TEST_CASE("controls: play with a gamepad — stick walk, trigger shot, Start pauses, B resumes") {
    REQUIRE_MESSAGE(test::have_display(),
                    "no DISPLAY: run the window tests under xvfb-run (./run.sh test does)");
    test::ScratchDir dir;
    test::write_file(dir / "level.json", test::corridor_level_json());
    Run r = play(dir, R"(20 click Play
24 pad ly -1     # full forward for 20 frames: as W
44 pad ly 0
46 pad rx 1      # turn right a little
48 pad rx 0
50 pad rt 1      # one shot per pull
60 pad rt -1
62 pad start tap
)",
                 66);
    INFO(r.result.output);
    INFO(r.status.text);
    REQUIRE(r.result.exit_code == 0);
    CHECK(r.status.screen == "paused");
    CHECK(r.status.shots == 1);
    CHECK(r.status.feet[2] < 20.0 - 4.0); // 20 frames at 0.25 units per frame: about 5 units
    CHECK(r.status.yaw < -1.0);           // turned right
    r = play(dir, "20 click Play\n30 pad start tap\n40 pad b tap\n", 44);
    CHECK(r.status.screen == "playing");
    CHECK_FALSE(r.status.paused);
}

TEST_CASE("controls: Jump rebound on Options > Controls, saved, swapped on conflict, used in play, reset") {
    REQUIRE_MESSAGE(test::have_display(),
                    "no DISPLAY: run the window tests under xvfb-run (./run.sh test does)");
    test::ScratchDir dir;
    test::write_file(dir / "level.json", test::corridor_level_json());
    Run r = play(dir, R"(20 click Options
24 click Controls…
28 click bind jump 1
32 key j tap       # Jump: J
36 click bind interact 1
40 key j tap       # J onto Interact: Jump gets E (a swap)
44 click bind forward 2
48 key escape tap  # cancels the rebind, stays on the screen
)",
                 52);
    INFO(r.result.output);
    INFO(r.status.text);
    REQUIRE(r.result.exit_code == 0);
    CHECK(r.status.screen == "controls");
    CHECK(has_line(r.status, "controls waiting -"));
    CHECK(has_line(r.status, "bind jump E"));
    CHECK(has_line(r.status, "bind interact J"));
    CHECK(has_line(r.status, "bind forward W / Up"));
    const std::string saved = test::read_file(dir / "config" / "killswitch" / "options.json");
    CHECK(saved.find("\"interact\": [\n      \"J\"") != std::string::npos);
    // In play: E jumps now (the player leaves the floor), J is the one that interacts.
    r = play(dir, "20 click Play\n24 key e down\n30 key e up\n", 31);
    CHECK(r.status.feet[1] > 0.1);
    // Esc from Controls goes to Options, again to the menu; How to Play lists the new keys.
    r = play(dir, "20 click Options\n24 click Controls…\n28 key escape tap\n", 32);
    CHECK(r.status.screen == "options");
    // Reset to defaults, saved.
    r = play(
        dir,
        "20 click Options\n24 click Controls…\n28 click Reset to defaults\n32 click Back\n36 click Back\n",
        40);
    CHECK(r.status.screen == "menu");
    CHECK(has_line(r.status, "bind jump Space"));
    CHECK(test::read_file(dir / "config" / "killswitch" / "options.json").find("\"Space\"") !=
          std::string::npos);
}

TEST_CASE("controls: Campaign > Continue resumes a saved run at its next level; a corrupt save is kept") {
    REQUIRE_MESSAGE(test::have_display(),
                    "no DISPLAY: run the window tests under xvfb-run (./run.sh test does)");
    test::ScratchDir dir;
    test::write_file(dir / "level.json", test::corridor_level_json());
    test::write_file(dir / "level2.json", test::corridor_level_json());
    test::write_file(dir / "campaign.json", R"({"name": "Two rooms", "levels": [
        {"file": "level.json", "title": "First"}, {"file": "level2.json", "title": "Second"}]})");
    const auto save = dir / "data" / "killswitch" / "campaign_save.json";
    std::filesystem::create_directories(save.parent_path());
    test::write_file(save, R"({"format": "killswitch-campaign-save", "version": 1, "campaign": ")" +
                               (dir / "campaign.json").string() + R"(", "name": "Two rooms", "level_count": 2,
        "levels": [{"title": "First", "seconds": 12.5, "robots_killed": 0, "robots_total": 0, "shots": 2,
                    "hits": 0}]})");
    const std::string campaign = " --campaign " + (dir / "campaign.json").string() + " --screen menu";
    Run r = play(dir, "20 click Campaign\n", 24, campaign);
    INFO(r.result.output);
    INFO(r.status.text);
    REQUIRE(r.result.exit_code == 0);
    CHECK(r.status.screen == "campaign_choice");
    r = play(dir, "20 click Campaign\n24 click Continue: level 2\n", 60, campaign);
    CHECK(r.status.screen == "playing");
    CHECK(r.status.text.find("campaign 2 2 level2.json Second") != std::string::npos);
    CHECK(r.status.text.find("campaign_result 12.50 0 0 2 0 First") != std::string::npos);
    // New campaign: level 1, and the save says nothing is won yet.
    r = play(dir, "20 click Campaign\n24 click New campaign\n", 60, campaign);
    CHECK(r.status.text.find("campaign 1 2 level.json First") != std::string::npos);
    CHECK(r.status.text.find("campaign_save 0 2") != std::string::npos);
    // A corrupt save: one warning naming the file; Campaign starts a new run; the bad file is kept aside.
    test::write_file(save, "{ \"format\": \"killswitch-campaign-save\", \"levels\": [");
    r = play(dir, "20 click Campaign\n", 60, campaign);
    CHECK(r.result.output.find(save.string() + ":1:") != std::string::npos);
    CHECK(r.result.output.find("file ends early (truncated?)") != std::string::npos);
    CHECK(r.status.text.find("campaign 1 2") != std::string::npos);
    CHECK(test::read_file(save.string() + ".unreadable") ==
          "{ \"format\": \"killswitch-campaign-save\", \"levels\": [");
    CHECK(r.status.text.find("campaign_save 0 2") != std::string::npos);
}
