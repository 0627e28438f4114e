// Idle autosave with an injected clock, rotation to the newest N, and recovery after a crash.
#include "editor_test_util.h"
#include "model/edit_entities.h"
#include "model/edit_files.h"
#include "model/edit_transforms.h"

#include "core/log.h"
#include "model/autosave.h"

#include <chrono>
#include <filesystem>

using namespace ks;
using namespace ks::editor;
using level::EntityType;
namespace fs = std::filesystem;

using editor_test::FakeClock;

TEST_CASE("autosave: only after the user pauses, only when changed, and at most every max_delay mid-work") {
    ks::test::ScratchDir dir;
    log::Capture quiet;
    FakeClock t;
    AutosaveConfig config;
    config.idle_seconds = 5;
    config.max_delay_seconds = 60;
    Autosaver autosaver(config, t.clock());
    Editor ed;
    REQUIRE(save_as(ed, dir / "lvl.json").ok());

    CHECK_FALSE(autosaver.update(ed)->has_value()); // clean: nothing to do
    t.now += 100;
    CHECK_FALSE(autosaver.update(ed)->has_value());

    (void)place(ed, EntityType::Robot, {0, 0, 0});
    CHECK_FALSE(autosaver.update(ed)->has_value()); // just changed
    t.now += 4.9;
    CHECK_FALSE(autosaver.update(ed)->has_value());
    t.now += 0.2;
    auto written = autosaver.update(ed);
    REQUIRE(written.ok());
    REQUIRE(written->has_value());
    CHECK(**written == dir / ".autosave" / "lvl.1.json");
    CHECK(ks::test::read_file(**written) == editor_test::text_of(ed));
    t.now += 100;
    CHECK_FALSE(autosaver.update(ed)->has_value()); // unchanged since the autosave

    // Continuous work: a change every second never pauses 5 s, but after 60 s it is saved anyway.
    int saves = 0;
    for (int i = 0; i < 70; ++i) {
        (void)move_selection(ed, {0.1f, 0, 0});
        t.now += 1.0;
        saves += autosaver.update(ed)->has_value();
    }
    CHECK(saves == 1);
}

TEST_CASE("autosave: rotation keeps the newest N; untitled levels go to the config folder") {
    ks::test::ScratchDir dir;
    log::Capture quiet;
    FakeClock t;
    AutosaveConfig config;
    config.keep = 3;
    config.untitled_dir = dir / "untitled";
    Autosaver autosaver(config, t.clock());
    Editor ed;
    (void)place(ed, EntityType::Robot, {0, 0, 0});
    CHECK_FALSE(autosaver.update(ed)->has_value()); // the frame of the change
    t.now += 10;
    auto first = autosaver.update(ed);
    REQUIRE(first->has_value());
    CHECK(**first == dir / "untitled" / "untitled.1.json");

    REQUIRE(save_as(ed, dir / "room.json").ok());
    for (int i = 0; i < 5; ++i) {
        (void)place(ed, EntityType::Pickup, {float(i), 0, 0});
        CHECK_FALSE(autosaver.update(ed)->has_value());
        t.now += 10;
        REQUIRE(autosaver.update(ed)->has_value());
    }
    auto saves = list_autosaves(dir / ".autosave", "room");
    REQUIRE(saves.size() == 3);
    CHECK(saves[0].filename() == "room.3.json");
    CHECK(saves[2].filename() == "room.5.json");
    CHECK(ks::test::read_file(saves[2]) == editor_test::text_of(ed));
    // Files of other levels and stray names in the folder are left alone.
    CHECK(list_autosaves(dir / ".autosave", "roo").empty());
}

TEST_CASE(
    "autosave: recovery is offered when an autosave is newer than the file, and accepting is undoable") {
    ks::test::ScratchDir dir;
    log::Capture quiet;
    FakeClock t;
    const fs::path file = dir / "crash.json";
    std::string saved_text, autosaved_text;
    {
        Editor ed;
        (void)place(ed, EntityType::Robot, {0, 0, 0});
        REQUIRE(save_as(ed, file).ok());
        saved_text = editor_test::text_of(ed);
        Autosaver autosaver({}, t.clock());
        (void)place(ed, EntityType::Pickup, {3, 0, 0});
        (void)rename_level(ed, "Unsaved work");
        CHECK_FALSE(autosaver.update(ed)->has_value());
        t.now += 30;
        REQUIRE(autosaver.update(ed)->has_value());
        autosaved_text = editor_test::text_of(ed);
        // The editor "crashes" here without saving. Make the autosave clearly newer than the file.
        fs::last_write_time(file, fs::last_write_time(file) - std::chrono::seconds(10));
    }
    Editor ed;
    REQUIRE(open(ed, file).ok());
    REQUIRE(ed.recovery_offer().has_value());
    CHECK(ed.recovery_offer()->autosave.filename() == "crash.1.json");
    REQUIRE(accept_recovery(ed).ok());
    CHECK(editor_test::text_of(ed) == autosaved_text);
    CHECK(ed.has_unsaved_changes());
    CHECK(ed.file_path() == file); // Save writes to the real file, not the autosave
    CHECK_FALSE(ed.recovery_offer().has_value());
    REQUIRE(ed.undo());
    CHECK(editor_test::text_of(ed) == saved_text);
    CHECK_FALSE(ed.has_unsaved_changes());

    // Decline: nothing changes and the offer goes away.
    Editor declined;
    REQUIRE(open(declined, file).ok());
    REQUIRE(declined.recovery_offer().has_value());
    declined.decline_recovery();
    CHECK_FALSE(declined.recovery_offer().has_value());
    CHECK(editor_test::text_of(declined) == saved_text);

    // Once the file is saved after the autosave, there is nothing to recover.
    REQUIRE(ed.redo());
    REQUIRE(save(ed).ok());
    Editor after;
    REQUIRE(open(after, file).ok());
    CHECK_FALSE(after.recovery_offer().has_value());
    CHECK_FALSE(find_recovery(dir / "never_autosaved.json").has_value());
}

TEST_CASE("autosave: an untitled level is recovered at start-up as an unsaved untitled document") {
    ks::test::ScratchDir dir;
    FakeClock t;
    AutosaveConfig config;
    config.untitled_dir = dir / "untitled";
    CHECK_FALSE(find_untitled_recovery(config).has_value());
    std::string autosaved;
    {
        Editor crashed;
        Autosaver autosaver(config, t.clock());
        (void)place(crashed, EntityType::Robot, {0, 0, 0});
        CHECK_FALSE(autosaver.update(crashed)->has_value());
        t.now += 10;
        REQUIRE(autosaver.update(crashed)->has_value());
        autosaved = editor_test::text_of(crashed);
    }
    auto offer = find_untitled_recovery(config);
    REQUIRE(offer.has_value());
    CHECK(offer->level_file.empty());
    Editor ed;
    ed.offer_recovery(*offer);
    REQUIRE(accept_recovery(ed).ok());
    CHECK(editor_test::text_of(ed) == autosaved);
    CHECK(ed.file_path().empty());
    CHECK(ed.has_unsaved_changes());
    remove_autosaves(untitled_autosave_dir(config), "untitled");
    CHECK_FALSE(find_untitled_recovery(config).has_value());
}
