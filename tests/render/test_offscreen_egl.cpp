// The headless EGL context (shell/egl_headless.h), the offscreen context's route when there is no display or
// KS_GL_PLATFORM=egl: a GPU machine with no X server (or a CI box without Xvfb) still runs the benchmarks.
#include "shell/offscreen_context.h"
#include "test_support.h"

#include <doctest/doctest.h>
#include <stb_image.h>

#include <string>

using namespace ks;

TEST_CASE("offscreen context: KS_GL_PLATFORM picks EGL or a window, and no display means EGL") {
    CHECK(shell::offscreen_wants_egl("egl", true));
    CHECK(shell::offscreen_wants_egl("egl", false));
    CHECK_FALSE(shell::offscreen_wants_egl("window", true));
    CHECK_FALSE(
        shell::offscreen_wants_egl("window", false)); // asked for: fails later with the no-display advice
    CHECK_FALSE(shell::offscreen_wants_egl(nullptr, true));
    CHECK(shell::offscreen_wants_egl(nullptr, false));
    CHECK_FALSE(shell::offscreen_wants_egl("", true));
    CHECK(shell::offscreen_wants_egl("glx", false)); // an unknown value: automatic
}

TEST_CASE("ks_bench render draws the main level through EGL with no display set") {
    test::ScratchDir shots;
    const std::string command =
        "env -u DISPLAY -u WAYLAND_DISPLAY KS_GL_PLATFORM=egl '" + (test::bin_dir() / "ks_bench").string() +
        "' render --quick --frames 10 --rounds 1 --width 160 --height 90 --only 'fast, scale 1'"
        " --shots '" +
        shots.path().string() + "'";
    const test::CommandResult run = test::run_command(command);
    INFO(run.output);
    REQUIRE(run.exit_code == 0);
    CHECK(run.output.find("(EGL ") != std::string::npos); // "(EGL device N)" or "(EGL surfaceless)"
    int width = 0, height = 0, channels = 0;
    unsigned char* rgb =
        stbi_load((shots / "fast__scale_1.png").string().c_str(), &width, &height, &channels, 3);
    REQUIRE(rgb != nullptr);
    CHECK(width == 160);
    CHECK(height == 90);
    long lit = 0; // the start view: lit walls and floor, not a cleared or black target
    for (int i = 0; i < width * height; ++i) lit += (rgb[i * 3] + rgb[i * 3 + 1] + rgb[i * 3 + 2]) > 60;
    stbi_image_free(rgb);
    CHECK(lit > width * height / 2);
}
