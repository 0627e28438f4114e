// The gizmo's hit tests and drags without a window, in the orthographic axis views and in perspective:
// handles keep their size on screen, end-on handles are neither shown nor hit, a drag moves by the mouse's
// distance in world units snapped to the grid, and the whole drag is one undo step.
#include "editor_test_util.h"
#include "model/edit_entities.h"
#include "view/gizmo.h"

using namespace ks;
using namespace ks::editor;

using editor_test::kViewport;

namespace {

ViewCamera axis_view(ViewMode mode, Vec3 centre = Vec3(0.0f), float extent = 60.0f) {
    ViewCamera v;
    v.set_viewport(kViewport);
    v.set_view(mode, centre, extent);
    return v;
}

Vec2 midpoint(Vec2 a, Vec2 b) {
    return (a + b) * 0.5f;
}

// An editor with one robot at `at`, selected, on a 1-unit grid.
Editor one_robot(Vec3 at) {
    Editor e;
    e.grid().step = 1.0f;
    REQUIRE(place(e, level::EntityType::Robot, at).ok());
    return e;
}
} // namespace

TEST_CASE("gizmo handles keep their size on screen in both projections") {
    for (float height : {10.0f, 60.0f, 400.0f}) {
        ViewCamera top = axis_view(ViewMode::Top);
        top.camera.ortho_height = height;
        const GizmoShape s = gizmo_shape(top, Vec3(0.0f));
        REQUIRE(s.valid);
        CHECK(glm::length(s.tips[0] - s.centre) == doctest::Approx(540.0f * kGizmoScreenFraction));
        CHECK(glm::length(s.tips[2] - s.centre) == doctest::Approx(540.0f * kGizmoScreenFraction));
    }
    for (float distance : {5.0f, 50.0f, 300.0f}) {
        ViewCamera v;
        v.set_viewport(kViewport);
        v.camera.position = Vec3(0, 0, distance);
        const GizmoShape s = gizmo_shape(v, Vec3(0.0f));
        REQUIRE(s.valid);
        // Seen straight on, the x axis is in the image plane: exactly the screen fraction.
        CHECK(glm::length(s.tips[0] - s.centre) ==
              doctest::Approx(540.0f * kGizmoScreenFraction).epsilon(1e-3));
    }
}

TEST_CASE("handles seen end-on are hidden and not hit") {
    const GizmoShape top = gizmo_shape(axis_view(ViewMode::Top), Vec3(0.0f));
    CHECK(top.axis_visible[0]);
    CHECK_FALSE(top.axis_visible[1]); // y points at the viewer
    CHECK(top.axis_visible[2]);
    CHECK_FALSE(top.plane_visible[0]); // XY edge-on
    CHECK(top.plane_visible[1]);       // XZ faces the viewer
    CHECK_FALSE(top.plane_visible[2]); // YZ edge-on
    CHECK(top.ring_visible[1]);
    // Clicks around the centre, where the hidden y axis is a point, never grab "y".
    for (Vec2 d : {Vec2(0, 0), Vec2(-4, -4), Vec2(-6, 2)})
        CHECK(gizmo_hit(GizmoMode::Move, top, top.centre + d) != Handle::AxisY);
    CHECK(gizmo_hit(GizmoMode::Move, top, top.centre + Vec2(-20, 20)) == Handle::None);

    const GizmoShape front = gizmo_shape(axis_view(ViewMode::Front), Vec3(0.0f));
    CHECK(front.axis_visible[0]);
    CHECK(front.axis_visible[1]);
    CHECK_FALSE(front.axis_visible[2]);
    CHECK(front.plane_visible[0]);
    CHECK_FALSE(front.plane_visible[1]);
    CHECK_FALSE(front.ring_visible[1]); // the yaw ring is a line from the front: rotate from the top view
    CHECK(gizmo_hit(GizmoMode::Rotate, front, front.centre + Vec2(60, 0)) == Handle::None);

    ViewCamera persp;
    persp.set_viewport(kViewport);
    persp.set_view(ViewMode::Perspective, Vec3(0.0f), 40.0f);
    const GizmoShape p = gizmo_shape(persp, Vec3(0.0f));
    CHECK(p.axis_visible[0]);
    CHECK(p.axis_visible[1]);
    CHECK(p.axis_visible[2]);
    CHECK(p.plane_visible[0]);
    CHECK(p.plane_visible[1]);
    CHECK(p.plane_visible[2]);
}

TEST_CASE("gizmo hit tests: axes within 9 pixels, plane squares inside, the ring on its line") {
    const ViewCamera top = axis_view(ViewMode::Top, Vec3(5, 0, 5));
    const Vec3 pivot(5, 0, 5);
    const GizmoShape s = gizmo_shape(top, pivot);
    CHECK(gizmo_hit(GizmoMode::Move, s, midpoint(s.centre, s.tips[0]) + Vec2(0, 8)) == Handle::AxisX);
    CHECK(gizmo_hit(GizmoMode::Move, s, midpoint(s.centre, s.tips[0]) + Vec2(0, 10)) == Handle::None);
    CHECK(gizmo_hit(GizmoMode::Move, s, s.tips[2] + Vec2(2, -3)) == Handle::AxisZ);
    const auto& q = s.planes[1];
    CHECK(gizmo_hit(GizmoMode::Move, s, (q[0] + q[2]) * 0.5f) == Handle::PlaneXZ);
    CHECK(gizmo_hit(GizmoMode::Scale, s, (q[0] + q[2]) * 0.5f) == Handle::None); // scale has no planes
    CHECK(gizmo_hit(GizmoMode::Scale, s, s.tips[0]) == Handle::AxisX);
    // Ring: a point on it hits, the centre does not.
    const Vec2 on_ring = s.rings[1][7];
    CHECK(gizmo_hit(GizmoMode::Rotate, s, on_ring + Vec2(3, 3)) == Handle::RingY);
    CHECK(gizmo_hit(GizmoMode::Rotate, s, s.centre) == Handle::None);
    // Behind the camera: nothing.
    ViewCamera persp;
    persp.set_viewport(kViewport);
    const GizmoShape behind = gizmo_shape(persp, persp.camera.position - persp.forward() * 10.0f);
    CHECK_FALSE(behind.valid);
    CHECK(gizmo_hit(GizmoMode::Move, behind, Vec2(480, 270)) == Handle::None);
}

TEST_CASE("drag maths: closest axis parameter and plane point, degenerate cases refused") {
    const geometry::Ray down{Vec3(3, 50, -2), Vec3(0, -1, 0)};
    CHECK(*axis_parameter(down, Vec3(0.0f), Vec3(1, 0, 0)) == doctest::Approx(3.0f));
    CHECK(*axis_parameter(down, Vec3(0.0f), Vec3(0, 0, 1)) == doctest::Approx(-2.0f));
    CHECK_FALSE(axis_parameter(down, Vec3(0.0f), Vec3(0, 1, 0))); // looking down the axis
    const auto p = plane_point(down, Vec3(0, 4, 0), Vec3(0, 1, 0));
    REQUIRE(p);
    CHECK(p->y == doctest::Approx(4.0f));
    CHECK(p->x == doctest::Approx(3.0f));
    CHECK_FALSE(plane_point(down, Vec3(0.0f), Vec3(1, 0, 0)));                             // edge-on
    CHECK_FALSE(plane_point({Vec3(0, -5, 0), Vec3(0, -1, 0)}, Vec3(0.0f), Vec3(0, 1, 0))); // behind
    // A slanted perspective ray: the parameter is the closest point of two skew lines.
    const geometry::Ray slant{Vec3(0, 10, 10), glm::normalize(Vec3(0.3f, -1.0f, -1.0f))};
    const float s = *axis_parameter(slant, Vec3(0.0f), Vec3(1, 0, 0));
    const Vec3 on_axis(s, 0, 0);
    const Vec3 w = on_axis - slant.origin;
    const Vec3 closest = slant.origin + slant.direction * glm::dot(w, slant.direction);
    CHECK(glm::dot(closest - on_axis, Vec3(1, 0, 0)) == doctest::Approx(0.0f).epsilon(1e-4));
}

TEST_CASE("dragging the x arrow in the top view moves by the mouse distance, snapped, as one step") {
    Editor editor = one_robot(Vec3(2, 0, 3));
    const int id = editor.doc().selection.front();
    const ViewCamera top = axis_view(ViewMode::Top, Vec3(0.0f), 60.0f);
    const Vec3 pivot = editor.level().find(id)->position;
    const GizmoShape s = gizmo_shape(top, pivot);
    const Vec2 grab = midpoint(s.centre, s.tips[0]);
    Gizmo gizmo;
    REQUIRE(gizmo.hit(top, pivot, grab) == Handle::AxisX);
    const std::size_t steps = editor.history().undo_count();
    gizmo.begin(editor, top, pivot, Handle::AxisX, grab);
    const float wpp = top.world_per_pixel(pivot); // 66 / 540 = 0.122 units per pixel
    // 50 pixels right and 30 down: 6.1 units along x (snapped to 6), nothing along z (the arrow is x).
    CHECK(gizmo.drag(editor, top, grab + Vec2(50, 30)).empty());
    CHECK(editor.level().find(id)->position.x == doctest::Approx(2.0f + std::round(50.0f * wpp)));
    CHECK(editor.level().find(id)->position.z == doctest::Approx(3.0f));
    CHECK(gizmo.readout().find("move +6.00") != std::string::npos);
    CHECK(gizmo.drag(editor, top, grab + Vec2(-20, 0)).empty()); // back past the start
    CHECK(editor.level().find(id)->position.x == doctest::Approx(2.0f + std::round(-20.0f * wpp)));
    gizmo.end(editor);
    CHECK_FALSE(gizmo.dragging());
    CHECK(editor.history().undo_count() == steps + 1); // the whole drag is one step
    editor.undo();
    CHECK(editor.level().find(id)->position == Vec3(2, 0, 3));
}

TEST_CASE("plane drag in the top view moves in x and z; cancel reverts; yaw ring turns by snapped steps") {
    Editor editor = one_robot(Vec3(0, 0, 0));
    const int id = editor.doc().selection.front();
    const ViewCamera top = axis_view(ViewMode::Top, Vec3(0.0f), 60.0f);
    const float wpp = top.world_per_pixel(Vec3(0.0f));
    const GizmoShape s = gizmo_shape(top, Vec3(0.0f));
    const Vec2 grab = (s.planes[1][0] + s.planes[1][2]) * 0.5f;
    Gizmo gizmo;
    REQUIRE(gizmo.hit(top, Vec3(0.0f), grab) == Handle::PlaneXZ);
    gizmo.begin(editor, top, Vec3(0.0f), Handle::PlaneXZ, grab);
    gizmo.drag(editor, top, grab + Vec2(41, -66)); // right = +x, up on screen = -z
    CHECK(editor.level().find(id)->position.x == doctest::Approx(std::round(41.0f * wpp)));
    CHECK(editor.level().find(id)->position.z == doctest::Approx(std::round(-66.0f * wpp)));
    gizmo.cancel(editor);
    CHECK(editor.level().find(id)->position == Vec3(0.0f));
    CHECK_FALSE(editor.history().can_redo());

    gizmo.mode = GizmoMode::Rotate;
    const float r = s.length / wpp; // ring radius in pixels
    const Vec2 east = s.centre + Vec2(r, 0), north = s.centre + Vec2(0, -r);
    REQUIRE(gizmo.hit(top, Vec3(0.0f), east) == Handle::RingY);
    const float yaw0 = editor.level().find(id)->rotation.x;
    gizmo.begin(editor, top, Vec3(0.0f), Handle::RingY, east);
    gizmo.drag(editor, top, s.centre + Vec2(r * 0.707f, -r * 0.66f)); // about 43 degrees: snaps to 45
    CHECK(std::remainder(editor.level().find(id)->rotation.x - yaw0, 360.0f) == doctest::Approx(45.0f));
    gizmo.drag(editor, top, north); // a quarter turn counterclockwise seen from above: +90
    CHECK(std::remainder(editor.level().find(id)->rotation.x - yaw0, 360.0f) == doctest::Approx(90.0f));
    gizmo.end(editor);
    editor.undo();
    CHECK(editor.level().find(id)->rotation.x == doctest::Approx(yaw0));
}

TEST_CASE("front view: the y arrow lifts, the x arrow slides; perspective drags follow the mouse") {
    Editor editor = one_robot(Vec3(0, 0, 0));
    const int id = editor.doc().selection.front();
    const ViewCamera front = axis_view(ViewMode::Front, Vec3(0.0f), 60.0f);
    const float wpp = front.world_per_pixel(Vec3(0.0f));
    const GizmoShape s = gizmo_shape(front, Vec3(0.0f));
    Gizmo gizmo;
    const Vec2 grab = midpoint(s.centre, s.tips[1]);
    REQUIRE(gizmo.hit(front, Vec3(0.0f), grab) == Handle::AxisY);
    gizmo.begin(editor, front, Vec3(0.0f), Handle::AxisY, grab);
    gizmo.drag(editor, front, grab + Vec2(0, -40));
    gizmo.end(editor);
    CHECK(editor.level().find(id)->position.y == doctest::Approx(std::round(40.0f * wpp)));

    ViewCamera persp;
    persp.set_viewport(kViewport);
    persp.camera.position = Vec3(0, 20, 30);
    persp.camera.pitch = radians(-30.0f);
    const Vec3 pivot = editor.level().find(id)->position;
    const GizmoShape ps = gizmo_shape(persp, pivot);
    const Vec2 grab_x = midpoint(ps.centre, ps.tips[0]);
    REQUIRE(gizmo.hit(persp, pivot, grab_x) == Handle::AxisX);
    editor.grid().snap = false;
    gizmo.begin(editor, persp, pivot, Handle::AxisX, grab_x);
    gizmo.drag(editor, persp, ps.tips[0]); // drag the middle of the arrow to its tip: half a handle length
    gizmo.end(editor);
    CHECK(editor.level().find(id)->position.x == doctest::Approx(pivot.x + ps.length * 0.5f).epsilon(1e-3));
}
