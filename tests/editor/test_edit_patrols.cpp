// Robot patrols in the editor: adding, moving and removing points, mode and wait, each one undo step; the
// script commands; the design check that a point stands on a floor, and its snap-down quick fix.
#include "editor_test_util.h"
#include "model/edit_files.h"
#include "model/edit_layers.h"
#include "model/edit_patrols.h"
#include "model/patrol_edit.h"
#include "model/quick_fix.h"
#include "model/script.h"

#include <limits>

using namespace ks;
using namespace ks::editor;
using namespace ks::editor_test;

namespace {

const level::Patrol& patrol_of(const Editor& ed, int id = kRobot) {
    REQUIRE(ed.level().find(id));
    REQUIRE(ed.level().find(id)->try_as<level::RobotProps>());
    return ed.level().find(id)->as<level::RobotProps>().patrol;
}

Result<ScriptReport> run_patrol(Editor& ed, const std::string& text) {
    return run_script_text(text, "patrol.kss", {}, ed);
}

std::vector<const Issue*> patrol_issues(Editor& ed) {
    std::vector<const Issue*> out;
    for (const Issue& issue : ed.issues())
        if (issue.rule == Rule::Patrol) out.push_back(&issue);
    return out;
}

} // namespace

TEST_CASE("patrol points are added, moved and removed, each one undo step that undoes exactly") {
    Editor ed = two_rooms();
    const std::string before = text_of(ed);
    const size_t steps = ed.history().undo_count();

    REQUIRE(patrol_add(ed, kRobot, {3, 0, -10}).ok());
    REQUIRE(patrol_add(ed, kRobot, {-5, 0, -10}).ok());
    REQUIRE(patrol_add(ed, kRobot, {0, 0, -5}, 0).ok()); // after the first point
    CHECK(patrol_of(ed).points == std::vector<Vec3>{{3, 0, -10}, {0, 0, -5}, {-5, 0, -10}});
    REQUIRE(patrol_move(ed, kRobot, 2, {-6, 0, -12}).ok());
    REQUIRE(patrol_set_mode(ed, kRobot, "ping_pong").ok());
    REQUIRE(patrol_set_wait(ed, kRobot, 1.5f).ok());
    REQUIRE(patrol_remove(ed, kRobot, 1).ok());
    CHECK(ed.history().undo_count() == steps + 7);
    const level::Patrol edited = patrol_of(ed);
    CHECK(edited.points == std::vector<Vec3>{{3, 0, -10}, {-6, 0, -12}});
    CHECK(edited.ping_pong());
    CHECK(edited.wait == 1.5f);
    CHECK(ed.history().undo_name() == "Remove patrol point");

    REQUIRE(ed.undo());
    CHECK(patrol_of(ed).points.size() == 3);
    for (int i = 0; i < 6; ++i) REQUIRE(ed.undo());
    CHECK(text_of(ed) == before);
    for (int i = 0; i < 7; ++i) REQUIRE(ed.redo());
    CHECK(patrol_of(ed) == edited);
}

TEST_CASE("removing the last point removes the patrol, so the file has none and the robot wanders") {
    Editor ed = two_rooms();
    const std::string before = text_of(ed);
    REQUIRE(patrol_add(ed, kRobot, {3, 0, -10}).ok());
    REQUIRE(patrol_set_wait(ed, kRobot, 4).ok());
    REQUIRE(patrol_remove(ed, kRobot, 0).ok());
    CHECK_FALSE(patrol_of(ed).active());
    CHECK(patrol_of(ed) == level::Patrol{});
    CHECK(text_of(ed) == before);
}

TEST_CASE("bad patrol edits are errors that change nothing") {
    Editor ed = two_rooms();
    REQUIRE(patrol_add(ed, kRobot, {3, 0, -10}).ok());
    const std::string before = text_of(ed);
    const size_t steps = ed.history().undo_count();
    const float nan = std::numeric_limits<float>::quiet_NaN();

    auto message = [](const Result<void>& r) { return r.ok() ? std::string("ok") : r.error().str(); };
    CHECK(message(patrol_add(ed, 1, {0, 0, 0})).find("entity 1 is a floor, not a robot") !=
          std::string::npos);
    CHECK(message(patrol_add(ed, 99, {0, 0, 0})).find("no entity with id 99") != std::string::npos);
    CHECK(message(patrol_add(ed, kRobot, {nan, 0, 0})).find("is not finite") != std::string::npos);
    CHECK(message(patrol_add(ed, kRobot, {2e5f, 0, 0})).find("out of range") != std::string::npos);
    CHECK(message(patrol_add(ed, kRobot, {0, 0, 0}, 5)).find("cannot add after point 5") !=
          std::string::npos);
    CHECK(message(patrol_move(ed, kRobot, 3, {0, 0, 0}))
              .find("no patrol point 3 (points are numbered 0 .. 0)") != std::string::npos);
    CHECK(message(patrol_remove(ed, kRobot, -1)).find("no patrol point -1") != std::string::npos);
    CHECK(message(patrol_set_mode(ed, kRobot, "zigzag")).find("unknown patrol mode 'zigzag'") !=
          std::string::npos);
    CHECK(message(patrol_set_wait(ed, kRobot, -2)).find("0 .. 600 seconds") != std::string::npos);
    REQUIRE(set_locked(ed, kRobot, true).ok());
    CHECK(message(patrol_add(ed, kRobot, {0, 0, 0})).find("is locked") != std::string::npos);
    REQUIRE(ed.undo()); // the lock (a step: locks are saved in the level's editor section)
    CHECK(text_of(ed) == before);
    CHECK(ed.history().undo_count() == steps);

    level::Patrol full;
    for (int i = 0; i < level::kMaxPatrolPoints; ++i) REQUIRE(add_patrol_point(full, {1, 0, 1}).ok());
    CHECK(message(add_patrol_point(full, {1, 0, 1})).find("already has 256 points; at most 256") !=
          std::string::npos);
}

TEST_CASE("script: patrol commands edit, expect and undo a route, and it survives save and open") {
    ks::test::ScratchDir dir;
    Editor ed = two_rooms();
    auto r = run_patrol(ed, R"(patrol 10 add 3,0,-10
patrol 10 add -5,0,-10
patrol 10 add 0,0,-15 after 0
patrol 10 move 2 -6,0,-12
patrol 10 mode ping_pong
patrol 10 wait 2
expect patrol 10 3
patrol 10 remove 1
expect patrol 10 2
undo
expect patrol 10 3
redo
expect patrol 10 2
expect no_issue patrol
expect valid
)");
    REQUIRE_MESSAGE(r.ok(), (r.ok() ? std::string() : r.error().str()));
    CHECK(r->expectations_checked == 6);
    REQUIRE(save_as(ed, dir / "patrol.json").ok());
    Editor reopened;
    REQUIRE(open(reopened, dir / "patrol.json").ok());
    const level::Patrol& patrol = patrol_of(reopened);
    CHECK(patrol.points == std::vector<Vec3>{{3, 0, -10}, {-6, 0, -12}});
    CHECK(patrol.ping_pong());
    CHECK(patrol.wait == 2.0f);

    auto failed = run_patrol(ed, "expect patrol 10 5\n");
    REQUIRE_FALSE(failed.ok());
    CHECK(failed.error().str().find("robot 10 has 2 patrol points, expected 5") != std::string::npos);
}

TEST_CASE("script: patrol syntax errors point at the word") {
    auto error_of = [](const char* text) {
        auto parsed = parse_script(text, "bad.kss");
        return parsed.ok() ? std::string("parsed") : parsed.error().str();
    };
    CHECK(error_of("patrol 10 jump 1,2,3").find("bad.kss:1:11: unknown patrol action 'jump'") !=
          std::string::npos);
    CHECK(error_of("patrol 10 mode zigzag")
              .find("bad.kss:1:16: unknown patrol mode 'zigzag' (modes: loop, ping_pong)") !=
          std::string::npos);
    CHECK(error_of("patrol 10 add 1,2").find("bad.kss:1:15: expected three numbers") != std::string::npos);
    CHECK(error_of("patrol robot add 1,2,3").find("bad.kss:1:8: expected the robot's id") !=
          std::string::npos);
    CHECK(error_of("patrol 10 move x 1,2,3").find("bad.kss:1:16: expected a point index") !=
          std::string::npos);
    CHECK(error_of("patrol 10 add 1,2,3 before 0").find("bad.kss:1:21: expected 'after'") !=
          std::string::npos);
    CHECK(error_of("expect patrol 10").find("bad.kss:1:") != std::string::npos);
    // A failing edit names the script line.
    Editor ed = two_rooms();
    auto r = run_patrol(ed, "patrol 10 add 0,0,0\npatrol 10 remove 4\n");
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().str().find("patrol.kss:2: Remove patrol point: robot 10: no patrol point 4") !=
          std::string::npos);
}

TEST_CASE(
    "validation: a patrol point off the floor is a warning whose quick fix snaps it down, one undo step") {
    Editor ed = two_rooms();
    REQUIRE(patrol_add(ed, kRobot, {3, 0, -10}).ok());
    REQUIRE(patrol_add(ed, kRobot, {-4, 2.5f, -8}).ok());  // floats above the floor
    REQUIRE(patrol_add(ed, kRobot, {-4, -0.3f, -4}).ok()); // sunk into it
    REQUIRE(patrol_add(ed, kRobot, {40, 0, -8}).ok());     // beyond every floor: no fix
    auto issues = patrol_issues(ed);
    REQUIRE(issues.size() == 3);
    CHECK(issues[0]->severity == IssueSeverity::Warning);
    CHECK(issues[0]->entity_id == kRobot);
    CHECK(issues[0]->message == "robot 10 patrol point 1 floats 2.50 units above the floor");
    CHECK(issues[1]->message == "robot 10 patrol point 2 is sunk 0.30 units into the floor");
    CHECK(issues[2]->message == "robot 10 patrol point 3 is outside every floor");
    CHECK(!issues[2]->fix.available());
    CHECK(issues[0]->fix.is<fixes::MovePatrolPoint>());
    CHECK(std::get<fixes::MovePatrolPoint>(issues[0]->fix.action).index == 1);

    const Issue first = *issues[0];
    REQUIRE(apply_quick_fix(ed, first).ok());
    CHECK(patrol_of(ed).points[1] == Vec3(-4, 0, -8));
    CHECK(patrol_issues(ed).size() == 2);
    REQUIRE(ed.undo());
    CHECK(patrol_of(ed).points[1] == Vec3(-4, 2.5f, -8));

    auto r =
        run_patrol(ed, "fix patrol\nexpect issue patrol 10\npatrol 10 remove 3\nexpect no_issue patrol\n");
    REQUIRE_MESSAGE(r.ok(), (r.ok() ? std::string() : r.error().str()));
    CHECK(patrol_of(ed).points[2] == Vec3(-4, 0, -4));
}
