// Dragging patrol points in the viewport, without a window: the selected robot's point under the cursor is
// picked, dragged on its horizontal plane, and the whole drag is one undo step.
#include "editor_test_util.h"
#include "model/edit_entities.h"
#include "model/edit_patrols.h"
#include "model/edit_selection.h"
#include "view/patrol_drag.h"

using namespace ks;
using namespace ks::editor;

using editor_test::top_view;

TEST_CASE("a selected robot's patrol point is picked under the cursor and dragged as one undo step") {
    Editor editor;
    editor.grid().step = 1.0f;
    const int robot = *place(editor, level::EntityType::Robot, Vec3(0, 0, 0));
    REQUIRE(patrol_add(editor, robot, Vec3(0, 0, 0)).ok());
    REQUIRE(patrol_add(editor, robot, Vec3(10, 0, -5)).ok());
    const ViewCamera view = top_view();
    Vec2 at;
    REQUIRE(view.project(Vec3(10, 0, -5), at));

    REQUIRE(select(editor, {robot}).ok());
    auto hit = pick_patrol_point(editor, view, at + Vec2(3, -2));
    REQUIRE(hit);
    CHECK(hit->robot_id == robot);
    CHECK(hit->index == 1);
    CHECK_FALSE(pick_patrol_point(editor, view, at + Vec2(40, 0))); // too far from any point
    editor.clear_selection();
    CHECK_FALSE(pick_patrol_point(editor, view, at)); // only the selected robots' routes
    REQUIRE(select(editor, {robot}).ok());

    const std::size_t undo_depth = editor.history().undo_count();
    PatrolDrag drag;
    drag.begin(editor, view, *hit, at + Vec2(3, -2));
    Vec2 five_units_east;
    REQUIRE(view.project(Vec3(15, 0, -5), five_units_east));
    for (int step = 1; step <= 4; ++step) {
        const Vec2 mouse = at + Vec2(3, -2) + (five_units_east - at) * (static_cast<float>(step) / 4.0f);
        CHECK(drag.drag(editor, view, mouse).empty());
    }
    drag.end();
    const Vec3 moved = editor.level().find(robot)->as<level::RobotProps>().patrol.points[1];
    CHECK(moved.x == doctest::Approx(15.0f).epsilon(0.01));
    CHECK(moved.y == doctest::Approx(0.0f));
    CHECK(moved.z == doctest::Approx(-5.0f).epsilon(0.01));
    CHECK(editor.history().undo_count() == undo_depth + 1); // one step for the whole drag
    REQUIRE(editor.undo());
    CHECK(editor.level().find(robot)->as<level::RobotProps>().patrol.points[1] == Vec3(10, 0, -5));
}

TEST_CASE("a dragged patrol point lands on the grid with Snap on, and anywhere with Snap off") {
    Editor editor;
    editor.grid().step = 2.0f;
    const int robot = *place(editor, level::EntityType::Robot, Vec3(0, 0, 0));
    REQUIRE(patrol_add(editor, robot, Vec3(0, 0, 0)).ok());
    REQUIRE(patrol_add(editor, robot, Vec3(10, 0, -6)).ok());
    REQUIRE(select(editor, {robot}).ok());
    const ViewCamera view = top_view();
    Vec2 at, target;
    REQUIRE(view.project(Vec3(10, 0, -6), at));
    REQUIRE(view.project(Vec3(13.3f, 0, -4.6f), target)); // between grid lines in x and z
    auto point = [&] { return editor.level().find(robot)->as<level::RobotProps>().patrol.points[1]; };

    PatrolDrag drag;
    drag.begin(editor, view, PatrolPointHit{robot, 1}, at);
    CHECK(drag.drag(editor, view, target).empty());
    drag.end();
    CHECK(point() == Vec3(14, 0, -4)); // the nearest grid point of step 2, height kept

    editor.grid().snap = false;
    REQUIRE(view.project(Vec3(14, 0, -4), at));
    drag.begin(editor, view, PatrolPointHit{robot, 1}, at);
    CHECK(drag.drag(editor, view, target).empty());
    drag.end();
    CHECK(point().x == doctest::Approx(13.3f).epsilon(0.01));
    CHECK(point().z == doctest::Approx(-4.6f).epsilon(0.01));
}
