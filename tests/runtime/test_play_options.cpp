// The Options panel through clicks (--input-script): the slow-machine options (render scale, quality)
// are saved and handed to the renderer, whose resolved values the --status-file reports; the difficulty is
// saved by its name and read back.
#include "runtime/play_session.h"
#include "runtime/screen_image.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <fstream>

using namespace ks;
using ks::test::Status;

TEST_CASE("options through the menu: Fast quality clicked, saved, and handed to the renderer") {
    REQUIRE_MESSAGE(test::have_display(),
                    "no DISPLAY: run the window tests under xvfb-run (./run.sh test does)");
    test::ScratchDir dir;
    test::write_file(dir / "level.json", test::corridor_level_json());
    test::write_file(dir / "options.txt", "20 click Options\n26 click Full\n30 click Fast\n34 click Back\n");
    const auto status_file = dir / "status.txt";
    const std::string killswitch = test::scripted_env(dir) + (test::bin_dir() / "killswitch").string() +
                                   " --width 480 --height 270 --level " + (dir / "level.json").string() +
                                   " --status-file " + status_file.string();
    auto run = test::run_command(killswitch + " --input-script " + (dir / "options.txt").string() +
                                 " --screenshot " + (dir / "o.png").string() + " --frames 40");
    INFO(run.output);
    REQUIRE(run.exit_code == 0);
    Status s = test::read_status(status_file);
    INFO(s.text);
    CHECK(s.screen == "menu"); // Back
    CHECK(s.text.find("options sensitivity 1.00 fov 75 invert_y 0 render_scale 0.00 quality fast") !=
          std::string::npos);
    CHECK(s.text.find("renderer render_scale") != std::string::npos);
    CHECK(s.text.find("quality fast\nrenderer") != std::string::npos);
    // Automatic scale: 0.5 on software rasterisers, 1 on GPUs.
    const bool resolved = s.text.find("renderer render_scale 0.50 quality fast") != std::string::npos ||
                          s.text.find("renderer render_scale 1.00 quality fast") != std::string::npos;
    CHECK(resolved);
    const std::string saved = test::read_file(dir / "config" / "killswitch" / "options.json");
    CHECK(saved.find("\"quality\": \"fast\"") != std::string::npos);
    CHECK(s.text.find("\ndifficulty normal\n") != std::string::npos);
    CHECK(saved.find("\"difficulty\": \"normal\"") != std::string::npos);
    // A render scale from the file reaches the renderer (0.25: a quarter of the pixels each way).
    test::write_file(
        dir / "config" / "killswitch" / "options.json",
        R"({"format": "killswitch-options", "version": 1, "render_scale": 0.25, "quality": "full",
            "difficulty": "hard"})");
    run = test::run_command(killswitch + " --screen menu --screenshot " + (dir / "m.png").string() +
                            " --frames 2");
    REQUIRE(run.exit_code == 0);
    s = test::read_status(status_file);
    CHECK(s.text.find("renderer render_scale 0.25 quality full") != std::string::npos);
    CHECK(s.text.find("\ndifficulty hard\n") != std::string::npos); // read from the file
}
