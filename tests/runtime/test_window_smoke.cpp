// GL smoke tests: start the real binaries under the test's display (Xvfb in CI) and look at what they draw.
#include "runtime/screen_image.h"
#include "test_support.h"

#include <doctest/doctest.h>
#include <stb_image.h>

#include <cstdlib>
#include <set>
#include <vector>

using namespace ks;

namespace {
using ks::test::distinct_colours;
using ks::test::have_display;
using ks::test::Image;
using ks::test::load_png;
} // namespace

TEST_CASE("killswitch --screenshot renders a non-blank frame of the requested size") {
    REQUIRE_MESSAGE(have_display(),
                    "no DISPLAY: GL smoke test cannot run (./run.sh test runs it under xvfb-run)");
    test::ScratchDir dir;
    auto shot = dir / "shot.png";
    auto run = test::run_command((test::bin_dir() / "killswitch").string() +
                                 " --width 640 --height 360 --frames 3 --screenshot " + shot.string());
    INFO(run.output);
    REQUIRE(run.exit_code == 0);
    Image img = load_png(shot);
    REQUIRE(img.width == 640);
    REQUIRE(img.height == 360);
    CHECK(distinct_colours(img) > 8);
}

TEST_CASE("killswitch-editor --screenshot renders a frame") {
    REQUIRE_MESSAGE(have_display(), "no DISPLAY: GL smoke test cannot run");
    test::ScratchDir dir;
    auto shot = dir / "editor.png";
    auto run = test::run_command((test::bin_dir() / "killswitch-editor").string() +
                                 " --width 640 --height 360 --frames 3 --screenshot " + shot.string());
    INFO(run.output);
    REQUIRE(run.exit_code == 0);
    Image img = load_png(shot);
    CHECK(img.width == 640);
}

TEST_CASE("without a display the binaries explain how to use xvfb-run and exit non-zero") {
    for (const char* exe : {"killswitch", "killswitch-editor"}) {
        auto run = test::run_command("env -u DISPLAY -u WAYLAND_DISPLAY " + (test::bin_dir() / exe).string());
        INFO(exe, ": ", run.output);
        CHECK(run.exit_code != 0);
        CHECK(run.exit_code != 139); // not a crash
        CHECK(run.output.find("xvfb-run") != std::string::npos);
    }
}

TEST_CASE("bad command-line options are reported, not ignored") {
    auto run = test::run_command((test::bin_dir() / "killswitch").string() + " --frames banana");
    CHECK(run.exit_code == 2);
    CHECK(run.output.find("--frames") != std::string::npos);
    auto typo = test::run_command((test::bin_dir() / "killswitch").string() + " --levle x.json");
    CHECK(typo.exit_code == 2);
    CHECK(typo.output.find("--levle") != std::string::npos);
}

TEST_CASE("--help describes every mode and exits 0 without a display") {
    const std::string exe = (test::bin_dir() / "killswitch").string();
    auto help = test::run_command("env -u DISPLAY -u WAYLAND_DISPLAY " + exe + " --help");
    INFO(help.output);
    CHECK(help.exit_code == 0);
    for (const char* option : {"--level", "--dojo", "--headless", "--view"})
        CHECK(help.output.find(option) != std::string::npos);
    auto headless = test::run_command("env -u DISPLAY -u WAYLAND_DISPLAY " + exe + " --headless --help");
    INFO(headless.output);
    CHECK(headless.exit_code == 0);
    for (const char* option : {"--seconds", "--autoplay", "--replay", "--stats-json"})
        CHECK(headless.output.find(option) != std::string::npos);
}
