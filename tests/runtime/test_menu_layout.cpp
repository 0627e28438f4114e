// The menus' layout: the main menu shows the game's version in its bottom-right corner
// (runtime/app/version_label.cpp); the Options and Controls panels fit the window and no slider's grab
// covers its value (issue 28, item 6), at five window sizes.
#include "runtime/play_session.h"
#include "runtime/screen_image.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <sstream>
#include <string>
#include <vector>

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

namespace {
struct Rect {
    std::string label;
    float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};
// The status file's `button` and `text` lines (x0 y0 x1 y1 LABEL).
std::vector<Rect> rects_of(const std::string& status, const std::string& kind) {
    std::vector<Rect> out;
    std::istringstream lines(status);
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind(kind + " ", 0) != 0) continue;
        std::istringstream in(line.substr(kind.size() + 1));
        Rect r;
        in >> r.x0 >> r.y0 >> r.x1 >> r.y1;
        std::getline(in >> std::ws, r.label);
        out.push_back(r);
    }
    return out;
}
bool overlap(const Rect& a, const Rect& b) {
    // One pixel of slack: ImGui rounds item rectangles to whole pixels.
    return std::min(a.x1, b.x1) - std::max(a.x0, b.x0) > 1.0f &&
           std::min(a.y1, b.y1) - std::max(a.y0, b.y0) > 1.0f;
}
} // namespace

TEST_CASE("options and controls: inside the window, no value under a slider, at five window sizes") {
    REQUIRE_MESSAGE(test::have_display(),
                    "no DISPLAY: GL screen tests cannot run (./run.sh test runs them under xvfb-run)");
    test::ScratchDir dir;
    const auto status_file = dir / "status.txt";
    struct Size {
        int w, h;
    };
    // The smallest size the menus' 0.6 scale fits (768x432), 4:3, 5:4 and 16:9 sizes.
    for (Size size : {Size{768, 432}, Size{800, 600}, Size{1024, 768}, Size{1280, 720}, Size{1280, 1024}})
        for (const char* screen : {"options", "controls"}) {
            // Controls at the extremes only (each size is a launch of the game).
            if (std::string(screen) == "controls" && (size.w == 1024 || size.h == 720)) continue;
            CAPTURE(size.w);
            CAPTURE(size.h);
            CAPTURE(screen);
            const auto run = test::run_command(
                "env XDG_CONFIG_HOME=" + (dir / "config").string() + " " +
                (test::bin_dir() / "killswitch").string() + " --width " + std::to_string(size.w) +
                " --height " + std::to_string(size.h) + " --frames 2 --screen " + screen + " --screenshot " +
                (dir / "shot.png").string() + " --status-file " + status_file.string());
            INFO(run.output);
            REQUIRE(run.exit_code == 0);
            const std::string status = test::read_status(status_file).text;
            const std::vector<Rect> buttons = rects_of(status, "button"), texts = rects_of(status, "text");
            CHECK(texts.size() == (std::string(screen) == "options" ? 7u : 2u)); // one value per slider
            CHECK(buttons.size() >= 4u);
            for (const Rect& r : buttons) {
                CAPTURE(r.label);
                CHECK(r.x0 >= 0.0f);
                CHECK(r.y0 >= 0.0f);
                CHECK(r.x1 <= static_cast<float>(size.w));
                CHECK(r.y1 <= static_cast<float>(size.h));
            }
            for (const Rect& t : texts) {
                CAPTURE(t.label);
                CHECK(t.x0 >= 0.0f);
                CHECK(t.x1 <= static_cast<float>(size.w));
                for (const Rect& b : buttons) {
                    CAPTURE(b.label);
                    CHECK_FALSE(overlap(t, b));
                }
            }
            for (std::size_t i = 0; i < buttons.size(); ++i)
                for (std::size_t j = i + 1; j < buttons.size(); ++j) {
                    CAPTURE(buttons[i].label);
                    CAPTURE(buttons[j].label);
                    CHECK_FALSE(overlap(buttons[i], buttons[j]));
                }
        }
}
