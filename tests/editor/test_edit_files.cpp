// New / Open / Save / Save As, title and dirty marker, drafts, external changes, recent files.
#include "editor_test_util.h"
#include "model/edit_entities.h"
#include "model/edit_files.h"
#include "model/edit_selection.h"
#include "model/edit_transforms.h"

#include "core/files.h"
#include "core/log.h"
#include "model/recent_files.h"

#include <chrono>
#include <cstdlib>
#include <filesystem>

using namespace ks;
using namespace ks::editor;
using level::EntityType;
namespace fs = std::filesystem;

TEST_CASE("files: open the shipped level, save it unchanged byte for byte, edit, save, reopen equal") {
    ks::test::ScratchDir dir;
    const fs::path copy = dir / "main.json";
    fs::copy_file(ks::test::source_dir() / "levels" / "main.json", copy);
    const std::string original = ks::test::read_file(copy);

    Editor ed;
    REQUIRE(open(ed, copy).ok());
    CHECK(title(ed) == "main.json - Killswitch Editor");
    CHECK_FALSE(ed.has_unsaved_changes());
    CHECK(disk_status(ed) == DiskStatus::Unchanged);
    auto saved = save(ed);
    REQUIRE(saved.ok());
    CHECK_FALSE(saved->draft);
    CHECK(ks::test::read_file(copy) == original); // load -> save is byte-identical

    REQUIRE(select(ed, {40}).ok()); // the robot behind door 1
    REQUIRE(move_selection(ed, {1, 0, 0}).ok());
    CHECK(title(ed) == "main.json* - Killswitch Editor");
    const std::string edited = editor_test::text_of(ed);
    REQUIRE(save(ed).ok());
    CHECK(title(ed) == "main.json - Killswitch Editor");
    CHECK(ks::test::read_file(copy) == edited);

    Editor again;
    REQUIRE(open(again, copy).ok());
    CHECK(again.level() == ed.level());
    // Undo after saving goes back to the original text, and the doc is dirty relative to the file.
    REQUIRE(ed.undo());
    CHECK(editor_test::text_of(ed) == original);
    CHECK(ed.has_unsaved_changes());
}

TEST_CASE("files: new, save without a path, Save As refusing to overwrite silently, missing folders") {
    ks::test::ScratchDir dir;
    log::Capture quiet;
    Editor ed;
    CHECK(title(ed) == "Untitled [draft] - Killswitch Editor"); // an empty level has no control panel
    (void)place(ed, EntityType::Robot, {0, 0, 0});
    CHECK(title(ed) == "Untitled* [draft] - Killswitch Editor");
    auto no_path = save(ed);
    REQUIRE_FALSE(no_path.ok());
    CHECK(no_path.error().hint.find("Save As") != std::string::npos);

    REQUIRE(files::write_atomic(dir / "taken.json", "someone else's file").ok());
    auto taken = save_as(ed, dir / "taken.json");
    REQUIRE_FALSE(taken.ok());
    CHECK(taken.error().where.file == (dir / "taken.json").string());
    CHECK(ks::test::read_file(dir / "taken.json") == "someone else's file");
    SaveOptions overwrite;
    overwrite.overwrite_existing = true;
    REQUIRE(save_as(ed, dir / "taken.json", overwrite).ok());

    CHECK_FALSE(save_as(ed, dir / "no" / "such" / "folder.json").ok());
    new_document(ed);
    CHECK(ed.file_path().empty());
    CHECK(ed.level().entities.empty());
    CHECK_FALSE(ed.history().can_undo());
}

TEST_CASE("files: a level with design errors saves as a flagged draft") {
    ks::test::ScratchDir dir;
    log::Capture capture;
    Editor ed;
    (void)place(ed, EntityType::Robot, {0, 0, 0}); // no floor, no control panel
    auto saved = save_as(ed, dir / "draft.json");
    REQUIRE(saved.ok());
    CHECK(saved->draft);
    CHECK(saved->error_count >= 2);
    CHECK(capture.text().find("draft") != std::string::npos);
    CHECK(title(ed).find("[draft]") != std::string::npos);
    // The draft is still a loadable level file.
    CHECK(level::load_level_file(dir / "draft.json").ok());
}

TEST_CASE("files: Save never overwrites a file changed on disk since it was opened") {
    ks::test::ScratchDir dir;
    log::Capture quiet;
    Editor ed;
    (void)place(ed, EntityType::Robot, {0, 0, 0});
    REQUIRE(save_as(ed, dir / "shared.json").ok());
    (void)place(ed, EntityType::Pickup, {2, 0, 0});

    // Someone else saves the same file.
    Editor other;
    REQUIRE(open(other, dir / "shared.json").ok());
    REQUIRE(rename_level(other, "Their edit").ok());
    REQUIRE(save(other).ok());
    const std::string theirs = ks::test::read_file(dir / "shared.json");
    CHECK(disk_status(ed) == DiskStatus::Modified);

    auto refused = save(ed);
    REQUIRE_FALSE(refused.ok());
    CHECK(refused.error().message.find("changed on disk") != std::string::npos);
    CHECK(ks::test::read_file(dir / "shared.json") == theirs);
    CHECK(ed.has_unsaved_changes());

    SaveOptions force;
    force.overwrite_external_changes = true;
    REQUIRE(save(ed, force).ok());
    CHECK(disk_status(ed) == DiskStatus::Unchanged);

    // Touching the file without changing its content is not a conflict.
    fs::last_write_time(dir / "shared.json", fs::file_time_type::clock::now() + std::chrono::seconds(5));
    (void)place(ed, EntityType::Pickup, {4, 0, 0});
    CHECK(save(ed).ok());

    fs::remove(dir / "shared.json");
    CHECK(disk_status(ed) == DiskStatus::Deleted);
}

TEST_CASE("files: opening bad files reports file and place, and leaves the document alone") {
    ks::test::ScratchDir dir;
    Editor ed;
    (void)place(ed, EntityType::Robot, {0, 0, 0});
    REQUIRE(files::write_atomic(dir / "broken.json",
                                "{\n  \"format\": \"killswitch-level\",\n  \"version\": 1,\n  oops\n}")
                .ok());
    auto r = open(ed, dir / "broken.json");
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().str().find("broken.json") != std::string::npos);
    CHECK(r.error().str().find(":4") != std::string::npos); // the line of the syntax error
    CHECK(ed.level().entities.size() == 1);
    CHECK_FALSE(open(ed, dir / "missing.json").ok());
    CHECK(ed.level().entities.size() == 1);
}

TEST_CASE("recent files: most recent first, capped, persisted; a malformed list is an error, not a crash") {
    ks::test::ScratchDir dir;
    const fs::path config = dir / "config" / "recent.json";
    {
        RecentFiles recent(config, 3);
        REQUIRE(recent.load().ok()); // missing: empty
        Editor ed;
        ed.set_recent_files(&recent);
        log::Capture quiet;
        for (const char* name : {"a.json", "b.json", "c.json", "d.json"})
            REQUIRE(save_as(ed, dir / name).ok());
        REQUIRE(open(ed, dir / "b.json").ok());
        REQUIRE(recent.entries().size() == 3);
        CHECK(recent.entries()[0] == dir / "b.json");
        CHECK(recent.entries()[1] == dir / "d.json");
        CHECK(recent.entries()[2] == dir / "c.json");
    }
    RecentFiles reloaded(config, 3);
    REQUIRE(reloaded.load().ok());
    CHECK(reloaded.entries().size() == 3);
    CHECK(reloaded.entries()[0] == dir / "b.json");

    REQUIRE(files::write_atomic(config, "[1, 2").ok());
    RecentFiles broken(config);
    auto r = broken.load();
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().where.file == config.string());
    CHECK(broken.entries().empty());
}
