// Turning about three axes, without a window: which types may pitch and roll, the yaw, pitch and roll after
// world and local turns (composed as quaternions, gimbal lock included), snapping, one undo step per turn or
// ring drag, the rings the gizmo offers, and the script's axis forms.
#include "editor_test_util.h"
#include "model/edit_entities.h"
#include "model/edit_selection.h"
#include "model/edit_transforms.h"
#include "model/rotation.h"
#include "model/script.h"
#include "view/gizmo.h"

using namespace ks;
using namespace ks::editor;

using editor_test::kViewport;

namespace {

// Two orientations are the same when they turn every axis the same way.
float orientation_difference(const Vec3& ypr_a, const Vec3& ypr_b) {
    auto q = [](const Vec3& v) { return quat_from_ypr(radians(v.x), radians(v.y), radians(v.z)); };
    const Mat3 a = glm::mat3_cast(q(ypr_a)), b = glm::mat3_cast(q(ypr_b));
    float worst = 0.0f;
    for (int c = 0; c < 3; ++c) worst = std::max(worst, glm::length(a[c] - b[c]));
    return worst;
}

Quat axis_turn(int axis, float degrees) {
    Vec3 unit(0.0f);
    unit[axis] = 1.0f;
    return glm::angleAxis(radians(degrees), unit);
}

Vec3 ypr_of(const Quat& q) {
    const DVec3 d = ypr_degrees_from_quat(glm::dquat(q.w, q.x, q.y, q.z));
    return Vec3(d);
}

Editor one(level::EntityType type, Vec3 at = Vec3(0.0f)) {
    Editor e;
    e.grid().step = 1.0f;
    REQUIRE(place(e, type, at).ok());
    return e;
}
} // namespace

TEST_CASE("world and local turns compose like quaternions") {
    const Vec3 start(30.0f, 20.0f, -10.0f);
    const Quat q = quat_from_ypr(radians(start.x), radians(start.y), radians(start.z));
    for (int axis = 0; axis < 3; ++axis)
        for (float degrees : {15.0f, -45.0f, 90.0f}) {
            CAPTURE(axis);
            CAPTURE(degrees);
            const Vec3 world = turned_ypr(start, axis, degrees, RotationSpace::World);
            const Vec3 local = turned_ypr(start, axis, degrees, RotationSpace::Local);
            CHECK(orientation_difference(world, ypr_of(axis_turn(axis, degrees) * q)) < 1e-4f);
            CHECK(orientation_difference(local, ypr_of(q * axis_turn(axis, degrees))) < 1e-4f);
            CHECK(local.y >= -90.0f);
            CHECK(local.y <= 90.0f);
        }
    // The turns that move one angle alone add to it exactly: world y is the yaw, local z the roll.
    CHECK(turned_ypr(start, 1, 45.0f, RotationSpace::World) == Vec3(75.0f, 20.0f, -10.0f));
    CHECK(turned_ypr(start, 2, 15.0f, RotationSpace::Local) == Vec3(30.0f, 20.0f, 5.0f));
    CHECK(turned_ypr({170.0f, 0, 0}, 1, 30.0f, RotationSpace::Local) == Vec3(-160.0f, 0, 0)); // wrapped
    // Quarter turns come back as whole numbers (the read-back noise is rounded off).
    CHECK(turned_ypr(Vec3(0.0f), 0, 90.0f, RotationSpace::Local) == Vec3(0.0f, 90.0f, 0.0f));
    CHECK(turned_ypr(Vec3(0.0f), 0, -45.0f, RotationSpace::World) == Vec3(0.0f, -45.0f, 0.0f));
}

TEST_CASE("gimbal lock: a wall pitched straight up still turns correctly about every axis") {
    Vec3 ypr = turned_ypr(Vec3(0.0f), 0, 90.0f, RotationSpace::Local); // pitch 90: yaw and roll share an axis
    REQUIRE(ypr == Vec3(0.0f, 90.0f, 0.0f));
    const Quat locked = quat_from_ypr(0.0f, radians(90.0f), 0.0f);
    for (int axis = 0; axis < 3; ++axis)
        for (RotationSpace space : {RotationSpace::World, RotationSpace::Local}) {
            CAPTURE(axis);
            const Vec3 turned = turned_ypr(ypr, axis, 30.0f, space);
            CHECK(is_finite(turned));
            const Quat expected = space == RotationSpace::World ? axis_turn(axis, 30.0f) * locked
                                                                : locked * axis_turn(axis, 30.0f);
            CHECK(orientation_difference(turned, ypr_of(expected)) < 1e-4f);
        }
    // A turn that lands on the lock folds the roll into the yaw: pitch 80, roll 20 turned 10 more about
    // world x is pitch 90, where only yaw - roll is defined (-20).
    const Vec3 folded = turned_ypr({0.0f, 80.0f, 20.0f}, 0, 10.0f, RotationSpace::World);
    CHECK(folded == Vec3(-20.0f, 90.0f, 0.0f));
    CHECK(orientation_difference(folded, {0.0f, 90.0f, 20.0f}) < 1e-5f);
    CHECK(turned_ypr(ypr, 1, 30.0f, RotationSpace::World) == Vec3(30.0f, 90.0f, 0.0f));
    // Many small turns through the lock and back leave no drift.
    for (int i = 0; i < 12; ++i) ypr = turned_ypr(ypr, 0, 15.0f, RotationSpace::Local);
    for (int i = 0; i < 12; ++i) ypr = turned_ypr(ypr, 0, -15.0f, RotationSpace::Local);
    CHECK(orientation_difference(ypr, Vec3(0.0f, 90.0f, 0.0f)) < 1e-4f);
}

TEST_CASE("only walls, floors, stairs and control panels turn about x and z; one undo step each") {
    Editor editor = one(level::EntityType::Wall, Vec3(0, 0, 0));
    const int wall = editor.doc().selection.front();
    CHECK(selection_turns_on_three_axes(editor.doc()));
    const size_t steps = editor.history().undo_count();
    REQUIRE(rotate_selection_about(editor, 0, 28.0f, RotationSpace::Local).ok()); // snapped to 30
    CHECK(editor.level().find(wall)->rotation == Vec3(0.0f, 30.0f, 0.0f));
    REQUIRE(rotate_selection_about(editor, 2, 7.0f, RotationSpace::Local, false).ok()); // free: as given
    CHECK(editor.level().find(wall)->rotation == Vec3(0.0f, 30.0f, 7.0f));
    CHECK(editor.history().undo_count() == steps + 2);
    editor.undo();
    editor.undo();
    CHECK(editor.level().find(wall)->rotation == Vec3(0.0f));

    REQUIRE(place(editor, level::EntityType::Robot, Vec3(5, 0, 0)).ok());
    REQUIRE(select(editor, {wall}, SelectMode::Add).ok());
    CHECK_FALSE(selection_turns_on_three_axes(editor.doc()));
    const std::string before = editor_test::text_of(editor);
    const auto refused = rotate_selection_about(editor, 2, 30.0f, RotationSpace::World);
    REQUIRE_FALSE(refused.ok());
    CHECK(refused.error().message.find("robot 2 turns about y only") != std::string::npos);
    CHECK(refused.error().message.find("wall, floor, stair, control_panel") != std::string::npos);
    CHECK(editor_test::text_of(editor) == before);                                // nothing changed
    REQUIRE(rotate_selection_about(editor, 1, 90.0f, RotationSpace::World).ok()); // y: both turn
    CHECK(editor.level().find(wall)->rotation.x == 90.0f);
    CHECK(editor.level().find(2)->rotation.x == 90.0f);
    // World turns swing the selection about its centre; local turns keep each in place.
    CHECK(editor.level().find(2)->position == Vec3(2.5f, 0, -2.5f));
    REQUIRE(rotate_selection_about(editor, 1, 90.0f, RotationSpace::Local).ok());
    CHECK(editor.level().find(2)->position == Vec3(2.5f, 0, -2.5f));
}

TEST_CASE("a group of walls turned about world x moves as one rigid piece") {
    Editor editor;
    editor.grid().step = 1.0f;
    REQUIRE(place(editor, level::EntityType::Wall, Vec3(0, 0, -4)).ok());
    REQUIRE(place(editor, level::EntityType::Wall, Vec3(0, 0, 4)).ok());
    select_all(editor);
    REQUIRE(rotate_selection_about(editor, 0, 90.0f, RotationSpace::World).ok());
    // Pivot (0, 0, 0): a right-handed turn about x takes +z to -y.
    CHECK(editor.level().find(1)->position == Vec3(0, 4, 0));
    CHECK(editor.level().find(2)->position == Vec3(0, -4, 0));
    CHECK(editor.level().find(1)->rotation == Vec3(0, 90, 0));
}

TEST_CASE("the gizmo offers three rings where the selection pitches and rolls, in world or local axes") {
    Editor editor = one(level::EntityType::Wall);
    const int wall = editor.doc().selection.front();
    REQUIRE(rotate_selection_about(editor, 1, 30.0f, RotationSpace::World).ok());
    ViewCamera persp;
    persp.set_viewport(kViewport);
    persp.camera.position = Vec3(12, 10, 14);
    persp.camera.yaw = radians(40.0f);
    persp.camera.pitch = radians(-30.0f);
    const GizmoFrame world = gizmo_frame(editor.doc(), RotationSpace::World);
    CHECK(world.three_axes);
    CHECK(world.axes == Mat3(1.0f));
    const GizmoShape s = gizmo_shape(persp, world);
    CHECK(s.ring_visible[0]);
    CHECK(s.ring_visible[1]);
    CHECK(s.ring_visible[2]);
    const GizmoFrame local = gizmo_frame(editor.doc(), RotationSpace::Local);
    CHECK(glm::length(local.axes[0] - glm::mat3_cast(editor.level().find(wall)->orientation())[0]) < 1e-6f);

    // Drag the local x ring a quarter of the way round: the wall pitches, one step, snapped.
    Gizmo gizmo;
    gizmo.mode = GizmoMode::Rotate;
    gizmo.space = RotationSpace::Local;
    const GizmoShape ls = gizmo_shape(persp, local);
    const int quarter = kGizmoRingSegments / 4;
    REQUIRE(gizmo_hit(GizmoMode::Rotate, ls, ls.rings[0][0]) == Handle::RingX);
    const size_t steps = editor.history().undo_count();
    gizmo.begin(editor, persp, local, Handle::RingX, ls.rings[0][0]);
    CHECK(gizmo.drag(editor, persp, ls.rings[0][quarter / 2]).empty()); // about 45 degrees
    CHECK(gizmo.drag(editor, persp, ls.rings[0][quarter]).empty());     // 90
    gizmo.end(editor);
    CHECK(editor.history().undo_count() == steps + 1);
    const Vec3 r = editor.level().find(wall)->rotation;
    CHECK(orientation_difference(r, turned_ypr(Vec3(30, 0, 0), 0, 90.0f, RotationSpace::Local)) < 1e-3f);
    CHECK(gizmo.readout().empty());
    editor.undo();
    CHECK(editor.level().find(wall)->rotation == Vec3(30, 0, 0));

    // Ctrl held (free): the same drag stops where the mouse is, between the snapping steps.
    gizmo.begin(editor, persp, local, Handle::RingX, ls.rings[0][0]);
    gizmo.drag(editor, persp, (ls.rings[0][1] + ls.rings[0][2]) * 0.5f, true); // about 11 degrees
    CHECK(gizmo.readout().find("rotate x +") != std::string::npos);
    CHECK(gizmo.readout().find("(local)") != std::string::npos);
    gizmo.end(editor);
    const float pitch = editor.level().find(wall)->rotation.y;
    CHECK(pitch > 5.0f);
    CHECK(pitch < 14.0f);
    CHECK(std::fmod(pitch, 15.0f) != 0.0f);

    // A robot gets the yaw ring only.
    REQUIRE(place(editor, level::EntityType::Robot, Vec3(6, 0, 0)).ok());
    const GizmoShape robot = gizmo_shape(persp, gizmo_frame(editor.doc(), RotationSpace::World));
    CHECK_FALSE(robot.ring_visible[0]);
    CHECK(robot.ring_visible[1]);
    CHECK_FALSE(robot.ring_visible[2]);
}

TEST_CASE("the script's rotate takes an axis and a space; the old form still turns the yaw") {
    Editor editor;
    const char* script = R"(grid 1 15
place wall at 0,0,0
rotate 30
expect field 1 rotation 30,0,0
rotate x 45 local
expect field 1 rotation 30,45,0
rotate z -15 local
expect field 1 rotation 30,45,-15
undo 2
rotate y 90 world
expect field 1 rotation 120,0,0
place robot at 5,0,0
)";
    auto report = run_script_text(script, "rotate.kss", {}, editor);
    REQUIRE_MESSAGE(report.ok(), report.error().str());
    auto refused = run_script_text("rotate x 30\n", "robot.kss", {}, editor);
    REQUIRE_FALSE(refused.ok());
    CHECK(refused.error().str().find("rotate.kss") == std::string::npos);
    CHECK(refused.error().str().find("robot.kss:1") != std::string::npos);
    for (const char* bad :
         {"rotate w 30\n", "rotate x\n", "rotate x 30 sideways\n", "rotate 30 world extra\n"})
        CHECK_FALSE(parse_script(bad, "bad.kss").ok());
}
