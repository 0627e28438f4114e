// The script language: parse errors with file:line:column, every command running through the Editor, and
// a script that builds, validates, saves and reloads a two-room level.
#include "editor_test_util.h"

#include "core/files.h"
#include "core/log.h"
#include "model/script.h"

using namespace ks;
using namespace ks::editor;
using level::EntityType;

namespace {
Result<ScriptReport> run(Editor& ed, const std::string& text, const std::filesystem::path& base = {}) {
    return run_script_text(text, "test.kss", base, ed);
}
} // namespace

TEST_CASE("script: parse errors name file, line and column, all at once, before anything runs") {
    const char* text = "place robot at 0,0,0\n"
                       "plaec robot at 1,0,0\n"
                       "\n"
                       "place robto at 1,0,0\n"
                       "move 1,2\n"
                       "undo three\n"
                       "expect count robot\n"
                       "select 3 x\n";
    auto parsed = parse_script(text, "levels/bad.kss");
    REQUIRE_FALSE(parsed.ok());
    const std::string all = parsed.error().str();
    INFO(all);
    CHECK(all.find("levels/bad.kss:2:1: unknown command 'plaec'") != std::string::npos);
    CHECK(all.find("levels/bad.kss:4:7: unknown entity type 'robto'") != std::string::npos);
    CHECK(all.find("levels/bad.kss:5:6: expected three numbers") != std::string::npos);
    CHECK(all.find("levels/bad.kss:6:6: expected a count") != std::string::npos);
    CHECK(all.find("levels/bad.kss:7:") != std::string::npos);
    CHECK(all.find("levels/bad.kss:8:10: expected an entity id") != std::string::npos);
    CHECK(all.find("types: wall, floor") != std::string::npos); // the hint lists what is valid

    Editor ed;
    CHECK_FALSE(run(ed, text).ok());
    CHECK(ed.level().entities.empty()); // line 1 did not run
}

TEST_CASE("script: comments, blank lines, CRLF, and colour values that start with #") {
    Editor ed;
    auto r =
        run(ed, "# a comment\r\n\r\n   # indented comment\r\nplace top_light at 0,16,0 # trailing comment\r\n"
                "set color #ff8000\r\nexpect field 1 color #ff8000\r\n");
    REQUIRE_MESSAGE(r.ok(), (r.ok() ? std::string() : r.error().str()));
    CHECK(r->lines_run == 3);
    CHECK(r->expectations_checked == 1);
}

TEST_CASE("script: run-time errors stop at their line and say why") {
    Editor ed;
    auto r = run(ed, "place robot at 0,0,0\nset health 5000000\nplace pickup at 1,0,0\n");
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().where.line == 2);
    CHECK(r.error().str().find("test.kss:2") != std::string::npos);
    CHECK(r.error().str().find("out of range") != std::string::npos);
    CHECK(ed.level().entities.size() == 1);

    Editor ed2;
    auto failed_expect = run(ed2, "place robot at 0,0,0\nexpect count robot 2\n");
    REQUIRE_FALSE(failed_expect.ok());
    CHECK(failed_expect.error().str().find("robot count is 1, expected 2") != std::string::npos);

    Editor ed3;
    auto open_tx = run(ed3, "begin Drag\nplace robot at 0,0,0\n");
    REQUIRE_FALSE(open_tx.ok());
    CHECK(open_tx.error().hint.find("commit") != std::string::npos);
    Editor ed4;
    CHECK_FALSE(run(ed4, "undo\n").ok());
    CHECK_FALSE(run(ed4, "commit\n").ok());
    CHECK_FALSE(run(ed4, "select 4\n").ok());
    CHECK_FALSE(run(ed4, "open no/such/file.json\n").ok());
}

TEST_CASE("script: every command drives the editor like the UI does") {
    ks::test::ScratchDir dir;
    log::Capture quiet;
    Editor ed;
    auto r = run(ed, R"(
grid 0.5 45
place robot at 1.2,0,0 yaw 50 name First robot
expect field 1 position 1,0,0
expect field 1 rotation 45,0,0
expect field 1 name First robot
snap off
place robot at 1.2,0,0
expect field 2 position 1.2,0,0
snap on
select 1 2
expect selected 2
select remove 2
select add 2
select toggle 1
expect selected 1
select all robot
expect selected 2
select none
expect selected 0
select box -1,0,-1 1.1,3,1
expect selected 2
select all
move 1,0,0
nudge +z
rotate 90
select 1
duplicate 0,0,5
expect count robot 3
set health 250
reset health
expect field 3 health 100
copy
paste
expect count robot 4
delete
expect count robot 3
undo 2
expect count robot 3
redo
expect count robot 4
undo all
expect count robot 0
redo all
expect count robot 3
setting fog_density 0.01
player_start 2,0,2 yaw 90
level_name Script test
lock 1
hide 2
unlock 1
show 2
begin Two moves
select 1
move 1,0,0
move 1,0,0
commit
begin Cancelled
move 5,0,0
cancel
expect dirty
save out.json
expect clean
new
expect count robot 0
open out.json
expect count robot 3
expect clean
place wall at 10,0,10
scale 2,2,1
expect field 5 size 20,32,0.5
select 1
scale 2
)",
                 dir.path());
    REQUIRE_FALSE(r.ok()); // the last line: robots have no size fields
    CHECK(r.error().where.line == 73);
    CHECK(r.error().str().find("Scale: none of the selected entities has size fields") != std::string::npos);
    CHECK(ed.level().name == "Script test");
    CHECK(ed.level().player_start.yaw == 90.0f);
    CHECK(ed.level().settings.fog_density == 0.01f);
    CHECK(ed.history().step_names() == std::vector<std::string>{"Place wall", "Scale"}); // since the open
    // Robot 1: (1,0,0) moved to 2, nudged to z 0.5, turned 90° about the pair's centre (2.1, 0, 0.5) to
    // (2.1, 0, 0.6), then the committed transaction's two moves (+2); the cancelled one left no trace.
    const auto* first = ed.level().find(1);
    REQUIRE(first);
    CHECK(first->position.x == doctest::Approx(4.1));
    CHECK(first->position.z == doctest::Approx(0.6));
    CHECK(first->rotation.x == 135.0f);
}

TEST_CASE("script: `save PATH` never overwrites another file unless told to") {
    ks::test::ScratchDir dir;
    log::Capture quiet;
    REQUIRE(files::write_atomic(dir / "taken.json", "precious").ok());
    Editor ed;
    auto r = run(ed, "place robot at 0,0,0\nsave taken.json\n", dir.path());
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().where.line == 2);
    CHECK(ks::test::read_file(dir / "taken.json") == "precious");
    Editor ed2;
    REQUIRE(run(ed2, "place robot at 0,0,0\nsave taken.json overwrite\n", dir.path()).ok());
}

TEST_CASE("script: builds a two-room level with a door, a robot, pickups and the panel; validates, saves, "
          "reloads") {
    ks::test::ScratchDir dir;
    const std::string script = std::string(editor_test::kTwoRoomScript) + R"(
expect count wall 7
expect count door 1
expect count robot 1
expect count pickup 2
expect count control_panel 1
expect valid
expect no_issue reachability
save two_rooms.json
# break it, check the rule fires, then undo
select all door
move 0,0,8
expect issue door_gap
undo
expect valid
expect clean
)";
    REQUIRE(files::write_atomic(dir / "build.kss", script).ok());
    auto r = run_script(dir / "build.kss");
    REQUIRE_MESSAGE(r.ok(), (r.ok() ? std::string() : r.error().str()));
    CHECK(r->expectations_checked == 10);
    REQUIRE(r->saved.size() == 1);

    auto loaded = level::load_level_file(dir / "two_rooms.json");
    REQUIRE(loaded.ok());
    CHECK(loaded->name == "Two rooms");
    CHECK(loaded->entities.size() == 13);
    CHECK(validate_design(*loaded).empty());
    CHECK(loaded->player_start.position == Vec3(0, 0, 15));
}

TEST_CASE("script: fix and recover commands") {
    Editor ed;
    auto r = run(ed, std::string(editor_test::kTwoRoomScript) + R"(
snap off
place pickup at 5,2.5,5
place gas_cylinder at -5,1,5
expect issue support
fix support
expect no_issue support
expect valid
)");
    REQUIRE_MESSAGE(r.ok(), (r.ok() ? std::string() : r.error().str()));
    CHECK_FALSE(run(ed, "recover accept\n").ok()); // nothing to recover
}

TEST_CASE("script: the example in docs/editor.md runs and builds a valid level") {
    const std::string doc = ks::test::read_file(ks::test::source_dir() / "docs" / "editor.md");
    const std::string marker = "Example (the two-room level";
    size_t at = doc.find(marker);
    REQUIRE(at != std::string::npos);
    size_t begin = doc.find("```\n", at);
    REQUIRE(begin != std::string::npos);
    begin += 4;
    const size_t end = doc.find("```", begin);
    REQUIRE(end != std::string::npos);
    ks::test::ScratchDir dir;
    Editor ed;
    auto r = run(ed, doc.substr(begin, end - begin), dir.path());
    REQUIRE_MESSAGE(r.ok(), (r.ok() ? std::string() : r.error().str()));
    CHECK(r->saved.size() == 1);
    CHECK(level::load_level_file(dir / "two_rooms.json").ok());
}
