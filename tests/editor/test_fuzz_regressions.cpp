// Hardening of the editor: every script the fuzzer kept (tests/data/fuzz/fuzz_editor_script/, replayed here
// with the GCC build), damaged levels opened in the editor, and saves and autosaves that fail or are
// "killed" part-way (core/files fault injection). Nothing crashes, the file on disk stays as it was, and the
// autosave brings back every edit it held.
#include "editor_test_util.h"
#include "hardening/fault_support.h"
#include "model/edit_entities.h"
#include "model/edit_files.h"
#include "model/edit_transforms.h"

#include "core/log.h"
#include "model/autosave.h"
#include "model/prefab.h"
#include "model/prefab_library.h"
#include "model/recent_files.h"
#include "model/script.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>

using namespace ks;
using namespace ks::editor;
using level::EntityType;
namespace fs = std::filesystem;

namespace {
using editor_test::FakeClock;

// Autosaves after the idle time has passed; returns what update() said.
Result<std::optional<fs::path>> autosave_now(Autosaver& autosaver, const Editor& ed, FakeClock& t) {
    (void)autosaver.update(ed); // notices the change
    t.now += autosaver.config().idle_seconds + 1;
    return autosaver.update(ed);
}

// The file "was saved before the crash": its autosave must be clearly newer for recovery to be offered.
void age(const fs::path& file) {
    fs::last_write_time(file, fs::last_write_time(file) - std::chrono::seconds(10));
}
} // namespace

TEST_CASE("fuzz regressions: every kept prefab loads, saves and loads back the same, or fails clearly") {
    // The fuzz target's properties (fuzz/fuzz_prefab_loader.cpp) over its kept corpus.
    const auto inputs = hardening::fuzz_inputs("fuzz_prefab_loader");
    REQUIRE_MESSAGE(!inputs.empty(), "fuzz/corpus/fuzz_prefab_loader.tar.xz holds the kept corpus");
    const Frame frame{Vec3(12.5f, 0.0f, -40.0f), 90.0f};
    int loaded = 0;
    for (const auto& path : inputs) {
        CAPTURE(path);
        const std::string name = path.filename().string();
        std::vector<Error> warnings;
        auto prefab = prefab_from_text(ks::test::read_file(path), name, &warnings);
        if (!prefab.ok()) {
            hardening::check_clear_error(prefab.error(), name);
            continue;
        }
        ++loaded;
        for (const Error& w : warnings) hardening::check_clear_error(w, name);
        const std::string saved = prefab_to_text(*prefab);
        auto again = prefab_from_text(saved, "resaved.prefab.json");
        REQUIRE_MESSAGE(again.ok(), again.error().str());
        CHECK(prefab_to_text(*again) == saved);
        for (const level::Entity& entity : prefab->entities) {
            const level::Entity back = entity_out_of_frame(entity_into_frame(entity, frame), frame);
            const Vec3 d = back.position - entity.position;
            const float size = std::max({1.0f, std::abs(entity.position.x), std::abs(entity.position.y),
                                         std::abs(entity.position.z)});
            CHECK(std::abs(d.x) + std::abs(d.y) + std::abs(d.z) <= 1e-4f * size);
        }
    }
    MESSAGE(inputs.size() << " prefab fuzz inputs replayed, " << loaded << " loaded");
}

TEST_CASE("fuzz regressions: every kept script parses or fails with a clear error on a real line") {
    const auto inputs = hardening::fuzz_inputs("fuzz_editor_script");
    REQUIRE_MESSAGE(!inputs.empty(), "tests/data/fuzz/fuzz_editor_script/ holds the seeds and found crashes");
    int parsed = 0;
    for (const auto& path : inputs) {
        CAPTURE(path);
        const std::string text = ks::test::read_file(path);
        const std::string name = path.filename().string();
        auto script = parse_script(text, name);
        if (script.ok()) {
            ++parsed;
            for (const ScriptStep& step : script->steps) CHECK(step.line >= 1);
            continue;
        }
        hardening::check_clear_error(script.error(), name);
        const int lines = 1 + int(std::count(text.begin(), text.end(), '\n'));
        CHECK(script.error().where.line >= 0);
        CHECK(script.error().where.line <= lines);
    }
    MESSAGE(inputs.size() << " script fuzz inputs replayed, " << parsed << " parsed");
}

TEST_CASE("faults: opening a damaged level reports the file and leaves the open document alone") {
    ks::test::ScratchDir dir;
    log::Capture quiet;
    const std::string good = ks::test::read_file(ks::test::source_dir() / "levels" / "main.json");
    Editor ed;
    REQUIRE(run_script_text(editor_test::kTwoRoomScript, "two_rooms.kss", dir.path(), ed).ok());
    REQUIRE(save_as(ed, dir / "two_rooms.json").ok());
    (void)place(ed, EntityType::Robot, {2, 0, 2}); // an unsaved edit that must survive the failed opens
    const std::string before = editor_test::text_of(ed);
    for (const auto& damaged : hardening::damaged_copies(good)) {
        CAPTURE(damaged.what);
        const fs::path path = dir / "damaged.json";
        {
            std::ofstream out(path, std::ios::binary | std::ios::trunc);
            out << damaged.text;
        }
        auto opened = open(ed, path);
        REQUIRE_FALSE(opened.ok());
        hardening::check_clear_error(opened.error(), path.string());
        CHECK(editor_test::text_of(ed) == before);
        CHECK(ed.file_path() == dir / "two_rooms.json");
        CHECK(ed.has_unsaved_changes());
    }
    auto missing = open(ed, dir / "missing.json");
    REQUIRE_FALSE(missing.ok());
    hardening::check_clear_error(missing.error(), (dir / "missing.json").string());
    CHECK(editor_test::text_of(ed) == before);
}

TEST_CASE("faults: a failed Save keeps the file on disk, the edits in the editor, and the document dirty") {
    ks::test::ScratchDir dir;
    log::Capture quiet;
    const fs::path file = dir / "level.json";
    Editor ed;
    REQUIRE(run_script_text(editor_test::kTwoRoomScript, "two_rooms.kss", dir.path(), ed).ok());
    REQUIRE(save_as(ed, file).ok());
    const std::string on_disk = ks::test::read_file(file);
    for (files::Fault fault : hardening::kSaveFaults) {
        CAPTURE(hardening::fault_name(fault));
        (void)place(ed, EntityType::Pickup, {float(int(fault)), 0, 5});
        const std::string edited = editor_test::text_of(ed);
        Result<SaveReport> saved = Error("not run");
        {
            hardening::FaultGuard guard(fault);
            saved = save(ed);
        }
        REQUIRE_FALSE(saved.ok());
        hardening::check_clear_error(saved.error(), file.string());
        CHECK(ks::test::read_file(file) == on_disk);
        CHECK(editor_test::text_of(ed) == edited);
        CHECK(ed.has_unsaved_changes());
        CHECK(title(ed).find('*') != std::string::npos);
        CHECK(disk_status(ed) == DiskStatus::Unchanged); // the failed save did not confuse change detection
    }
    // Save As to a new name fails the same way and does not adopt the new name.
    {
        hardening::FaultGuard guard(files::Fault::OpenTemp);
        auto saved_as = save_as(ed, dir / "elsewhere.json");
        REQUIRE_FALSE(saved_as.ok());
    }
    CHECK_FALSE(fs::exists(dir / "elsewhere.json"));
    CHECK(ed.file_path() == file);
    // Once the disk works again, the next Save writes every edit.
    const std::string edited = editor_test::text_of(ed);
    REQUIRE(save(ed).ok());
    CHECK(ks::test::read_file(file) == edited);
    CHECK_FALSE(ed.has_unsaved_changes());
}

TEST_CASE(
    "faults: an editor killed mid-save loses no edits: the old file is whole and the autosave recovers") {
    ks::test::ScratchDir dir;
    log::Capture quiet;
    FakeClock t;
    const fs::path file = dir / "level.json";
    std::string saved_text, edited_text;
    {
        Editor ed;
        Autosaver autosaver({}, t.clock());
        REQUIRE(run_script_text(editor_test::kTwoRoomScript, "two_rooms.kss", dir.path(), ed).ok());
        REQUIRE(save_as(ed, file).ok());
        saved_text = ks::test::read_file(file);
        age(file);
        (void)place(ed, EntityType::GasCylinder, {4, 0, -4});
        (void)rename_level(ed, "Edited, then killed while saving");
        auto autosaved = autosave_now(autosaver, ed, t);
        REQUIRE(autosaved.ok());
        REQUIRE(autosaved->has_value());
        edited_text = editor_test::text_of(ed);
        // The process dies after writing the temporary file, before the rename.
        hardening::FaultGuard killed(files::Fault::BeforeRename);
        REQUIRE_FALSE(save(ed).ok());
    }
    CHECK(ks::test::read_file(file) == saved_text);
    CHECK(hardening::leftover_temp_files(dir.path()) == 1); // what the dead process left behind

    Editor restarted;
    REQUIRE(open(restarted, file).ok()); // the stray temporary file is not in the way
    CHECK(editor_test::text_of(restarted) == saved_text);
    REQUIRE(restarted.recovery_offer().has_value());
    REQUIRE(accept_recovery(restarted).ok());
    CHECK(editor_test::text_of(restarted) == edited_text);
    CHECK(restarted.has_unsaved_changes());
    REQUIRE(save(restarted).ok());
    CHECK(ks::test::read_file(file) == edited_text);
}

TEST_CASE("faults: an untitled level survives a failed Save As and a crash through its autosave") {
    ks::test::ScratchDir dir;
    log::Capture quiet;
    FakeClock t;
    AutosaveConfig config;
    config.untitled_dir = dir / "untitled";
    std::string edited_text;
    {
        Editor ed;
        Autosaver autosaver(config, t.clock());
        REQUIRE(run_script_text(editor_test::kTwoRoomScript, "two_rooms.kss", dir.path(), ed).ok());
        REQUIRE(autosave_now(autosaver, ed, t)->has_value());
        edited_text = editor_test::text_of(ed);
        hardening::FaultGuard read_only(files::Fault::OpenTemp);
        auto saved = save_as(ed, dir / "first_save.json");
        REQUIRE_FALSE(saved.ok());
        CHECK(saved.error().hint.find("writable") != std::string::npos);
        CHECK(ed.file_path().empty());
    }
    CHECK_FALSE(fs::exists(dir / "first_save.json"));
    auto offer = find_untitled_recovery(config);
    REQUIRE(offer.has_value());
    Editor restarted;
    restarted.offer_recovery(*offer);
    REQUIRE(accept_recovery(restarted).ok());
    CHECK(editor_test::text_of(restarted) == edited_text);
}

TEST_CASE(
    "faults: a failing autosave reports itself, keeps the older autosave, and the next change retries") {
    ks::test::ScratchDir dir;
    log::Capture quiet;
    FakeClock t;
    const fs::path file = dir / "level.json";
    Editor ed;
    Autosaver autosaver({}, t.clock());
    REQUIRE(run_script_text(editor_test::kTwoRoomScript, "two_rooms.kss", dir.path(), ed).ok());
    REQUIRE(save_as(ed, file).ok());
    age(file);
    (void)place(ed, EntityType::Robot, {1, 0, 1});
    auto first = autosave_now(autosaver, ed, t);
    REQUIRE(first.ok());
    REQUIRE(first->has_value());
    const fs::path first_autosave = **first;
    const std::string first_text = ks::test::read_file(first_autosave);

    for (files::Fault fault : hardening::kSaveFaults) {
        CAPTURE(hardening::fault_name(fault));
        (void)place(ed, EntityType::Pickup, {float(int(fault)), 0, -3});
        Result<std::optional<fs::path>> failed = std::optional<fs::path>();
        {
            hardening::FaultGuard guard(fault);
            failed = autosave_now(autosaver, ed, t);
        }
        REQUIRE_FALSE(failed.ok());
        CHECK(failed.error().str().find(".autosave") != std::string::npos);
        // The older autosave is whole and still the one recovery offers; a temp file left by a "killed"
        // autosave is not mistaken for an autosave.
        CHECK(ks::test::read_file(first_autosave) == first_text);
        CHECK(list_autosaves(dir / ".autosave", "level") == std::vector<fs::path>{first_autosave});
        auto offer = find_recovery(file);
        REQUIRE(offer.has_value());
        CHECK(offer->autosave == first_autosave);
    }
    // The next change autosaves normally, with everything done since.
    (void)nudge(ed, 0, 1);
    auto retried = autosave_now(autosaver, ed, t);
    REQUIRE(retried.ok());
    REQUIRE(retried->has_value());
    CHECK(ks::test::read_file(**retried) == editor_test::text_of(ed));
}

TEST_CASE("faults: a failed autosave is retried after an idle period even without a new edit") {
    ks::test::ScratchDir dir;
    log::Capture quiet;
    FakeClock t;
    Editor ed;
    Autosaver autosaver({}, t.clock());
    REQUIRE(run_script_text(editor_test::kTwoRoomScript, "two_rooms.kss", dir.path(), ed).ok());
    REQUIRE(save_as(ed, dir / "level.json").ok());
    (void)place(ed, EntityType::Robot, {1, 0, 1});
    {
        hardening::FaultGuard full_disk(files::Fault::ShortWrite);
        auto failed = autosave_now(autosaver, ed, t);
        REQUIRE_FALSE(failed.ok());
        // Not hammered every frame while the disk is full.
        t.now += 0.1;
        auto soon = autosaver.update(ed);
        REQUIRE(soon.ok());
        CHECK_FALSE(soon->has_value());
    }
    // The disk has room again; no further edit is made, yet the edits get autosaved.
    t.now += autosaver.config().idle_seconds + 1;
    auto retried = autosaver.update(ed);
    REQUIRE(retried.ok());
    REQUIRE(retried->has_value());
    CHECK(ks::test::read_file(**retried) == editor_test::text_of(ed));
}

TEST_CASE("faults: a damaged autosave is refused with its name and the document stays as opened") {
    ks::test::ScratchDir dir;
    log::Capture quiet;
    FakeClock t;
    const fs::path file = dir / "level.json";
    fs::path autosave;
    {
        Editor ed;
        Autosaver autosaver({}, t.clock());
        REQUIRE(run_script_text(editor_test::kTwoRoomScript, "two_rooms.kss", dir.path(), ed).ok());
        REQUIRE(save_as(ed, file).ok());
        age(file);
        (void)place(ed, EntityType::Robot, {1, 0, 1});
        auto written = autosave_now(autosaver, ed, t);
        REQUIRE(written->has_value());
        autosave = **written;
    }
    const std::string autosaved = ks::test::read_file(autosave);
    const std::string saved = ks::test::read_file(file);
    {
        std::ofstream out(autosave, std::ios::binary | std::ios::trunc);
        out << autosaved.substr(0, autosaved.size() / 2);
    }
    Editor ed;
    REQUIRE(open(ed, file).ok());
    REQUIRE(ed.recovery_offer().has_value());
    auto accepted = accept_recovery(ed);
    REQUIRE_FALSE(accepted.ok());
    hardening::check_clear_error(accepted.error(), autosave.string());
    CHECK(editor_test::text_of(ed) == saved);
    CHECK_FALSE(ed.has_unsaved_changes());
    CHECK_FALSE(ed.history().can_undo());
}

TEST_CASE("faults: the prefab library and the recent-files list keep their previous file under every fault") {
    log::Capture quiet;
    for (files::Fault fault : hardening::kSaveFaults) {
        CAPTURE(hardening::fault_name(fault));
        ks::test::ScratchDir dir;
        // A prefab saved, then saved again under the fault: the old file and the library's entry stay.
        PrefabLibrary library({dir / "prefabs"});
        level::Entity wall;
        wall.id = 1;
        wall.props = level::default_props(EntityType::Wall);
        auto first = library.save(Prefab{"doorway", "Doorway", {wall}});
        REQUIRE(first.ok());
        const std::string prefab_before = ks::test::read_file(*first);
        Result<fs::path> failed_prefab = Error("not run");
        {
            hardening::FaultGuard guard(fault);
            failed_prefab = library.save(Prefab{"doorway", "Doorway, wider", {wall}});
        }
        REQUIRE_FALSE(failed_prefab.ok());
        hardening::check_clear_error(failed_prefab.error(), first->string());
        CHECK(failed_prefab.error().str().find("previous file was left untouched") != std::string::npos);
        CHECK(ks::test::read_file(*first) == prefab_before);
        library.rescan();
        REQUIRE(library.get("doorway").ok());
        CHECK(library.get("doorway")->title == "Doorway");
        CHECK(hardening::leftover_temp_files(dir / "prefabs") ==
              (fault == files::Fault::BeforeRename ? 1 : 0));
        REQUIRE(library.save(Prefab{"doorway", "Doorway, wider", {wall}}).ok());
        CHECK(library.get("doorway")->title == "Doorway, wider");

        // The recent-files list the same way: the list on disk is the previous one until a save succeeds.
        RecentFiles recent(dir / "recent.json");
        recent.add(dir / "first.json");
        REQUIRE(recent.save().ok());
        const std::string recent_before = ks::test::read_file(dir / "recent.json");
        recent.add(dir / "second.json");
        Result<void> failed_recent = ok();
        {
            hardening::FaultGuard guard(fault);
            failed_recent = recent.save();
        }
        REQUIRE_FALSE(failed_recent.ok());
        hardening::check_clear_error(failed_recent.error(), (dir / "recent.json").string());
        CHECK(ks::test::read_file(dir / "recent.json") == recent_before);
        RecentFiles reread(dir / "recent.json");
        REQUIRE(reread.load().ok());
        CHECK(reread.entries().size() == 1);
        REQUIRE(recent.save().ok());
        REQUIRE(reread.load().ok());
        CHECK(reread.entries().size() == 2);
    }
}
