// The playable runtime's screens, seen through `killswitch --screen NAME --screenshot FILE`: each screen
// draws something, in its own colours where its parts should be (menu panel and accent buttons, the HUD's
// bars, the loading bar), and the Dojo's robot moves when a key plays a clip.
#include "runtime/screen_image.h"
#include "test_support.h"

#include <doctest/doctest.h>
#include <stb_image.h>

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <set>
#include <vector>

using namespace ks;

namespace {
using ks::test::distinct_colours;
using ks::test::have_display;
using ks::test::Image;
using ks::test::load_png;
using Test = std::function<bool(int r, int g, int b)>;
// Fraction of the pixels in the rectangle (fractions of the image size) that pass `test`.
double fraction(const Image& img, double x0, double y0, double x1, double y1, const Test& test) {
    int pass = 0, total = 0;
    for (int y = static_cast<int>(y0 * img.height); y < static_cast<int>(y1 * img.height); ++y)
        for (int x = static_cast<int>(x0 * img.width); x < static_cast<int>(x1 * img.width); ++x) {
            const unsigned char* p = img.at(x, y);
            pass += test(p[0], p[1], p[2]) ? 1 : 0;
            ++total;
        }
    return total ? static_cast<double>(pass) / total : 0.0;
}

const Test kPanelLight = [](int r, int g, int b) { return r > 200 && g > 205 && b > 205; };
const Test kAccentBlue = [](int r, int g, int b) { return b > 180 && g > 130 && r < 110 && b > r + 90; };
const Test kDark = [](int r, int g, int b) { return r + g + b < 200; };

struct Shot {
    int exit_code = -1;
    std::string output;
    Image image;
};

// Runs killswitch with `args` at 960x540 and loads its screenshot. The options file goes to a scratch folder.
Shot screenshot(const test::ScratchDir& dir, const std::string& name, const std::string& args,
                int frames = 3) {
    const auto file = dir / (name + ".png");
    auto run =
        test::run_command("env XDG_CONFIG_HOME=" + (dir / "config").string() + " " +
                          (test::bin_dir() / "killswitch").string() + " --width 960 --height 540 --frames " +
                          std::to_string(frames) + " --screenshot " + file.string() + " " + args);
    Shot s{run.exit_code, run.output, {}};
    if (run.exit_code == 0) s.image = load_png(file);
    return s;
}
} // namespace

TEST_CASE("game app: the menus draw a light panel with accent buttons over a darkened level") {
    REQUIRE_MESSAGE(have_display(),
                    "no DISPLAY: GL screen tests cannot run (./run.sh test runs them under xvfb-run)");
    test::ScratchDir dir;
    for (const char* screen : {"menu", "howto", "credits", "options", "pause"}) {
        CAPTURE(screen);
        Shot s = screenshot(dir, screen, std::string("--screen ") + screen);
        INFO(s.output);
        REQUIRE(s.exit_code == 0);
        REQUIRE(s.image.width == 960);
        CHECK(distinct_colours(s.image) > 20);
        // The panel body is light: a strip just inside its left edge (no buttons there).
        CHECK(fraction(s.image, 0.305, 0.45, 0.325, 0.6, kPanelLight) > 0.6);
        // Accent-blue buttons in the centre column, and the title tab's border above the panel.
        CHECK(fraction(s.image, 0.4, 0.2, 0.6, 0.95, kAccentBlue) > 0.08);
        // Outside the panel the backdrop is dark.
        CHECK(fraction(s.image, 0.0, 0.0, 0.1, 0.15, kDark) > 0.8);
    }
}

TEST_CASE("game app: the loading screen shows a part-filled bar") {
    REQUIRE_MESSAGE(have_display(), "no DISPLAY: cannot run");
    test::ScratchDir dir;
    Shot s = screenshot(dir, "loading", "--screen loading");
    INFO(s.output);
    REQUIRE(s.exit_code == 0);
    // The bar spans 440 px (720p) centred; its filled part is accent blue, the rest light grey. Find the
    // row where both show most (a panel border row is all blue, the panel body has neither).
    const int bar_w = 440 * s.image.height / 720;
    const int x0 = (s.image.width - bar_w) / 2;
    auto grey = [](int r, int g, int b) {
        return r > 185 && r < 220 && g > 190 && g < 225 && b > 190 && b < 228;
    };
    int best_blue = 0, best_grey = 0;
    for (int y = s.image.height / 3; y < s.image.height * 2 / 3; ++y) {
        int blue = 0, light = 0;
        for (int x = x0; x < x0 + bar_w; ++x) {
            const unsigned char* p = s.image.at(x, y);
            blue += kAccentBlue(p[0], p[1], p[2]) ? 1 : 0;
            light += grey(p[0], p[1], p[2]) ? 1 : 0;
        }
        if (std::min(blue, light) > std::min(best_blue, best_grey)) best_blue = blue, best_grey = light;
    }
    // Part-filled: a good share of blue and of grey on the same row.
    CHECK(best_blue > bar_w / 10);
    CHECK(best_grey > bar_w / 10);
    CHECK(best_blue + best_grey > bar_w * 8 / 10);
}

TEST_CASE("game app: the game screen shows the HUD bars in their colours and the world behind") {
    REQUIRE_MESSAGE(have_display(), "no DISPLAY: cannot run");
    test::ScratchDir dir;
    Shot s = screenshot(dir, "play", "--screen play");
    INFO(s.output);
    REQUIRE(s.exit_code == 0);
    // HUD at 540p: scale 0.75, bars 270 x 21 px from (10.5, 10.5), 7.5 px apart. Health full: green;
    // ammo 150/400: orange in its first third only.
    const double w = s.image.width, h = s.image.height;
    auto green = [](int r, int g, int b) { return g > 140 && g > r + 60 && g > b + 60; };
    auto orange = [](int r, int g, int b) { return r > 180 && g > 100 && g < 200 && b < 90; };
    CHECK(fraction(s.image, 120 / w, 12 / h, 270 / w, 30 / h, green) > 0.7);
    const double ammo_y0 = (10.5 + 2 * 28.5 + 2) / h, ammo_y1 = (10.5 + 2 * 28.5 + 19) / h;
    CHECK(fraction(s.image, 80 / w, ammo_y0, 105 / w, ammo_y1, orange) > 0.5);
    CHECK(fraction(s.image, 160 / w, ammo_y0, 270 / w, ammo_y1, orange) < 0.1);
    // The level is drawn (not a flat clear) in the middle of the screen.
    CHECK(distinct_colours(s.image) > 200);
}

TEST_CASE("game app: death and win menus") {
    REQUIRE_MESSAGE(have_display(), "no DISPLAY: cannot run");
    test::ScratchDir dir;
    Shot death = screenshot(dir, "death", "--screen death");
    INFO(death.output);
    REQUIRE(death.exit_code == 0);
    CHECK(fraction(death.image, 0.305, 0.45, 0.325, 0.6, kPanelLight) > 0.6);
    // The death screen is tinted red outside the panel.
    auto reddish = [](int r, int g, int b) { return r > g + 8 && r > b; };
    CHECK(fraction(death.image, 0.0, 0.3, 0.2, 0.7, reddish) > 0.5);
    Shot win = screenshot(dir, "win", "--screen win");
    INFO(win.output);
    REQUIRE(win.exit_code == 0);
    CHECK(fraction(win.image, 0.305, 0.45, 0.325, 0.6, kPanelLight) > 0.6);
    CHECK(fraction(win.image, 0.4, 0.6, 0.6, 0.95, kAccentBlue) > 0.1);
}

TEST_CASE("game app: the Dojo robot moves when key 2 plays the shoot pose") {
    REQUIRE_MESSAGE(have_display(), "no DISPLAY: cannot run");
    test::ScratchDir dir;
    Shot rest = screenshot(dir, "dojo_rest", "--screen dojo --dojo-time 1");
    Shot posed = screenshot(dir, "dojo_key2", "--screen dojo --dojo-key 2 --dojo-time 1");
    INFO(rest.output, posed.output);
    REQUIRE(rest.exit_code == 0);
    REQUIRE(posed.exit_code == 0);
    REQUIRE(rest.image.rgb.size() == posed.image.rgb.size());
    // Compare the scene below the legend (top right) and above the hint: pixels that changed clearly.
    int changed = 0;
    for (int y = rest.image.height / 4; y < rest.image.height * 3 / 4; ++y)
        for (int x = 0; x < rest.image.width * 2 / 3; ++x) {
            const unsigned char* a = rest.image.at(x, y);
            const unsigned char* b = posed.image.at(x, y);
            changed += (std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]) > 40) ? 1 : 0;
        }
    CHECK(changed > 500);
    // Same command twice gives the same picture (the Dojo is deterministic at a fixed time).
    Shot again = screenshot(dir, "dojo_key2b", "--screen dojo --dojo-key 2 --dojo-time 1");
    REQUIRE(again.exit_code == 0);
    int differ = 0;
    for (size_t i = 0; i < again.image.rgb.size(); ++i)
        differ += std::abs(again.image.rgb[i] - posed.image.rgb[i]) > 40 ? 1 : 0;
    CHECK(differ < 200);
}

TEST_CASE("game app: bad automation options are errors naming the option") {
    for (const char* args :
         {"--screen banana", "--warp 1,2", "--dojo-key x", "--dojo-time -3", "--seed abc"}) {
        CAPTURE(args);
        auto run = test::run_command((test::bin_dir() / "killswitch").string() + " " + args);
        CHECK(run.exit_code == 2);
        const std::string option = std::string(args).substr(0, std::string(args).find(' '));
        CHECK(run.output.find(option) != std::string::npos);
    }
    test::ScratchDir dir;
    auto bad_level = dir / "bad.json";
    auto run =
        test::run_command("sh -c 'echo \"{ nope\" > " + bad_level.string() + "; " +
                          (test::bin_dir() / "killswitch").string() + " --level " + bad_level.string() + "'");
    CHECK(run.exit_code == 2);
    CHECK(run.output.find("bad.json") != std::string::npos);
}
