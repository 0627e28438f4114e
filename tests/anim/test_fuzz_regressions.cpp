// Hardening of animation files: every input the fuzzer kept (tests/data/fuzz/fuzz_clip_loader/, replayed
// here with the GCC build) and every way the clip file can be damaged, unreadable or fail to save. Each gives
// a library or a clear error naming the file; a failed save leaves the previous file as it was.
#include "anim/clip_io.h"
#include "core/paths.h"
#include "hardening/fault_support.h"

#include <filesystem>
#include <fstream>

using namespace ks;
using namespace ks::anim;
namespace fs = std::filesystem;

namespace {
// The fuzz target's properties (fuzz/fuzz_clip_loader.cpp), checked with doctest.
void check_clip_input(const std::string& text, const std::string& name) {
    auto file = load_animation_string(text, name);
    if (!file.ok()) {
        hardening::check_clear_error(file.error(), name);
        return;
    }
    const std::string saved = save_animation_string(*file);
    auto again = load_animation_string(saved, name);
    REQUIRE_MESSAGE(again.ok(), again.error().str());
    CHECK(save_animation_string(*again) == saved);
    auto rig = build_rig(*file);
    if (!rig.ok()) {
        CHECK_FALSE(rig.error().message.empty());
        return;
    }
    auto clips = compile(*file, *rig);
    if (!clips.ok()) CHECK_FALSE(clips.error().message.empty());
}

const fs::path& robot_clips() {
    static const fs::path path = paths::asset("animations/robot.json");
    return path;
}
} // namespace

TEST_CASE("fuzz regressions: every kept clip input loads or fails with a clear error") {
    const auto inputs = hardening::fuzz_inputs("fuzz_clip_loader");
    REQUIRE_MESSAGE(!inputs.empty(), "tests/data/fuzz/fuzz_clip_loader/ holds the seeds and found crashes");
    for (const auto& path : inputs) {
        CAPTURE(path);
        check_clip_input(ks::test::read_file(path), path.filename().string());
    }
    MESSAGE(inputs.size() << " clip fuzz inputs replayed");
}

TEST_CASE("faults: damaged copies of the robot clip file fail with an error naming the file") {
    const std::string good = ks::test::read_file(robot_clips());
    REQUIRE(load_animation_string(good, "robot.json").ok());
    ks::test::ScratchDir dir;
    for (const auto& damaged : hardening::damaged_copies(good)) {
        CAPTURE(damaged.what);
        const fs::path path = dir / "robot.json";
        {
            std::ofstream out(path, std::ios::binary | std::ios::trunc);
            out << damaged.text;
        }
        auto library = load_animation_library(path);
        REQUIRE_FALSE(library.ok());
        hardening::check_clear_error(library.error(), path.string());
        // A cut-off file is pinned to the line where the text stopped ("file:line:column").
        if (damaged.what.rfind("truncated", 0) == 0 && damaged.text.find('\n') != std::string::npos)
            CHECK(library.error().str().find(path.string() + ":") != std::string::npos);
    }
}

TEST_CASE("faults: a missing clip file, a folder in its place and an unreadable file are clear errors") {
    ks::test::ScratchDir dir;
    for (const fs::path& path : {dir / "missing.json", dir / "folder.json", dir / "dangling.json"}) {
        if (path.filename() == "folder.json") fs::create_directory(path);
        if (path.filename() == "dangling.json") fs::create_symlink(dir / "gone.json", path);
        CAPTURE(path);
        auto library = load_animation_library(path);
        REQUIRE_FALSE(library.ok());
        hardening::check_clear_error(library.error(), path.string());
    }

    const fs::path locked = dir / "locked.json";
    fs::copy_file(robot_clips(), locked);
    fs::permissions(locked, fs::perms::none);
    auto unreadable = load_animation_library(locked);
    fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_write);
    if (!hardening::permissions_enforced()) {
        MESSAGE(
            "running as root: permission bits are not enforced; unreadable files are covered by the folder "
            "and dangling-link cases above");
        CHECK(unreadable.ok());
    } else {
        REQUIRE_FALSE(unreadable.ok());
        hardening::check_clear_error(unreadable.error(), locked.string());
    }
}

TEST_CASE("faults: a clip save that fails at any stage keeps the previous file byte for byte") {
    ks::test::ScratchDir dir;
    const fs::path path = dir / "robot.json";
    auto original_file = load_animation_file(robot_clips());
    REQUIRE(original_file.ok());
    REQUIRE(save_animation_file(path, *original_file).ok());
    const std::string original = ks::test::read_file(path);
    AnimationFile changed = *original_file;
    changed.default_blend = 0.75;
    changed.wrap_captured_angles = !changed.wrap_captured_angles;

    for (files::Fault fault : hardening::kSaveFaults) {
        CAPTURE(hardening::fault_name(fault));
        Result<void> saved = ok();
        {
            hardening::FaultGuard guard(fault);
            saved = save_animation_file(path, changed);
        }
        REQUIRE_FALSE(saved.ok());
        hardening::check_clear_error(saved.error(), path.string());
        CHECK(ks::test::read_file(path) == original);
        CHECK(load_animation_library(path).ok());
        CHECK(hardening::leftover_temp_files(dir.path()) == (fault == files::Fault::BeforeRename ? 1 : 0));
        for (const auto& entry : fs::directory_iterator(dir.path()))
            if (entry.path() != path) fs::remove(entry.path());
    }
    REQUIRE(save_animation_file(path, changed).ok());
    auto reloaded = load_animation_file(path);
    REQUIRE_MESSAGE(reloaded.ok(), reloaded.error().str());
    CHECK(save_animation_string(*reloaded) == save_animation_string(changed));

    auto missing_folder = save_animation_file(dir / "no" / "robot.json", changed);
    REQUIRE_FALSE(missing_folder.ok());
    hardening::check_clear_error(missing_folder.error(), (dir / "no" / "robot.json").string());
}
