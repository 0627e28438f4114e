// Hardening of level files: every input the fuzzer kept (tests/data/fuzz/fuzz_level_loader/, replayed here
// with the GCC build) and every way a level file can be damaged, unreadable or fail to save. Each gives a
// level or a clear error naming the file, and a failed save leaves the previous file as it was.
#include "core/log.h"
#include "hardening/fault_support.h"
#include "level/campaign.h"
#include "level/level_io.h"
#include "level_builders.h"

#include <filesystem>
#include <fstream>

using namespace ks;
using namespace ks::level;
namespace fs = std::filesystem;

namespace {
// The fuzz target's properties (fuzz/fuzz_level_loader.cpp), checked with doctest.
void check_level_input(const std::string& text, const std::string& name) {
    LoadReport report;
    auto level = load_level_string(text, name, &report);
    if (level.ok()) {
        CHECK(report.error_count() == 0);
        const std::string saved = save_level_string(*level);
        auto again = load_level_string(saved, name);
        REQUIRE_MESSAGE(again.ok(), again.error().str());
        CHECK(save_level_string(*again) == saved);
        return;
    }
    hardening::check_clear_error(level.error(), name);
    REQUIRE(report.error_count() >= 1);
    for (const Diagnostic& d : report.diagnostics) {
        CHECK(d.error.where.file == name);
        CHECK_FALSE(d.error.message.empty());
    }
}
} // namespace

TEST_CASE("fuzz regressions: every kept level input loads or fails with a clear error") {
    const auto inputs = hardening::fuzz_inputs("fuzz_level_loader");
    REQUIRE_MESSAGE(!inputs.empty(), "tests/data/fuzz/fuzz_level_loader/ holds the seeds and found crashes");
    for (const auto& path : inputs) {
        CAPTURE(path);
        check_level_input(ks::test::read_file(path), path.filename().string());
    }
    MESSAGE(inputs.size() << " level fuzz inputs replayed");
}

TEST_CASE(
    "fuzz regressions: every kept campaign input loads, saves and loads back the same, or fails clearly") {
    // The fuzz target's properties (fuzz/fuzz_campaign_loader.cpp): level names looked up in levels/.
    const auto inputs = hardening::fuzz_inputs("fuzz_campaign_loader");
    REQUIRE_MESSAGE(!inputs.empty(), "fuzz/corpus/fuzz_campaign_loader.tar.xz holds the kept corpus");
    const fs::path folder = ks::test::source_dir() / "levels";
    int loaded = 0;
    for (const auto& path : inputs) {
        CAPTURE(path);
        const std::string name = path.filename().string();
        auto campaign = load_campaign_string(ks::test::read_file(path), name, folder);
        if (!campaign.ok()) {
            hardening::check_clear_error(campaign.error(), name);
            continue;
        }
        ++loaded;
        CHECK_FALSE(campaign->levels.empty());
        const std::string saved = save_campaign_string(*campaign);
        auto again = load_campaign_string(saved, "resaved.json", folder);
        REQUIRE_MESSAGE(again.ok(), again.error().str());
        CHECK(save_campaign_string(*again) == saved);
    }
    MESSAGE(inputs.size() << " campaign fuzz inputs replayed, " << loaded << " loaded");
}

TEST_CASE("faults: damaged copies of the main level fail with an error naming the file") {
    const std::string good = ks::test::read_file(ks::test::source_dir() / "levels" / "main.json");
    REQUIRE(load_level_string(good, "main.json").ok());
    ks::test::ScratchDir dir;
    for (const auto& damaged : hardening::damaged_copies(good)) {
        CAPTURE(damaged.what);
        const fs::path path = dir / "damaged.json";
        {
            std::ofstream out(path, std::ios::binary | std::ios::trunc);
            out << damaged.text;
        }
        LoadReport report;
        auto level = load_level_file(path, &report);
        REQUIRE_FALSE(level.ok());
        hardening::check_clear_error(level.error(), path.string());
        // A cut-off file is pinned to the line where the text stopped.
        if (damaged.what.rfind("truncated", 0) == 0) {
            REQUIRE_FALSE(report.diagnostics.empty());
            CHECK(report.diagnostics.front().error.where.line > 0);
        }
    }
}

TEST_CASE("faults: a missing level, a folder in its place and an unreadable file are clear errors") {
    ks::test::ScratchDir dir;
    auto missing = load_level_file(dir / "nowhere" / "main.json");
    REQUIRE_FALSE(missing.ok());
    hardening::check_clear_error(missing.error(), (dir / "nowhere" / "main.json").string());
    CHECK(missing.error().message.find("not found") != std::string::npos);

    fs::create_directory(dir / "folder.json");
    auto folder = load_level_file(dir / "folder.json");
    REQUIRE_FALSE(folder.ok());
    hardening::check_clear_error(folder.error(), (dir / "folder.json").string());

    fs::create_symlink(dir / "gone.json", dir / "dangling.json");
    auto dangling = load_level_file(dir / "dangling.json");
    REQUIRE_FALSE(dangling.ok());
    hardening::check_clear_error(dangling.error(), (dir / "dangling.json").string());

    const fs::path locked = dir / "locked.json";
    REQUIRE(save_level_file(locked, ks::test::level_with_every_type()).ok());
    fs::permissions(locked, fs::perms::none);
    auto unreadable = load_level_file(locked);
    fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_write);
    if (!hardening::permissions_enforced()) {
        MESSAGE(
            "running as root: permission bits are not enforced; unreadable files are covered by the folder "
            "and dangling-link cases above");
        CHECK(unreadable.ok());
    } else {
        REQUIRE_FALSE(unreadable.ok());
        hardening::check_clear_error(unreadable.error(), locked.string());
        CHECK(unreadable.error().hint.find("permission") != std::string::npos);
    }
}

TEST_CASE("faults: a save that fails at any stage keeps the previous level file byte for byte") {
    ks::test::ScratchDir dir;
    log::Capture quiet;
    const fs::path path = dir / "level.json";
    const Level before = ks::test::level_with_every_type();
    REQUIRE(save_level_file(path, before).ok());
    const std::string original = ks::test::read_file(path);
    Level changed = before;
    changed.name = "Changed after the last save";
    changed.entities.erase(changed.entities.begin()); // the wall: no link names it

    for (files::Fault fault : hardening::kSaveFaults) {
        CAPTURE(hardening::fault_name(fault));
        Result<void> saved = ok();
        {
            hardening::FaultGuard guard(fault);
            saved = save_level_file(path, changed);
        }
        REQUIRE_FALSE(saved.ok());
        hardening::check_clear_error(saved.error(), path.string());
        CHECK(saved.error().hint.find("previous file was left untouched") != std::string::npos);
        CHECK(ks::test::read_file(path) == original);
        auto reloaded = load_level_file(path);
        REQUIRE(reloaded.ok());
        CHECK(*reloaded == before);
        // Only a "killed" process leaves its temporary file; an orderly failure cleans up.
        CHECK(hardening::leftover_temp_files(dir.path()) == (fault == files::Fault::BeforeRename ? 1 : 0));
        for (const auto& entry : fs::directory_iterator(dir.path()))
            if (entry.path() != path) fs::remove(entry.path());
    }
    // With the fault gone the same save goes through, and a leftover temp file would not have been in the
    // way.
    REQUIRE(save_level_file(path, changed).ok());
    auto reloaded = load_level_file(path);
    REQUIRE(reloaded.ok());
    CHECK(*reloaded == changed);
}

TEST_CASE("faults: saving into a missing or read-only folder is a clear error") {
    ks::test::ScratchDir dir;
    auto missing = save_level_file(dir / "no" / "such" / "level.json", ks::test::level_with_every_type());
    REQUIRE_FALSE(missing.ok());
    hardening::check_clear_error(missing.error(), (dir / "no" / "such" / "level.json").string());
    CHECK_FALSE(fs::exists(dir / "no"));

    if (!hardening::permissions_enforced()) {
        MESSAGE("running as root: a read-only folder is covered by Fault::OpenTemp in the test above");
        return;
    }
    const fs::path folder = dir / "readonly";
    fs::create_directory(folder);
    REQUIRE(save_level_file(folder / "level.json", ks::test::level_with_every_type()).ok());
    const std::string original = ks::test::read_file(folder / "level.json");
    fs::permissions(folder, fs::perms::owner_read | fs::perms::owner_exec);
    auto saved = save_level_file(folder / "level.json", Level{});
    fs::permissions(folder, fs::perms::owner_all);
    REQUIRE_FALSE(saved.ok());
    hardening::check_clear_error(saved.error(), (folder / "level.json").string());
    CHECK(ks::test::read_file(folder / "level.json") == original);
}
