// The animator's round trip: a clip changed with the dojo panel's own model calls and saved with its save
// (validate, atomic write) is what the runtime's Dojo then plays, and a new clip saved that way is listed in
// the runtime's Dojo at its next start and plays when clicked in the list. The runtime reads a scratch copy
// of the data folder (KS_DATA_DIR: the shipped assets and levels linked in, assets/animations/ copied), so
// the shipped robot.json is never touched.
#include "anim/clip_io.h"
#include "model/dojo_keys.h"
#include "runtime/play_session.h"
#include "runtime/screen_image.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

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

// The runtime's Dojo with `key` (default 2, the shoot pose) held one second in, from the data folder `root`.
test::Image dojo_shot(const test::ScratchDir& dir, const fs::path& root, const std::string& name,
                      const std::string& key = "2") {
    const auto file = dir / (name + ".png");
    auto run = test::run_command("env KS_DATA_DIR=" + root.string() + " XDG_CONFIG_HOME=" +
                                 (dir / "config").string() + " " + (test::bin_dir() / "killswitch").string() +
                                 " --width 640 --height 360 --frames 3 --screen dojo --dojo-key " + key +
                                 " --dojo-time 1 --screenshot " + file.string());
    INFO(run.output);
    REQUIRE(run.exit_code == 0);
    return test::load_png(file);
}

// The runtime's Dojo driven by real input (--input-script): Tab frees the mouse for the clip list, then
// `click` (empty: none) clicks that clip's row; the picture 1 s later and the last status file.
struct ScriptedDojo {
    test::Image image;
    std::string status;
};
ScriptedDojo dojo_script(const test::ScratchDir& dir, const fs::path& root, const std::string& name,
                         const std::string& click) {
    const auto script = dir / (name + ".txt");
    std::ofstream(script) << "5 key tab tap\n" << (click.empty() ? "" : "8 click " + click + "\n");
    const auto file = dir / (name + ".png"), status = dir / (name + "_status.txt");
    // An X server of its own: a pointer moved on the shared display (a parallel xdotool test) would reach
    // ImGui instead of the script's.
    static const test::PrivateDisplay display;
    auto run = test::run_command(
        "env DISPLAY=" + display.name() + " KS_DATA_DIR=" + root.string() +
        " XDG_CONFIG_HOME=" + (dir / "config").string() + " " + (test::bin_dir() / "killswitch").string() +
        " --width 640 --height 360 --frames 70 --dojo --input-script " + script.string() + " --status-file " +
        status.string() + " --screenshot " + file.string());
    INFO(run.output);
    REQUIRE(run.exit_code == 0);
    return {test::load_png(file), test::read_file(status)};
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
    REQUIRE_MESSAGE(test::have_display(),
                    "no DISPLAY: dojo round-trip test cannot run (./run.sh test runs it under xvfb-run)");
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

TEST_CASE("dojo round trip: a new clip saved in the dojo is listed in the runtime's Dojo and plays from it") {
    REQUIRE_MESSAGE(test::have_display(),
                    "no DISPLAY: dojo round-trip test cannot run (./run.sh test runs it under xvfb-run)");
    test::ScratchDir dir;
    const fs::path root = dir / "data";
    make_data_copy(root);
    const fs::path clips = root / "assets" / "animations" / "robot.json";

    // The animator adds a clip that raises the right arm high, and saves.
    auto file = anim::load_animation_file(clips);
    REQUIRE(file);
    anim::ClipDef wave;
    wave.name = "wave";
    anim::PhaseDef up;
    up.duration = 0.3;
    anim::TargetDef arm;
    arm.node = "arm_r";
    arm.rot = DVec3(0, 0, 150);
    up.targets.push_back(arm);
    wave.phases.push_back(up);
    file->clips.push_back(wave);
    auto saved = editor::save_dojo_file(clips, *file);
    REQUIRE_MESSAGE(saved, (saved ? std::string() : saved.error().str()));

    // Tab alone: the list is open (every clip a button, the new one too), the robot at rest.
    const ScriptedDojo open = dojo_script(dir, root, "open", "");
    INFO(open.status);
    CHECK(open.status.find("dojo clips 8 playing - picking 1 moved 0.0\n") != std::string::npos);
    CHECK(open.status.find(" wave\n") != std::string::npos); // its row, as a button
    CHECK(open.status.find(" idle\n") != std::string::npos);
    CHECK(open.status.find("captured 0") != std::string::npos);

    // Clicking "wave" in the list plays it: the robot's arm is up 150 degrees.
    const ScriptedDojo waved = dojo_script(dir, root, "waved", "wave");
    INFO(waved.status);
    CHECK(waved.status.find("dojo clips 8 playing wave picking 1 moved 150.0\n") != std::string::npos);

    // And on screen: the new clip is key 7 (after the reference five and idle), and the robot it poses
    // differs from the robot at rest.
    const test::Image rest = dojo_shot(dir, root, "rest", "0");
    const test::Image raised = dojo_shot(dir, root, "raised", "7");
    const int changed = pixels_changed(rest, raised);
    INFO("pixels changed by the new clip: " << changed);
    CHECK(changed > 300);

    // The shipped data has no such clip.
    const ScriptedDojo shipped = dojo_script(dir, test::source_dir(), "shipped", "");
    CHECK(shipped.status.find("dojo clips 7 playing - picking 1") != std::string::npos);
    CHECK(shipped.status.find(" wave\n") == std::string::npos);
}
