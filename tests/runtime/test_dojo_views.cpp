// What the dojo panel draws, from the real editor's screenshots (--dojo-view puts it in a state; the status
// file reports what it drew): the onion skin's tinted ghosts, the curve view's segments and key handles,
// a clip previewed on a level robot in the level viewport (preview in context), and the events' sounds
// played as the playhead passes them.
#include "level/level_io.h"
#include "runtime/screen_image.h"
#include "test_support.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <fstream>

using namespace ks;
using nlohmann::json;

namespace {
struct Shot {
    test::Image image;
    json status;
    std::string output;
};

// The editor with `args`, 8 frames, a screenshot and the status file of its last frame.
Shot editor_shot(const test::ScratchDir& dir, const std::string& name, const std::string& args) {
    const auto png = dir / (name + ".png"), status = dir / (name + ".json");
    auto run = test::run_command((test::bin_dir() / "killswitch-editor").string() + " " + args +
                                 " --width 1280 --height 720 --frames 8 --screenshot " + png.string() +
                                 " --status-file " + status.string());
    INFO(run.output);
    REQUIRE(run.exit_code == 0);
    std::ifstream in(status);
    return {test::load_png(png), json::parse(in, nullptr, false), run.output};
}

// The next key's ghost: the robot washed magenta (far from its own yellow and from the floor's grey).
bool magenta(int r, int g, int b) {
    return r > 150 && b > 110 && r - g > 70 && b - g > 40;
}
} // namespace

TEST_CASE("dojo onion skin: the keys around the playhead are drawn as tinted ghosts, only when switched on") {
    REQUIRE_MESSAGE(test::have_display(),
                    "no DISPLAY: dojo view test cannot run (./run.sh test runs it under xvfb-run)");
    test::ScratchDir dir;
    // Halfway into the shoot pose: the previous key is the rest pose, the next the raised arms.
    const Shot on = editor_shot(dir, "onion", "--dojo --dojo-view clip=shoot_pose,time=0.15,onion=1");
    const Shot off = editor_shot(dir, "plain", "--dojo --dojo-view clip=shoot_pose,time=0.15");
    REQUIRE(on.image.width == 1280);
    REQUIRE(off.image.width == 1280);
    CHECK(on.status["dojo"]["onion"] == true);
    CHECK(on.status["dojo"]["ghosts"].get<int>() > 0);
    CHECK(off.status["dojo"]["ghosts"] == 0);
    // The preview is the left half of the tab, above the transport.
    const int with = count_pixels(on.image, 10, 60, 640, 370, magenta);
    const int without = count_pixels(off.image, 10, 60, 640, 370, magenta);
    INFO("magenta pixels with the onion skin " << with << ", without " << without);
    CHECK(with > 300);
    CHECK(without < 20);
}

TEST_CASE("dojo curve view: a node's channel drawn over the clip's time, one handle per key") {
    REQUIRE_MESSAGE(test::have_display(), "no DISPLAY: dojo view test cannot run");
    test::ScratchDir dir;
    const Shot death =
        editor_shot(dir, "curve", "--dojo --dojo-view clip=death,page=curves,node=chest,channel=rot.x");
    REQUIRE(death.image.width == 1280);
    CHECK(death.status["dojo"]["page"] == "curves");
    const json& keys = death.status["dojo"]["curve_keys"];
    REQUIRE(keys.size() == 2); // death's two phases
    // The handles lie in the right half, later keys further right; chest x goes to -22.5 degrees and stays.
    CHECK(keys[0][0].get<float>() > 660.0f);
    CHECK(keys[1][0].get<float>() > keys[0][0].get<float>());
    CHECK(keys[0][1].get<float>() == doctest::Approx(keys[1][1].get<float>()).epsilon(0.01));
    // The curve in its axis' colour (x: red), in the plot.
    auto segment = [](int r, int g, int b) { return r > 200 && g > 70 && g < 110 && b > 70 && b < 110; };
    const int drawn = count_pixels(death.image, 660, 290, 1270, 510, segment);
    INFO("curve pixels: " << drawn);
    CHECK(drawn > 150);
}

TEST_CASE("dojo preview in context: a clip plays on the selected level robot, in place in the viewport") {
    REQUIRE_MESSAGE(test::have_display(), "no DISPLAY: dojo view test cannot run");
    test::ScratchDir dir;
    {
        std::ofstream script(dir / "room.kss");
        script << "new\nplace floor at 0,0,0 name Ground\nset size 30,30\nplace top_light at 0,12,4\n"
                  "place robot at 0,0,0 name Guard\nplayer_start 0,0,12\nsave room.json\n";
    }
    REQUIRE(test::run_command((test::bin_dir() / "killswitch-editor").string() + " --script " +
                              (dir / "room.kss").string())
                .exit_code == 0);
    auto level = level::load_level_file(dir / "room.json");
    REQUIRE(level);
    int robot = 0;
    for (const auto& e : level->entities)
        if (e.type() == level::EntityType::Robot) robot = e.id;
    REQUIRE(robot > 0);
    { // both shots select the robot, so only the pose differs
        std::ofstream select(dir / "select.kss");
        select << "select " << robot << "\n";
    }
    const std::string common = "--level " + (dir / "room.json").string() + " --run " +
                               (dir / "select.kss").string() +
                               " --camera 0,4,9,0,-12 --dojo-view clip=death,time=1.6";
    const Shot rest = editor_shot(dir, "rest", common);
    const Shot posed = editor_shot(dir, "posed", common + ",robot=" + std::to_string(robot));
    CHECK(rest.status["clip_preview"]["on"] == false);
    CHECK(posed.status["clip_preview"]["on"] == true);
    CHECK(posed.status["clip_preview"]["robot"] == robot);
    CHECK(posed.status["selection"] == json::array({robot}));
    REQUIRE(rest.image.width == posed.image.width);
    // The viewport (between the outliner and the inspector) above the preview bar: the dead robot lies
    // tipped over where the standing one was.
    const json& vp = posed.status["viewport"];
    const int x0 = vp[0].get<int>(), y0 = vp[1].get<int>(), x1 = x0 + vp[2].get<int>(),
              y1 = y0 + vp[3].get<int>() - 90;
    int changed = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const unsigned char *a = rest.image.at(x, y), *b = posed.image.at(x, y);
            if (std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]) > 60) ++changed;
        }
    INFO("viewport pixels changed by the preview: " << changed);
    CHECK(changed > 1500);
    CHECK(posed.output.find("error") == std::string::npos);
}

TEST_CASE("dojo event sounds: an event's sound is played as the playhead passes it") {
    REQUIRE_MESSAGE(test::have_display(), "no DISPLAY: dojo view test cannot run");
    test::ScratchDir dir;
    // shooting's muzzle_flash (sound robot_shot) sits at 0 s: it fires as soon as the clip plays. idle has no
    // events. Without a sound card the editor's player runs silently, and still counts what it was given.
    const Shot shooting = editor_shot(dir, "shooting", "--dojo --dojo-view clip=shooting");
    const Shot idle = editor_shot(dir, "idle", "--dojo --dojo-view clip=idle");
    CHECK(shooting.status["dojo"]["auditioned"].get<int>() >= 1);
    CHECK(idle.status["dojo"]["auditioned"] == 0);
}
