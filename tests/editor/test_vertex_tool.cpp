// The vertex tool (model/tool_vertex.h), its handles in a view (view/vertex_handles.h) and its script lines:
// select, drag, a vertex shared by two brushes, split, merge and remove; every valid drag one undo step,
// every refused one leaving the level and the history as they were.
#include "editor_test_util.h"
#include "model/edit_brushes.h"
#include "model/edit_selection.h"
#include "model/tool_vertex.h"
#include "view/vertex_handles.h"

#include <algorithm>

using namespace ks;
using namespace ks::editor;

namespace {

bool vt_has_vertex(const brush::Brush& b, const DVec3& p) {
    return std::any_of(b.vertices().begin(), b.vertices().end(),
                       [&](const DVec3& v) { return glm::length(v - p) < 1e-9; });
}

// A box 0..4 on every axis, selected; returns its id.
int vt_box(Editor& ed, Vec3 lo = Vec3(0.0f), Vec3 hi = Vec3(4.0f)) {
    auto id = place_box_brush(ed, lo, hi);
    REQUIRE(id.ok());
    return *id;
}

} // namespace

TEST_CASE("vertex tool: a selected vertex dragged is one undo step; undo and redo restore each side") {
    Editor ed;
    const int id = vt_box(ed);
    VertexTool tool;
    CHECK(tool.handles(ed.doc()).size() == 8 + 12); // the corners, then the edges' split handles
    REQUIRE(tool.select(ed.doc(), {4, 4, 4}, false).ok());
    REQUIRE(tool.select(ed.doc(), {0, 0, 0}, true).ok()); // Shift adds
    CHECK(tool.selected().size() == 2);
    REQUIRE(tool.select(ed.doc(), {0, 0, 0}, true).ok()); // and drops a selected one
    CHECK(tool.selected() == std::vector<DVec3>{DVec3(4, 4, 4)});
    CHECK_FALSE(tool.select(ed.doc(), {2, 2, 2}, false).ok());

    const std::string before = editor_test::text_of(ed);
    const size_t steps = ed.history().undo_count();
    REQUIRE(tool.grab(ed.doc(), {4, 4, 4}).ok());
    tool.drag(ed.doc(), {1, 0, 0});
    tool.drag(ed.doc(), {1, 1, 0}); // many mouse moves, one step
    CHECK(tool.preview(ed.doc()).problem.empty());
    CHECK(tool.preview(ed.doc()).segments.size() > 12); // the moved brush's edges
    CHECK(editor_test::text_of(ed) == before);          // nothing changes until the release
    REQUIRE(tool.release(ed).ok());
    CHECK(ed.history().undo_count() == steps + 1);
    CHECK(ed.history().undo_name() == "Move vertices");
    const brush::Brush moved = editor_test::world_brush_of(ed, id);
    CHECK(vt_has_vertex(moved, {5, 5, 4}));
    CHECK_FALSE(vt_has_vertex(moved, {4, 4, 4}));
    CHECK(tool.selected() == std::vector<DVec3>{DVec3(5, 5, 4)}); // the selection follows the handle
    const std::string after = editor_test::text_of(ed);
    REQUIRE(ed.undo());
    CHECK(editor_test::text_of(ed) == before);
    REQUIRE(ed.redo());
    CHECK(editor_test::text_of(ed) == after);
}

TEST_CASE("vertex tool: a vertex shared by two selected brushes moves in both, as one step") {
    Editor ed;
    const int a = vt_box(ed);
    const int b = vt_box(ed, Vec3(4, 0, 0), Vec3(8, 4, 4));
    REQUIRE(select(ed, {a, b}).ok());
    VertexTool tool;
    CHECK(tool.handles(ed.doc()).size() == 12 + 20); // 16 corners less the 4 shared; 24 edges less 4 shared
    const size_t steps = ed.history().undo_count();
    REQUIRE(tool.grab(ed.doc(), {4, 4, 4}).ok());
    tool.drag(ed.doc(), {0, 1, 0});
    CHECK(tool.moved().size() == 2);
    REQUIRE(tool.release(ed).ok());
    CHECK(ed.history().undo_count() == steps + 1);
    CHECK(vt_has_vertex(editor_test::world_brush_of(ed, a), {4, 5, 4}));
    CHECK(vt_has_vertex(editor_test::world_brush_of(ed, b), {4, 5, 4}));
    REQUIRE(ed.undo());
    CHECK(vt_has_vertex(editor_test::world_brush_of(ed, a), {4, 4, 4}));
    CHECK(vt_has_vertex(editor_test::world_brush_of(ed, b), {4, 4, 4}));
}

TEST_CASE("vertex tool: a turned brush's vertex moves by the world delta") {
    Editor ed;
    auto turned = run_script_text("brush box 0,0,0 4,4,4\nrotate y 90\n", "turned.kss", {}, ed);
    REQUIRE(turned.ok());
    const int id = ed.doc().selection.front();
    REQUIRE(ed.level().find(id)->rotation.x != 0.0f); // its own frame is turned; its corners are the box's
    VertexTool tool;
    REQUIRE(tool.grab(ed.doc(), {4, 4, 4}).ok());
    tool.drag(ed.doc(), {1, 0, 0});
    REQUIRE(tool.release(ed).ok());
    const brush::Brush world = editor_test::world_brush_of(ed, id);
    CHECK(std::any_of(world.vertices().begin(), world.vertices().end(),
                      [](const DVec3& v) { return glm::length(v - DVec3(5, 4, 4)) < 1e-5; }));
}

TEST_CASE("vertex tool: a refused drag says why and leaves the level and the history unchanged") {
    Editor ed;
    vt_box(ed);
    const std::string before = editor_test::text_of(ed);
    const size_t steps = ed.history().undo_count();
    VertexTool tool;
    REQUIRE(tool.grab(ed.doc(), {4, 4, 4}).ok());
    tool.drag(ed.doc(), {-2, -2, -2}); // into the brush
    CHECK(tool.preview(ed.doc()).problem.find("would no longer be a corner") != std::string::npos);
    auto released = tool.release(ed);
    REQUIRE_FALSE(released.ok());
    CHECK(released.error().message.find("Vertex: brush 1: vertex") == 0);
    CHECK(tool.preview(ed.doc()).problem.find("would no longer be a corner") != std::string::npos);
    CHECK(editor_test::text_of(ed) == before);
    CHECK(ed.history().undo_count() == steps);
    // A zero drag (a click) changes nothing either, and says nothing.
    REQUIRE(tool.grab(ed.doc(), {4, 4, 4}).ok());
    CHECK(tool.preview(ed.doc()).problem.empty());
    REQUIRE(tool.release(ed).ok());
    CHECK(ed.history().undo_count() == steps);
}

TEST_CASE("vertex tool: an edge's midpoint dragged out splits it; a vertex onto its neighbour merges; Delete "
          "removes") {
    Editor ed;
    const int id = vt_box(ed);
    VertexTool tool;
    REQUIRE(tool.grab(ed.doc(), {2, 4, 4}).ok()); // the split handle of the top front edge
    tool.drag(ed.doc(), {0, 1, 0});
    REQUIRE(tool.release(ed).ok());
    CHECK(ed.history().undo_name() == "Split edge");
    CHECK(editor_test::world_brush_of(ed, id).vertices().size() == 9);
    CHECK(vt_has_vertex(editor_test::world_brush_of(ed, id), {2, 5, 4}));
    CHECK(tool.selected() == std::vector<DVec3>{DVec3(2, 5, 4)});
    // Dragged into the brush a split handle is refused.
    REQUIRE(tool.grab(ed.doc(), {2, 0, 4}).ok());
    tool.drag(ed.doc(), {0, 0, -1});
    CHECK_FALSE(tool.release(ed).ok());

    // The new vertex dragged back onto its neighbour (0,4,4) merges into it.
    REQUIRE(tool.grab(ed.doc(), {2, 5, 4}).ok());
    tool.drag(ed.doc(), {-2, -1, 0});
    REQUIRE(tool.release(ed).ok());
    CHECK(editor_test::world_brush_of(ed, id).vertices().size() == 8);
    CHECK(tool.selected() == std::vector<DVec3>{DVec3(0, 4, 4)}); // the vertex it merged into

    REQUIRE(tool.select(ed.doc(), {4, 4, 4}, false).ok());
    REQUIRE(tool.remove_selected(ed).ok());
    CHECK(ed.history().undo_name() == "Remove vertices");
    CHECK(editor_test::world_brush_of(ed, id).vertices().size() == 7);
    // Removing so much that no volume is left is refused.
    for (const DVec3& p : {DVec3(0, 0, 0), DVec3(4, 0, 0), DVec3(0, 4, 0), DVec3(4, 4, 0)})
        REQUIRE(tool.select(ed.doc(), p, true).ok());
    const size_t steps = ed.history().undo_count();
    CHECK_FALSE(tool.remove_selected(ed).ok());
    CHECK(ed.history().undo_count() == steps);
}

TEST_CASE("vertex tool: edge and face modes move their handles' corners") {
    Editor ed;
    const int id = vt_box(ed);
    VertexTool tool;
    tool.set_mode(VertexMode::edge);
    CHECK(tool.handles(ed.doc()).size() == 12);
    REQUIRE(tool.grab(ed.doc(), {2, 4, 4}).ok());
    tool.drag(ed.doc(), {0, 2, 0});
    REQUIRE(tool.release(ed).ok());
    CHECK(ed.history().undo_name() == "Move edges");
    CHECK(vt_has_vertex(editor_test::world_brush_of(ed, id), {0, 6, 4}));
    CHECK(vt_has_vertex(editor_test::world_brush_of(ed, id), {4, 6, 4}));
    REQUIRE(ed.undo());

    tool.set_mode(VertexMode::face);
    CHECK(tool.handles(ed.doc()).size() == 6);
    REQUIRE(tool.grab(ed.doc(), {2, 4, 2}).ok()); // the top face's centre
    tool.drag(ed.doc(), {0, 3, 0});
    REQUIRE(tool.release(ed).ok());
    CHECK(ed.history().undo_name() == "Move faces");
    CHECK(editor_test::world_brush_of(ed, id).bounds_max() == DVec3(4, 7, 4));
}

TEST_CASE("vertex tool in a view: the handle under the mouse, a box select, and a snapped drag") {
    Editor ed;
    vt_box(ed);
    const ViewCamera top = editor_test::top_view(Vec3(2, 0, 2));
    VertexTool tool;
    const auto handles = tool.handles(ed.doc());
    Vec2 corner;
    REQUIRE(top.project(Vec3(4, 4, 4), corner));
    const auto under = handle_under(handles, top, corner + Vec2(3, -2));
    REQUIRE(under);
    CHECK(under->at == DVec3(4, 4, 4)); // above (4,0,4) in the top view: the nearer one
    CHECK_FALSE(handle_under(handles, top, corner + Vec2(30, 30)));
    Vec2 origin;
    REQUIRE(top.project(Vec3(0, 4, 0), origin));
    CHECK(handles_in_rect(handles, top, origin - Vec2(2), corner + Vec2(2)).size() == 8);

    const VertexDrag drag = start_vertex_drag(ed.doc(), top, corner, {4, 4, 4}, true);
    Vec2 target;
    REQUIRE(top.project(Vec3(6.3f, 4.0f, 5.2f), target));
    const auto delta = vertex_drag_delta(ed.doc(), top, target, drag);
    REQUIRE(delta);
    CHECK(glm::length(*delta - DVec3(2, 0, 1)) < 1e-6); // onto the grid, across the view
}

TEST_CASE("tool vertex script lines drag, split and remove; bad words are reported at their column") {
    Editor ed;
    const char* script = R"(grid 1
brush box 0,0,0 4,4,4
brush box 4,0,0 8,4,4
select 1 2
tool vertex 4,4,4 by 0,1,0
tool vertex face 8,2,2 by 1,0,0
tool vertex split 2,0,4 by 0,0,1
tool vertex remove 9,0,0
)";
    auto report = run_script_text(script, "vertex.kss", {}, ed);
    REQUIRE_MESSAGE(report.ok(), (report.ok() ? std::string() : report.error().str()));
    CHECK(vt_has_vertex(editor_test::world_brush_of(ed, 1), {4, 5, 4}));
    CHECK(vt_has_vertex(editor_test::world_brush_of(ed, 2), {9, 4, 4}));
    CHECK(vt_has_vertex(editor_test::world_brush_of(ed, 1), {2, 0, 5}));
    CHECK_FALSE(vt_has_vertex(editor_test::world_brush_of(ed, 2), {9, 0, 0}));
    CHECK(editor_test::world_brush_of(ed, 2).vertices().size() == 7);

    auto no_by = run_script_text("tool vertex 1,1,1 0,1,0\n", "by.kss", {}, ed);
    REQUIRE_FALSE(no_by.ok());
    CHECK(no_by.error().str().find("by.kss:1:") != std::string::npos);
    auto inside = run_script_text("tool vertex 4,5,4 by 0,-3,0\n", "inside.kss", {}, ed);
    REQUIRE_FALSE(inside.ok());
    CHECK(inside.error().str().find("Vertex: brush") != std::string::npos);
}
