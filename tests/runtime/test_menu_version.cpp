// The main menu shows the game's version in its bottom-right corner (runtime/app/version_label.cpp): light
// text there on the menu, none on a screen without the label (How to Play), same backdrop otherwise.
#include "runtime/screen_image.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <string>

using namespace ks;

namespace {
// Fraction of light (text) pixels in the bottom-right corner, where the label sits.
double corner_light(const test::Image& img) {
    int light = 0, total = 0;
    for (int y = img.height * 90 / 100; y < img.height; ++y)
        for (int x = img.width * 80 / 100; x < img.width; ++x) {
            const unsigned char* p = img.at(x, y);
            light += (p[0] > 120 && p[1] > 120 && p[2] > 130) ? 1 : 0;
            ++total;
        }
    return static_cast<double>(light) / total;
}
} // namespace

TEST_CASE("main menu: the version in the bottom-right corner") {
    REQUIRE_MESSAGE(test::have_display(),
                    "no DISPLAY: GL screen tests cannot run (./run.sh test runs them under xvfb-run)");
    test::ScratchDir dir;
    double light[2] = {0.0, 0.0};
    const char* screens[2] = {"menu", "howto"};
    for (int i = 0; i < 2; ++i) {
        const auto file = dir / (std::string(screens[i]) + ".png");
        const auto run = test::run_command("env XDG_CONFIG_HOME=" + (dir / "config").string() + " " +
                                           (test::bin_dir() / "killswitch").string() +
                                           " --width 960 --height 540 --frames 3 --screen " + screens[i] +
                                           " --screenshot " + file.string());
        INFO(run.output);
        REQUIRE(run.exit_code == 0);
        light[i] = corner_light(test::load_png(file));
    }
    CAPTURE(light[0]);
    CAPTURE(light[1]);
    CHECK(light[0] > 0.01);  // the label's glyphs
    CHECK(light[1] < 0.002); // the bare backdrop
}
