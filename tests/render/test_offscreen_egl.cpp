// The headless EGL context (shell/egl_headless.h), the offscreen context's route when there is no display or
// KS_GL_PLATFORM=egl: a GPU machine with no X server (or a box without Xvfb) still runs the GL tests and the
// benchmarks. The drawing case runs in a child of this test program, with no display in its environment, so
// it gets a context of its own whatever the parent has.
#include "gl_test_support.h"
#include "test_support.h"

#include "render/scene_renderer.h"
#include "render/shaders.h"
#include "shell/offscreen_context.h"

#include <doctest/doctest.h>

#include <filesystem>
#include <string>

using namespace ks;
using namespace ks::render;

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

// Run only as the child of the case below (doctest's --no-skip): the shared GL context, made with no display,
// is an EGL one; every program compiles there and the main level's start view draws lit.
TEST_CASE("EGL child: headless context compiles the shaders and draws the main level" * doctest::skip()) {
    KS_REQUIRE_GL();
    CHECK(test::gl_context()->platform().rfind("EGL ", 0) == 0);
    const int programs = ks::test::check_every_program_builds();
    CHECK(programs == static_cast<int>(ks::render::all_programs().size())); // every one built headless too
    const test::OffscreenShot shot = test::render_main_level_start(RendererSettings{});
    const test::ImageStats stats = test::image_stats(shot.rgb, test::kGlWidth, test::kGlHeight);
    MESSAGE("EGL start view: mean luma " << stats.mean_luma << ", " << shot.stats.draw_calls << " draws");
    CHECK(stats.mean_luma > 20.0);        // lit walls and floor, not a cleared or black target
    CHECK(stats.luma_stddev > 5.0);       // a picture, not one colour
    CHECK(stats.magenta_fraction < 0.01); // textures found
}

TEST_CASE("the GL tests run headless through EGL when no display is set") {
    std::error_code ec;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    REQUIRE_FALSE(ec);
    const test::CommandResult run =
        test::run_command("env -u DISPLAY -u WAYLAND_DISPLAY KS_GL_PLATFORM=egl '" + self.string() +
                          "' --no-skip --test-case='EGL child: headless context*' --success=false");
    INFO(run.output);
    CHECK(run.exit_code == 0);
    CHECK(run.output.find("1 passed | 0 failed") != std::string::npos); // the child case ran and passed
}
