// The animator's round trip: a clip changed with the dojo panel's own model calls and saved with its save
// (validate, atomic write) is what the runtime's Dojo then plays. The runtime reads a scratch copy of the
// data folder (KS_DATA_DIR: the shipped assets and levels linked in, assets/animations/ copied), so the
// shipped robot.json is never touched.
#include "anim/clip_io.h"
#include "model/dojo_keys.h"
#include "runtime/screen_image.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>

using namespace ks;
namespace fs = std::filesystem;

namespace {
// `root`/assets and `root`/levels: everything links to the source tree except assets/animations/, copied.
void make_data_copy(const fs::path& root) {
    const fs::path source = test::source_dir();
    fs::create_directories(root / "assets");
    fs::create_directory_symlink(source / "levels", root / "levels");
    for (const auto& entry : fs::directory_iterator(source / "assets")) {
        const auto name = entry.path().filename();
        if (name == "animations")
            fs::copy(entry.path(), root / "assets" / name, fs::copy_options::recursive);
        else if (entry.is_directory())
            fs::create_directory_symlink(entry.path(), root / "assets" / name);
        else
            fs::create_symlink(entry.path(), root / "assets" / name);
    }
}

// The runtime's Dojo with key 2 (the shoot pose) held one second in, from the data folder `root`.
test::Image dojo_shot(const test::ScratchDir& dir, const fs::path& root, const std::string& name) {
    const auto file = dir / (name + ".png");
    auto run = test::run_command("env KS_DATA_DIR=" + root.string() + " XDG_CONFIG_HOME=" +
                                 (dir / "config").string() + " " + (test::bin_dir() / "killswitch").string() +
                                 " --width 640 --height 360 --frames 3 --screen dojo --dojo-key 2 "
                                 "--dojo-time 1 --screenshot " +
                                 file.string());
    INFO(run.output);
    REQUIRE(run.exit_code == 0);
    return test::load_png(file);
}

int pixels_changed(const test::Image& a, const test::Image& b) {
    REQUIRE(a.rgb.size() == b.rgb.size());
    int changed = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            const unsigned char *p = a.at(x, y), *q = b.at(x, y);
            changed += std::abs(p[0] - q[0]) + std::abs(p[1] - q[1]) + std::abs(p[2] - q[2]) > 40 ? 1 : 0;
        }
    return changed;
}
} // namespace

TEST_CASE("dojo round trip: a shoot pose changed and saved in the dojo is what the runtime's Dojo plays") {
    if (!test::have_display()) {
        MESSAGE("no DISPLAY: dojo round-trip test skipped (./run.sh test runs it under xvfb-run)");
        return;
    }
    test::ScratchDir dir;
    const fs::path root = dir / "data";
    make_data_copy(root);
    const fs::path clips = root / "assets" / "animations" / "robot.json";
    REQUIRE(fs::is_regular_file(clips));
    REQUIRE_FALSE(fs::is_symlink(clips));

    // The copy, untouched, looks exactly like the shipped data: what changes later is the edit's doing.
    const test::Image shipped = dojo_shot(dir, test::source_dir(), "shipped");
    const test::Image copied = dojo_shot(dir, root, "copied");
    CHECK(pixels_changed(shipped, copied) < 100);

    // The animator drops the right arm's keys from the shoot pose (the arm stays at rest) and saves.
    auto file = anim::load_animation_file(clips);
    REQUIRE(file);
    size_t clip = file->clips.size();
    for (size_t i = 0; i < file->clips.size(); ++i)
        if (file->clips[i].name == "shoot_pose") clip = i;
    REQUIRE(clip < file->clips.size());
    for (const char* node : {"arm_r", "forearm_r", "hand_r"}) {
        auto removed = editor::remove_node_key(*file, clip, 0, node);
        INFO(node << ": " << (removed ? std::string() : removed.error().str()));
        REQUIRE(removed);
    }
    auto saved = editor::save_dojo_file(clips, *file);
    REQUIRE_MESSAGE(saved, (saved ? std::string() : saved.error().str()));

    const test::Image edited = dojo_shot(dir, root, "edited");
    const int changed = pixels_changed(copied, edited);
    INFO("pixels changed by the edit: " << changed);
    CHECK(changed > 300);
    // And the runtime plays the saved file again the same way (deterministic at a fixed time).
    CHECK(pixels_changed(edited, dojo_shot(dir, root, "edited_again")) < 100);
}
