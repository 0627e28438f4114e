// Auto's dynamic resolution in the game (runtime/app/render_scale_control.h over
// render/dynamic_resolution.h), seen in the status file's "renderer render_scale S quality Q dynamic D":
// with a generous frame budget it climbs from the automatic half scale, with an impossible one it stays
// there, and a screenshot run without --target-fps keeps the fixed automatic scale.
#include "test_support.h"

#include <doctest/doctest.h>

#include <sstream>
#include <string>

using namespace ks;

namespace {

struct RendererLine {
    float scale = -1.0f;
    int dynamic = -1;
};

RendererLine run_game(const test::ScratchDir& dir, const std::string& extra) {
    const auto status = dir / "status.txt";
    std::filesystem::remove(status);
    const auto run = test::run_command(
        "env XDG_CONFIG_HOME=" + (dir / "config").string() + " " + (test::bin_dir() / "killswitch").string() +
        " --width 320 --height 180 --frames 150 --screen play --status-file " + status.string() +
        " --screenshot " + (dir / "shot.png").string() + extra);
    RendererLine r;
    if (run.exit_code != 0) {
        MESSAGE(run.output);
        return r;
    }
    std::istringstream in(test::read_file(status));
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string renderer, scale_word, quality_word, quality, dynamic_word;
        if (words >> renderer >> scale_word >> r.scale >> quality_word >> quality >> dynamic_word >>
                r.dynamic &&
            renderer == "renderer" && scale_word == "render_scale" && dynamic_word == "dynamic")
            return r;
    }
    return RendererLine{};
}

} // namespace

TEST_CASE("the game's automatic render scale climbs when frames are cheap and holds when they are not") {
    test::ScratchDir dir;
    // The game forced onto the fast path's automatic scale as on a software rasteriser (the tests run on
    // llvmpipe, where Auto is 0.5).
    const RendererLine fixed = run_game(dir, "");
    REQUIRE(fixed.dynamic == 0); // a screenshot run keeps a fixed scale
    CHECK(fixed.scale == doctest::Approx(0.5f));

    // 10 fps: every 320x180 frame fits (even in the sanitized build), so it climbs a step per 20 frames.
    const RendererLine easy = run_game(dir, " --target-fps 10");
    CHECK(easy.dynamic == 1);
    CHECK(easy.scale > 0.5f);

    // 1000 fps: no frame fits; it never goes below the automatic scale.
    const RendererLine impossible = run_game(dir, " --target-fps 1000");
    CHECK(impossible.dynamic == 1);
    CHECK(impossible.scale == doctest::Approx(0.5f));

    const auto bad = test::run_command((test::bin_dir() / "killswitch").string() + " --target-fps 0");
    CHECK(bad.exit_code == 2);
    CHECK(bad.output.find("--target-fps '0'") != std::string::npos);
}
