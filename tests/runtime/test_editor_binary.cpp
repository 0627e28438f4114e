// Drives the real killswitch-editor binary: scripted mode (no window) builds and saves a two-room level that
// the level loader, the editor's design rules and the runtime's headless mode accept; a bad
// script fails with file:line; the window mode renders the level into its viewport (under Xvfb).
#include "level/level_io.h"
#include "runtime/screen_image.h"
#include "test_support.h"

#include <doctest/doctest.h>
#include <stb_image.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <vector>

using namespace ks;

namespace {
using ks::test::distinct_colours;
using ks::test::have_display;
using ks::test::Image;
using ks::test::load_png;
// Two rooms (20 x 20 each) joined by a door in the wall between them; a robot and the control panel in the
// far room, pickups and a gas cylinder in the near one; the player starts in the near room facing the door.
const char* kTwoRoomScript = R"(# two rooms joined by a door
new
level_name Two rooms
grid 0.5 15
place floor at 0,0,0 name Ground
set size 20,40
place wall at 0,0,-20 name North wall
set size 20,16,0.5
place wall at 0,0,20 name South wall
set size 20,16,0.5
place wall at -10,0,0 yaw 90 name West wall
set size 40,16,0.5
place wall at 10,0,0 yaw 90 name East wall
set size 40,16,0.5
place wall at -6.25,0,0 name Door west side
set size 7.5,16,0.5
place wall at 6.25,0,0 name Door east side
set size 7.5,16,0.5
place wall at 0,5,0 name Lintel
set size 5,11,0.5
place door at 0,0,0 name Door
place robot at 3,0,-10 yaw 90 name Guard
place pickup at -5,0,10 name Ammo
set kind ammo
place pickup at 5,0,10 name Health
place gas_cylinder at 7,0,5
place top_light at 0,15,10
place control_panel at 0,0,-16 name Panel
player_start 0,0,15
expect count robot 1
expect count pickup 2
expect count control_panel 1
expect valid
save two_rooms.json
)";
// Builds two_rooms.json in `dir` with the editor's scripted mode.
void build_two_rooms(const std::filesystem::path& dir) {
    test::write_file(dir / "build.kss", kTwoRoomScript);
    REQUIRE(
        test::run_command(test::editor_binary() + " --script " + (dir / "build.kss").string()).exit_code ==
        0);
}
} // namespace

TEST_CASE("killswitch-editor --script builds, validates and saves a two-room level") {
    test::ScratchDir dir;
    test::write_file(dir / "build.kss", kTwoRoomScript);
    auto run = test::run_command(test::editor_binary() + " --script " + (dir / "build.kss").string());
    INFO(run.output);
    REQUIRE(run.exit_code == 0);
    const auto saved = dir / "two_rooms.json";
    REQUIRE(std::filesystem::exists(saved));

    level::LoadReport report;
    auto loaded = level::load_level_file(saved, &report);
    REQUIRE(loaded);
    CHECK(report.diagnostics.empty());
    CHECK(loaded->name == "Two rooms");
    std::map<level::EntityType, int> counts;
    for (const auto& e : loaded->entities) counts[e.type()]++;
    CHECK(counts[level::EntityType::Floor] == 1);
    CHECK(counts[level::EntityType::Wall] == 7);
    CHECK(counts[level::EntityType::Door] == 1);
    CHECK(counts[level::EntityType::Robot] == 1);
    CHECK(counts[level::EntityType::Pickup] == 2);
    CHECK(counts[level::EntityType::ControlPanel] == 1);
    CHECK(loaded->player_start.position == Vec3(0, 0, 15));
    const level::Entity* robot = nullptr;
    for (const auto& e : loaded->entities)
        if (e.type() == level::EntityType::Robot) robot = &e;
    REQUIRE(robot);
    CHECK(robot->position == Vec3(3, 0, -10));
    CHECK(robot->rotation.x == doctest::Approx(90.0f));
    bool ammo = false;
    for (const auto& e : loaded->entities)
        if (const auto* p = e.try_as<level::PickupProps>()) ammo = ammo || p->kind.value == "ammo";
    CHECK(ammo);

    // The runtime plays it: two simulated seconds, the robot awake, without a window.
    const std::string runtime = (test::bin_dir() / "killswitch").string();
    auto play = test::run_command(runtime + " --headless --level " + saved.string() + " --seconds 2");
    INFO(play.output);
    CHECK(play.exit_code == 0);
}

TEST_CASE("killswitch-editor --script reports a bad line as file:line and exits non-zero") {
    test::ScratchDir dir;
    test::write_file(dir / "bad.kss", "new\nplace robot at 0,0,0\nplace teapot at 1,2,3\n");
    auto run = test::run_command(test::editor_binary() + " --script " + (dir / "bad.kss").string());
    INFO(run.output);
    CHECK(run.exit_code != 0);
    CHECK(run.output.find("bad.kss:3") != std::string::npos);

    // A line that parses but fails when run (an expectation) names its line too, and saves nothing after it.
    test::write_file(dir / "fails.kss", "new\nplace robot at 0,0,0\nexpect count robot 2\nsave never.json\n");
    auto fails = test::run_command(test::editor_binary() + " --script " + (dir / "fails.kss").string());
    INFO(fails.output);
    CHECK(fails.exit_code != 0);
    CHECK(fails.output.find("fails.kss:3") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir / "never.json"));

    auto missing = test::run_command(test::editor_binary() + " --script " + (dir / "nope.kss").string());
    CHECK(missing.exit_code != 0);
    CHECK(missing.output.find("nope.kss") != std::string::npos);
}

TEST_CASE("killswitch-editor --help-script lists the script commands from the registry, without a display") {
    auto help =
        test::run_command("env -u DISPLAY -u WAYLAND_DISPLAY " + test::editor_binary() + " --help-script");
    INFO(help.output);
    CHECK(help.exit_code == 0);
    for (const char* form : {"place TYPE at X,Y,Z [yaw D] [name TEXT]", "expect valid", "prefab update",
                             "link SOURCE remove INDEX", "expect curve CLIP NODE CHANNEL TIME V"})
        CHECK(help.output.find(form) != std::string::npos);
    CHECK(test::run_command("env -u DISPLAY " + test::editor_binary() + " --help")
              .output.find("--help-script") != std::string::npos);
}

TEST_CASE("killswitch-editor --screenshot shows the level in its viewport between the panels") {
    REQUIRE_MESSAGE(have_display(),
                    "no DISPLAY: editor window test cannot run (./run.sh test runs it under xvfb-run)");
    test::ScratchDir dir;
    build_two_rooms(dir.path());
    auto shot = dir / "editor.png";
    auto run = test::run_command(test::editor_binary() + " --level " + (dir / "two_rooms.json").string() +
                                 " --width 1280 --height 720 --frames 4 --screenshot " + shot.string());
    INFO(run.output);
    REQUIRE(run.exit_code == 0);
    const Image img = load_png(shot);
    const int w = img.width, h = img.height;
    const auto& rgb = img.rgb;
    REQUIRE(!rgb.empty());
    CHECK(w == 1280);
    CHECK(h == 720);
    // The viewport is the middle of the window (between the outliner and the inspector, above the log):
    // the level drawn there has many colours; an empty or unrendered viewport is one flat colour.
    std::set<unsigned> colours;
    for (int y = h / 5; y < h * 3 / 5; y += 3)
        for (int x = w * 3 / 10; x < w * 7 / 10; x += 3) {
            const unsigned char* p = &rgb[(static_cast<size_t>(y) * w + x) * 3];
            colours.insert((p[0] << 16) | (p[1] << 8) | p[2]);
        }
    CHECK(colours.size() > 200);
    // And the window is more than the viewport: panel text makes the left strip non-uniform too.
    std::set<unsigned> left;
    for (int y = 40; y < h / 2; y += 2)
        for (int x = 4; x < w / 6; x += 2) {
            const unsigned char* p = &rgb[(static_cast<size_t>(y) * w + x) * 3];
            left.insert((p[0] << 16) | (p[1] << 8) | p[2]);
        }
    CHECK(left.size() > 4);
}

TEST_CASE("killswitch-editor draws the selection outline and the gizmo for a selected entity") {
    REQUIRE_MESSAGE(have_display(),
                    "no DISPLAY: editor window test cannot run (./run.sh test runs it under xvfb-run)");
    test::ScratchDir dir;
    build_two_rooms(dir.path());
    test::write_file(dir / "select.kss", "select all robot\n");
    test::write_file(dir / "none.kss", "select none\n");
    const std::string common = test::editor_binary() + " --level " + (dir / "two_rooms.json").string() +
                               " --camera 3,4,-2,0,-10 --width 1280 --height 720 --frames 3";
    auto a = test::run_command(common + " --run " + (dir / "none.kss").string() + " --screenshot " +
                               (dir / "none.png").string());
    auto b = test::run_command(common + " --run " + (dir / "select.kss").string() + " --screenshot " +
                               (dir / "selected.png").string());
    INFO(a.output);
    INFO(b.output);
    REQUIRE(a.exit_code == 0);
    REQUIRE(b.exit_code == 0);
    const Image none = load_png(dir / "none.png"), selected = load_png(dir / "selected.png");
    REQUIRE(!none.rgb.empty());
    REQUIRE(!selected.rgb.empty());
    // The outline is orange (255, 158, 26) and the gizmo's arrows pure-ish red, green and blue; the
    // viewport is x in [~240, ~960), y in [~55, ~560) at 1280 x 720.
    auto orange = [](int r, int g, int b) { return r > 220 && g > 120 && g < 190 && b < 70; };
    auto gizmo_green = [](int r, int g, int b) { return g > 190 && r < 140 && b < 110; };
    const int o0 = count_pixels(none, 250, 60, 950, 550, orange),
              o1 = count_pixels(selected, 250, 60, 950, 550, orange);
    const int g0 = count_pixels(none, 250, 60, 950, 550, gizmo_green),
              g1 = count_pixels(selected, 250, 60, 950, 550, gizmo_green);
    CHECK(o1 > o0 + 20);
    CHECK(g1 > g0 + 20);
}

TEST_CASE("killswitch-editor's top view outlines the walls, so the floor plan reads from above") {
    REQUIRE_MESSAGE(have_display(),
                    "no DISPLAY: editor window test cannot run (./run.sh test runs it under xvfb-run)");
    test::ScratchDir dir;
    build_two_rooms(dir.path());
    // The same level without its walls: the outline colour must come from the walls, not from the grid,
    // the floor or the other overlays.
    auto level = level::load_level_file(dir / "two_rooms.json");
    REQUIRE(level);
    std::erase_if(level->entities,
                  [](const level::Entity& e) { return e.type() == level::EntityType::Wall; });
    REQUIRE(level::save_level_file(dir / "no_walls.json", *level));
    auto top = [&](const char* name) {
        const auto shot = dir / (std::string(name) + ".png");
        auto run = test::run_command(
            test::editor_binary() + " --level " + (dir / (std::string(name) + ".json")).string() +
            " --view top --width 1280 --height 720 --frames 4 --screenshot " + shot.string());
        INFO(run.output);
        REQUIRE(run.exit_code == 0);
        return load_png(shot);
    };
    const Image walls = top("two_rooms"), bare = top("no_walls");
    REQUIRE(!walls.rgb.empty());
    REQUIRE(!bare.rgb.empty());
    // The wall outline is a pale blue-white (217, 230, 255); the floor's grey has b close to r.
    auto outline = [](int r, int g, int b) { return r > 170 && g > 185 && b > 225 && b > r + 15; };
    const int with_walls = count_pixels(walls, 250, 60, 950, 550, outline),
              without = count_pixels(bare, 250, 60, 950, 550, outline);
    INFO("outline pixels with walls " << with_walls << ", without " << without);
    CHECK(with_walls > 300);
    CHECK(with_walls > 10 * without);
}

TEST_CASE("killswitch-editor --dojo shows the posed robot in its preview") {
    REQUIRE_MESSAGE(have_display(),
                    "no DISPLAY: dojo window test cannot run (./run.sh test runs it under xvfb-run)");
    test::ScratchDir dir;
    auto shot = dir / "dojo.png";
    auto run =
        test::run_command(test::editor_binary() +
                          " --dojo --width 1280 --height 720 --frames 10 --screenshot " + shot.string());
    INFO(run.output);
    REQUIRE(run.exit_code == 0);
    const Image img = load_png(shot);
    REQUIRE(img.width == 1280);
    // The preview is the left half above the transport; the robot is yellow.
    auto yellow = [](int r, int g, int b) { return r > 150 && g > 110 && b < 90 && r - b > 100; };
    CHECK(count_pixels(img, 10, 60, 640, 400, yellow) > 2000);
    CHECK(run.output.find("error") == std::string::npos);
}

TEST_CASE("killswitch-editor draws a sound emitter's speaker, and its radius sphere while it is selected") {
    REQUIRE_MESSAGE(have_display(),
                    "no DISPLAY: editor window test cannot run (./run.sh test runs it under xvfb-run)");
    test::ScratchDir dir;
    build_two_rooms(dir.path());
    auto level = level::load_level_file(dir / "two_rooms.json");
    REQUIRE(level);
    REQUIRE(level::save_level_file(dir / "silent.json", *level));
    const int id = level->add(level::EntityType::Sound, Vec3(0, 3, -10), "hum").id;
    level->find(id)->as<level::SoundProps>().radius = 6;
    REQUIRE(level::save_level_file(dir / "hum.json", *level));
    test::write_file(dir / "none.kss", "select none\n");
    test::write_file(dir / "select.kss", "select " + std::to_string(id) + "\n");
    auto shot = [&](const char* level_name, const char* script) {
        const auto png = dir / (std::string(level_name) + "_" + script + ".png");
        auto run = test::run_command(
            test::editor_binary() + " --level " + (dir / level_name).string() + " --run " +
            (dir / script).string() +
            " --camera 3,4,-2,0,-10 --width 1280 --height 720 --frames 3 --screenshot " + png.string());
        INFO(run.output);
        REQUIRE(run.exit_code == 0);
        return load_png(png);
    };
    const Image silent = shot("silent.json", "none.kss"), idle = shot("hum.json", "none.kss"),
                selected = shot("hum.json", "select.kss");
    // The marker's pink (255, 115, 217), blended and anti-aliased: red and blue well above green.
    auto pink = [](int r, int g, int b) { return r > 180 && b > 140 && r > g + 60 && b > g + 40; };
    const int p0 = count_pixels(silent, 250, 60, 950, 550, pink),
              p1 = count_pixels(idle, 250, 60, 950, 550, pink),
              p2 = count_pixels(selected, 250, 60, 950, 550, pink);
    INFO("pink pixels: no emitter " << p0 << ", emitter " << p1 << ", selected " << p2);
    CHECK(p1 > p0 + 20);  // the speaker
    CHECK(p2 > p1 + 200); // and the sphere of its radius
}
