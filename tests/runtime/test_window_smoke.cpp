// GL smoke tests: start the real binaries under the test's display (Xvfb in CI) and look at what they draw.
#include "test_support.h"

#include <doctest/doctest.h>
#include <stb_image.h>

#include <cstdlib>
#include <set>
#include <vector>

using namespace ks;

namespace {
bool have_display() {
    const char* d = std::getenv("DISPLAY");
    return d && *d;
}

struct Image {
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;
};

Image load_png(const std::filesystem::path& path) {
    Image img;
    int channels = 0;
    unsigned char* data = stbi_load(path.c_str(), &img.width, &img.height, &channels, 3);
    if (data) {
        img.rgb.assign(data, data + static_cast<size_t>(img.width) * img.height * 3);
        stbi_image_free(data);
    }
    return img;
}

// Number of distinct colours on a coarse grid: a blank (single-colour) frame has one.
size_t distinct_colours(const Image& img) {
    std::set<unsigned> colours;
    for (int y = 0; y < img.height; y += 4)
        for (int x = 0; x < img.width; x += 4) {
            const unsigned char* p = &img.rgb[(static_cast<size_t>(y) * img.width + x) * 3];
            colours.insert((p[0] << 16) | (p[1] << 8) | p[2]);
        }
    return colours.size();
}
} // namespace

TEST_CASE("killswitch --screenshot renders a non-blank frame of the requested size") {
    if (!have_display()) {
        MESSAGE("no DISPLAY: GL smoke test skipped (./run.sh test runs it under xvfb-run)");
        return;
    }
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
    if (!have_display()) {
        MESSAGE("no DISPLAY: GL smoke test skipped");
        return;
    }
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
