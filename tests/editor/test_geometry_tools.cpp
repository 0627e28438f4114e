// The geometry tools' state machines (tool_draw.h, tool_clip.h, tool_measure.h), the pointer that feeds
// them (view/tool_pointer.h) and their script lines: each commit one undo step, every refusal leaving the
// level and the history as they were.
#include "editor_test_util.h"
#include "model/edit_brushes.h"
#include "model/edit_selection.h"
#include "model/tool_clip.h"
#include "model/tool_draw.h"
#include "model/tool_measure.h"
#include "view/tool_pointer.h"

#include "level/entity_shapes.h"

#include <algorithm>

using namespace ks;
using namespace ks::editor;

namespace {

bool gt_has_label(const ToolPreview& p, const std::string& text) {
    return std::any_of(p.labels.begin(), p.labels.end(), [&](const ToolLabel& l) { return l.text == text; });
}

const DrawPlane kGtTopPlane{1, 0.0, std::nullopt};

} // namespace

TEST_CASE("draw tool: a box dragged in the top view shows its size live and commits as one undo step") {
    Editor ed;
    DrawTool tool;
    tool.press(kGtTopPlane, {0, 0, 0});
    tool.move({4, 0, 2});
    CHECK(tool.stage() == DrawStage::dragging);
    const ToolPreview live = tool.preview();
    CHECK(live.segments.size() == 12);
    CHECK(gt_has_label(live, "4.000 \xC3\x97 2.000 \xC3\x97 1.000")); // width x depth x the grid step
    CHECK(gt_has_label(live, "4.000"));                               // the edge lengths
    CHECK(gt_has_label(live, "2.000"));
    CHECK(live.problem.empty());
    tool.step_height(2); // ] twice
    CHECK(tool.height() == 3.0);
    auto id = tool.release(ed);
    REQUIRE_MESSAGE(id.ok(), (id.ok() ? "" : id.error().str()));
    CHECK(tool.stage() == DrawStage::idle);
    CHECK(editor_test::world_brush_of(ed, *id).bounds_min() == DVec3(0, 0, 0));
    CHECK(editor_test::world_brush_of(ed, *id).bounds_max() == DVec3(4, 3, 2));
    CHECK(ed.history().undo_count() == 1);

    // The next box in the top view takes the last one's height range; in the front view its depth range.
    tool.press(kGtTopPlane, {6, 0, 0});
    tool.move({8, 0, 2});
    CHECK(tool.dimensions() == DVec3(2, 3, 2));
    REQUIRE(tool.release(ed).ok());
    tool.press({2, 0.0, std::nullopt}, {0, 0, 7});
    tool.move({2, 5, 7});
    CHECK(*tool.bounds() == std::array{DVec3(0, 0, 0), DVec3(2, 5, 2)});
    tool.cancel();
    CHECK(ed.undo());
    CHECK(editor_test::brush_count(ed) == 1);
}

TEST_CASE("draw tool: in an axis view the selection's range along the view axis wins over the last brush's") {
    Editor ed;
    DrawTool tool;
    tool.press(kGtTopPlane, {0, 0, 0}); // the last brush: z from 0 to 9
    tool.move({4, 0, 9});
    REQUIRE(tool.release(ed).ok());
    // A wall selected (z 3 to 4): the doorway drawn in the front view goes through it, not the last range.
    tool.reference = std::array{DVec3(-5, 0, 3), DVec3(5, 8, 4)};
    const DrawPlane front{2, 0.0, std::nullopt};
    tool.press(front, {0, 0, 0});
    tool.move({2, 3, 0});
    CHECK(*tool.bounds() == std::array{DVec3(0, 0, 3), DVec3(2, 3, 4)});
    tool.set_height(3.0); // a typed depth keeps the start of the range
    CHECK(*tool.bounds() == std::array{DVec3(0, 0, 3), DVec3(2, 3, 6)});
    tool.cancel();
    // A polygon takes it too; a flat selection (no size along the axis) is ignored for the last brush's.
    REQUIRE(tool.add_point(front, {0, 0, 0}).ok());
    CHECK(tool.preview().problem.empty());
    tool.cancel();
    tool.reference = std::array{DVec3(-5, 0, 2), DVec3(5, 8, 2)};
    tool.press(front, {0, 0, 0});
    tool.move({2, 3, 0});
    CHECK(*tool.bounds() == std::array{DVec3(0, 0, 0), DVec3(2, 3, 9)});
    tool.cancel();
    // In perspective (a plane that grows) the reference is not used.
    tool.press({1, 0.0, 1}, {0, 0, 0});
    tool.move({2, 0, 2});
    CHECK((*tool.bounds())[1].y == 1.0);
}

TEST_CASE(
    "draw tool: a zero-size or one-axis drag, and a box beyond the world, are refused and change nothing") {
    Editor ed;
    const std::string before = editor_test::text_of(ed);
    DrawTool tool;
    tool.press(kGtTopPlane, {3, 0, 3});
    CHECK(tool.preview().problem == "the box has no size along x");
    auto click = tool.release(ed);
    REQUIRE_FALSE(click.ok());
    CHECK(click.error().message == "Draw: the box has no size along x");
    tool.press(kGtTopPlane, {0, 0, 0});
    tool.move({5, 0, 0});
    auto line = tool.release(ed);
    REQUIRE_FALSE(line.ok());
    CHECK(line.error().message == "Draw: the box has no size along z");
    tool.press(kGtTopPlane, {1e6, 0, 1e6});
    tool.move({1e6 + 8, 0, 1e6 + 8});
    auto far = tool.release(ed);
    REQUIRE_FALSE(far.ok());
    CHECK(far.error().message.find("Place box brush") != std::string::npos);
    CHECK(tool.stage() == DrawStage::idle);
    CHECK(editor_test::text_of(ed) == before);
    CHECK(ed.history().undo_count() == 0);
}

TEST_CASE("draw tool: on a face in perspective the box grows out of the face by the height") {
    Editor ed;
    DrawTool tool;
    tool.set_height(2.0);               // typed before the drag
    tool.press({0, 4.0, 1}, {4, 0, 0}); // the +x face of a brush at x = 4
    tool.move({4, 3, 5});
    CHECK(*tool.bounds() == std::array{DVec3(4, 0, 0), DVec3(6, 3, 5)});
    tool.cancel();
    tool.press({0, 0.0, -1}, {0, 0, 0}); // a -x face: grows toward -x
    tool.move({0, 1, 1});
    CHECK(*tool.bounds() == std::array{DVec3(-2, 0, 0), DVec3(0, 1, 1)});
    REQUIRE(tool.release(ed).ok());
}

TEST_CASE("draw tool: a polygon is clicked, closed on its first corner, extruded by the mouse and placed") {
    Editor ed;
    DrawTool tool;
    tool.shape = DrawShape::polygon;
    REQUIRE(tool.add_point(kGtTopPlane, {0, 0, 0}).ok());
    REQUIRE(tool.add_point(kGtTopPlane, {4, 7, 0}).ok()); // off the plane: taken onto it
    CHECK(tool.points().back() == DVec3(4, 0, 0));
    auto twice = tool.add_point(kGtTopPlane, {4, 0, 0});
    REQUIRE_FALSE(twice.ok());
    CHECK(twice.error().message == "Draw: the point repeats corner 2");
    REQUIRE(tool.add_point(kGtTopPlane, {4, 0, 4}).ok());
    CHECK(gt_has_label(tool.preview(), "4.000"));         // edge lengths while placing
    REQUIRE(tool.add_point(kGtTopPlane, {0, 0, 0}).ok()); // the first corner closes
    CHECK(tool.stage() == DrawStage::extruding);
    // A ray passing the vertical line through the centre (8/3, y, 4/3) at height 5.
    tool.extrude_toward({Vec3(20.0f, 5.0f, 4.0f / 3.0f), Vec3(-1, 0, 0)});
    CHECK(tool.height() == doctest::Approx(5.0));
    tool.extrude_toward({Vec3(0, 10, 0), Vec3(0, -1, 0)}); // along the axis: no height shown, kept
    CHECK(tool.height() == doctest::Approx(5.0));
    auto id = tool.commit(ed);
    REQUIRE_MESSAGE(id.ok(), (id.ok() ? "" : id.error().str()));
    CHECK(editor_test::world_brush_of(ed, *id).volume() == doctest::Approx(8.0 * 5.0));
    CHECK(ed.history().undo_count() == 1);
}

TEST_CASE("draw tool: non-convex, collinear and too-small polygons are refused with the reason") {
    Editor ed;
    DrawTool tool;
    tool.shape = DrawShape::polygon;
    for (DVec3 p : {DVec3(0, 0, 0), DVec3(4, 0, 0), DVec3(1, 0, 1), DVec3(0, 0, 4)})
        REQUIRE(tool.add_point(kGtTopPlane, p).ok());
    auto dent = tool.close();
    REQUIRE_FALSE(dent.ok());
    CHECK(dent.error().message.find("not strictly convex") != std::string::npos);
    CHECK(dent.error().message.find("(corner 3)") != std::string::npos);
    CHECK(tool.stage() == DrawStage::placing_points);
    tool.remove_last_point(); // Backspace, twice: (0,0,0) (4,0,0) remain
    tool.remove_last_point();
    auto two = tool.close();
    REQUIRE_FALSE(two.ok());
    CHECK(two.error().message == "Draw: a polygon needs at least 3 corners, it has 2");
    REQUIRE(tool.add_point(kGtTopPlane, {8, 0, 0}).ok());
    auto line = tool.commit(ed);
    REQUIRE_FALSE(line.ok());
    CHECK(line.error().message.find("cannot be extruded") != std::string::npos);
    CHECK(editor_test::brush_count(ed) == 0);
    CHECK(ed.history().undo_count() == 0);
}

namespace {
// A 4 x 4 x 4 box brush at the origin corner, selected.
int gt_cube(Editor& ed, DVec3 lo = DVec3(0), DVec3 hi = DVec3(4)) {
    auto id = place_box_brush(ed, Vec3(lo), Vec3(hi));
    REQUIRE(id.ok());
    return *id;
}
} // namespace

TEST_CASE("clip tool: three points preview the cut on the selected brush; Enter keeps the chosen side") {
    Editor ed;
    const int cube = gt_cube(ed);
    ClipTool tool;
    CHECK(tool.preview(ed.doc()).problem == "no plane yet");
    REQUIRE(tool.add_point({2, 0, 0}).ok());
    REQUIRE(tool.add_point({2, 1, 0}).ok());
    CHECK(tool.preview(ed.doc()).problem == "two points make a plane only in an axis view");
    REQUIRE(tool.add_point({2, 0, 1}).ok());
    const auto plane = tool.plane();
    REQUIRE(plane.ok());
    CHECK(plane->normal == DVec3(1, 0, 0));
    const ToolPreview shown = tool.preview(ed.doc());
    CHECK(shown.problem.empty());
    const auto cut = std::count_if(shown.segments.begin(), shown.segments.end(),
                                   [](const ToolSegment& s) { return s.kind == ToolLine::cut; });
    CHECK(cut == 4); // the square where x = 2 crosses the cube
    for (const ToolSegment& s : shown.segments)
        if (s.kind == ToolLine::cut) CHECK(s.a.x == doctest::Approx(2.0));
    CHECK(gt_has_label(shown, "keep back"));
    tool.cycle_keep();
    CHECK(tool.keep() == ClipKeep::front);
    REQUIRE(tool.apply(ed).ok());
    CHECK(editor_test::world_brush_of(ed, cube).bounds_min().x == doctest::Approx(2.0));
    CHECK(editor_test::world_brush_of(ed, cube).bounds_max().x == doctest::Approx(4.0));
    CHECK_FALSE(tool.busy());
    CHECK(ed.history().undo_count() == 2);
    REQUIRE(ed.undo());
    CHECK(editor_test::world_brush_of(ed, cube).bounds_min().x == doctest::Approx(0.0));
}

TEST_CASE("clip tool: the cut's outline on a turned brush lies on the plane and inside the brush") {
    Editor ed;
    auto report = run_script_text("brush box 0,0,0 4,4,4\nrotate y 45\n", "turned.kss", {}, ed);
    REQUIRE_MESSAGE(report.ok(), (report.ok() ? std::string() : report.error().str()));
    const brush::Brush world = editor_test::world_brush_of(ed, ed.doc().selection.front());
    ClipTool tool;
    for (DVec3 p : {DVec3(2, 0, 0), DVec3(2, 1, 0), DVec3(2, 0, 1)}) REQUIRE(tool.add_point(p).ok());
    const ToolPreview shown = tool.preview(ed.doc());
    CHECK(shown.problem.empty());
    int cut = 0;
    for (const ToolSegment& s : shown.segments) {
        if (s.kind != ToolLine::cut) continue;
        ++cut;
        CHECK(s.a.x == doctest::Approx(2.0));
        for (const brush::Face& f : world.faces()) CHECK(f.plane.signed_distance(s.a) <= 1e-9);
    }
    CHECK(cut == 4); // the turned cube cut straight across: a rectangle

    // The pointer finds the turned brush's top face and its corners too.
    const ViewCamera top = editor_test::top_view(Vec3(2, 0, 2));
    Vec2 corner;
    REQUIRE(top.project(Vec3(world.bounds_max().x, 4.0f, 2.0f), corner));
    auto vertex = tool_point(ed.doc(), top, corner + Vec2(-2, 0), editor_test::all_shown);
    REQUIRE(vertex);
    CHECK(vertex->kind == PointKind::vertex);
    CHECK(vertex->point.x == doctest::Approx(world.bounds_max().x));
    CHECK(vertex->point.y == doctest::Approx(4.0));
}

TEST_CASE("clip tool: two points in an axis view make a plane containing the view direction; keep both") {
    Editor ed;
    gt_cube(ed);
    ClipTool tool;
    tool.set_view_direction(DVec3(0, -1, 0)); // the top view
    REQUIRE(tool.add_point({2, 0, -1}).ok());
    auto same = tool.add_point({2, 0, -1});
    REQUIRE_FALSE(same.ok());
    CHECK(same.error().message == "Clip: the point repeats point 1");
    REQUIRE(tool.add_point({2, 0, 5}).ok());
    REQUIRE(tool.plane().ok());
    CHECK(tool.plane()->normal == DVec3(1, 0, 0));
    tool.set_keep(ClipKeep::both);
    REQUIRE(tool.apply(ed).ok());
    CHECK(editor_test::brush_count(ed) == 2);

    ClipTool straight; // two points one above the other, seen from the top
    straight.set_view_direction(DVec3(0, -1, 0));
    REQUIRE(straight.add_point({1, 0, 1}).ok());
    REQUIRE(straight.add_point({1, 3, 1}).ok());
    REQUIRE_FALSE(straight.plane().ok());
    CHECK(straight.plane().error().message == "Clip: the two points line up with the view direction");
}

TEST_CASE("clip tool: collinear points, a plane missing the brush and a clip leaving nothing are refused") {
    Editor ed;
    const int cube = gt_cube(ed);
    const std::string before = editor_test::text_of(ed);
    ClipTool line;
    for (DVec3 p : {DVec3(0, 0, 0), DVec3(1, 1, 1), DVec3(3, 3, 3)}) REQUIRE(line.add_point(p).ok());
    CHECK(line.preview(ed.doc()).problem == "the three points lie on one line");
    REQUIRE_FALSE(line.apply(ed).ok());

    ClipTool miss;
    for (DVec3 p : {DVec3(10, 0, 0), DVec3(10, 1, 0), DVec3(10, 0, 1)}) REQUIRE(miss.add_point(p).ok());
    CHECK(miss.preview(ed.doc()).problem == "the plane misses the selected brushes");
    auto missed = miss.apply(ed);
    REQUIRE_FALSE(missed.ok());
    CHECK(missed.error().message == "Clip: the plane misses the selected brushes");
    miss.set_keep(ClipKeep::front); // the cube lies wholly behind x = 10
    CHECK(miss.preview(ed.doc()).problem == "the clip would leave nothing of brush " + std::to_string(cube));
    auto emptied = miss.apply(ed);
    REQUIRE_FALSE(emptied.ok());
    CHECK(emptied.error().message.find("leaves nothing") != std::string::npos);

    ClipTool along; // the plane of the cube's -x face: it cuts nothing, and keeping the back leaves nothing
    for (DVec3 p : {DVec3(0, 0, 0), DVec3(0, 1, 0), DVec3(0, 0, 1)}) REQUIRE(along.add_point(p).ok());
    CHECK(along.preview(ed.doc()).problem == "the clip would leave nothing of brush " + std::to_string(cube));
    REQUIRE_FALSE(along.apply(ed).ok());

    ed.clear_selection();
    ClipTool none;
    for (DVec3 p : {DVec3(2, 0, 0), DVec3(2, 1, 0), DVec3(2, 0, 1)}) REQUIRE(none.add_point(p).ok());
    CHECK(none.preview(ed.doc()).problem == "no brush is selected");
    REQUIRE_FALSE(none.apply(ed).ok());
    CHECK(editor_test::text_of(ed) == before);
    CHECK(ed.history().undo_count() == 1);
}

TEST_CASE("clip tool: match a face cuts by that face's plane; a fourth point starts a new plane") {
    Editor ed;
    const int low = gt_cube(ed);
    const int tall = gt_cube(ed, {6, 0, 0}, {8, 10, 2});
    const brush::Brush lows = editor_test::world_brush_of(ed, low);
    const auto top = std::find_if(lows.faces().begin(), lows.faces().end(),
                                  [](const brush::Face& f) { return f.plane.normal.y > 0.5; });
    REQUIRE(top != lows.faces().end());
    ClipTool tool;
    REQUIRE(tool.add_point({0, 0, 0}).ok());
    tool.match_face(top->plane);
    CHECK(tool.points().empty());
    REQUIRE(select(ed, {tall}).ok());
    REQUIRE(tool.apply(ed).ok());
    CHECK(editor_test::world_brush_of(ed, tall).bounds_max().y == doctest::Approx(4.0));

    ClipTool again;
    for (DVec3 p : {DVec3(0, 0, 0), DVec3(1, 0, 0), DVec3(0, 1, 0), DVec3(5, 5, 5)})
        REQUIRE(again.add_point(p).ok());
    CHECK(again.points() == std::vector<DVec3>{DVec3(5, 5, 5)});
    again.cycle_keep();
    again.cycle_keep();
    again.cycle_keep();
    CHECK(again.keep() == ClipKeep::back);
}

TEST_CASE("measuring tool: distance and angle to the horizontal to 1 mm, live to the mouse, far out too") {
    MeasureTool tool;
    CHECK_FALSE(tool.measurement());
    tool.add_point({0, 0, 0});
    tool.hover(DVec3(4, 3, 0));
    REQUIRE(tool.measurement());
    CHECK(tool.measurement()->distance == doctest::Approx(5.0));
    CHECK(angle_text(tool.measurement()->rise_degrees) == "36.870\xC2\xB0");
    tool.add_point({0, -2, 0}); // straight down
    CHECK(measurement_text(*tool.measurement()) ==
          "distance 2.000  angle -90.000\xC2\xB0  (dx 0.000, dy -2.000, dz 0.000)");
    CHECK(gt_has_label(tool.preview(), measurement_text(*tool.measurement())));
    tool.add_point({1, 1, 1}); // a third click starts again
    CHECK(tool.busy());
    tool.hover(DVec3(1, 1, 1)); // the same point: no length, level
    CHECK(tool.measurement()->distance == 0.0);
    CHECK(tool.measurement()->rise_degrees == 0.0);
    const Measurement far = measure({65000.0, -65000.0, 65000.0}, {65000.001, -65000.0, 65000.0});
    CHECK(length_text(far.distance) == "0.001");
    CHECK(length_text(-0.0004) == "0.000");
}

TEST_CASE("tool pointer: a vertex near the mouse, else the face the ray enters, else the grid") {
    Editor ed;
    gt_cube(ed);
    ed.clear_selection();
    const ViewCamera top = editor_test::top_view(Vec3(2, 0, 2));
    Vec2 corner;
    REQUIRE(top.project(Vec3(4, 4, 4), corner));
    auto vertex = tool_point(ed.doc(), top, corner + Vec2(-3, -2), editor_test::all_shown);
    REQUIRE(vertex);
    CHECK(vertex->kind == PointKind::vertex);
    CHECK(vertex->point == DVec3(4, 4, 4)); // the top corner, nearer the eye than the bottom one
    Vec2 middle;
    REQUIRE(top.project(Vec3(1.2f, 4, 2.9f), middle));
    auto face = tool_point(ed.doc(), top, middle, editor_test::all_shown);
    REQUIRE(face);
    CHECK(face->kind == PointKind::face);
    CHECK(face->point == DVec3(1, 4, 3)); // on the top, snapped across it
    REQUIRE(face->face);
    CHECK(face->face->normal == DVec3(0, 1, 0));
    Vec2 outside;
    REQUIRE(top.project(Vec3(10.4f, 0, -6.2f), outside));
    auto grid = tool_point(ed.doc(), top, outside, editor_test::all_shown);
    REQUIRE(grid);
    CHECK(grid->kind == PointKind::grid);
    CHECK(grid->point == DVec3(10, 0, -6));
    auto only_grid = tool_point(ed.doc(), top, middle, editor_test::all_shown, {false, false});
    CHECK(only_grid->kind == PointKind::grid);
    CHECK(draw_plane_at(*face, top).axis == 1);
    CHECK_FALSE(draw_plane_at(*face, top).grows);

    ViewCamera eye;
    eye.set_viewport(editor_test::kViewport);
    eye.camera.position = Vec3(2, 10, 20);
    eye.camera.yaw = 0.0f;
    eye.camera.pitch = -0.5f;
    const ToolPoint side{DVec3(4, 2, 2), PointKind::face, brush::Plane{DVec3(1, 0, 0), 4.0}, 1};
    const DrawPlane plane = draw_plane_at(side, eye);
    CHECK(plane.axis == 0);
    CHECK(plane.level == 4.0);
    CHECK(plane.grows == 1);
}

TEST_CASE("tool script lines draw, extrude, clip and measure; bad words are reported at their column") {
    Editor ed;
    const char* script = R"(grid 1
tool draw top 0,0,0 4,0,4 height 3
tool polygon perspective 10,0,0 14,0,0 12,0,3 height 2
select 1
tool clip top 2,0,-1 2,0,5 keep both
expect count brush 3
tool clip match 2 1 keep front
tool measure 0,0,0 3,4,0 is 5 53.130
)";
    auto report = run_script_text(script, "tools.kss", {}, ed);
    REQUIRE_MESSAGE(report.ok(), (report.ok() ? std::string() : report.error().str()));
    CHECK(report->expectations_checked == 3);

    Editor fresh;
    auto one = run_script_text("tool draw top 0,0,0\n", "one.kss", {}, fresh);
    REQUIRE_FALSE(one.ok());
    CHECK(one.error().str().find("one.kss:1:20: a box is dragged from one corner to another") !=
          std::string::npos);
    auto view = run_script_text("tool clip perspective 0,0,0 1,0,0\n", "view.kss", {}, fresh);
    REQUIRE_FALSE(view.ok());
    CHECK(view.error().str().find("view.kss:1:11: two-point clips need an axis view") != std::string::npos);
    auto flat = run_script_text("tool draw front 0,0,0 0,3,0\n", "flat.kss", {}, fresh);
    REQUIRE_FALSE(flat.ok());
    CHECK(flat.error().str().find("flat.kss:1: Draw: the box has no size along x") != std::string::npos);
    auto wrong = run_script_text("tool measure 0,0,0 1,0,0 is 2\n", "wrong.kss", {}, fresh);
    REQUIRE_FALSE(wrong.ok());
    CHECK(wrong.error().str().find("measured 1.000, expected 2.000") != std::string::npos);
}
