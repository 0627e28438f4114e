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
