// Brush faces one by one (edit_faces.h) and their script lines: the face selection through edits and undo,
// material, offset, scale and rotation, fit, align to an edge, copy/paste, replace across the level and
// texture lock; the hard cases (tiny faces, slivers, scale near 0, rotation wrap, NaN) are refused or exact.
#include "editor_test_util.h"
#include "model/edit_brushes.h"
#include "model/edit_faces.h"
#include "model/edit_selection.h"
#include "model/edit_transforms.h"
#include "model/face_drag.h"
#include "model/script.h"
#include "view/face_picking.h"

#include "brush/texture_mapping.h"
#include "level/entity_shapes.h"

#include <cmath>
#include <limits>

using namespace ks;
using namespace ks::editor;

namespace {

int face_test_box(Editor& ed, Vec3 a, Vec3 b, const char* material = "concrete") {
    auto id = place_box_brush(ed, a, b, {material, ""});
    REQUIRE(id.ok());
    return *id;
}

const brush::Face& local_face(const Editor& ed, int id, int face) {
    return ed.level().find(id)->as<level::BrushProps>().brush.faces()[static_cast<size_t>(face)];
}

brush::Face world_face(const Editor& ed, int id, int face) {
    return editor_test::world_brush_of(ed, id).faces()[static_cast<size_t>(face)];
}

// The world corners of a face.
std::vector<DVec3> world_corners(const Editor& ed, int id, int face) {
    const brush::Brush world = editor_test::world_brush_of(ed, id);
    std::vector<DVec3> out;
    for (int v : world.polygons()[static_cast<size_t>(face)])
        out.push_back(world.vertices()[static_cast<size_t>(v)]);
    return out;
}

int top_of(const Editor& ed, int id) {
    auto top = face_facing(*ed.level().find(id), {0, 1, 0});
    REQUIRE(top.ok());
    return *top;
}

const double kNaN = std::numeric_limits<double>::quiet_NaN();

} // namespace

TEST_CASE("faces: select by index or direction; refusals; the selection follows edits and undo") {
    Editor ed;
    const int id = face_test_box(ed, {0, 0, 0}, {4, 4, 4});
    const int top = top_of(ed, id);
    CHECK(world_face(ed, id, top).plane.normal.y == doctest::Approx(1.0));
    REQUIRE(select_face(ed, id, top).ok());
    REQUIRE(ed.doc().faces.size() == 1);
    CHECK(select_face(ed, id, 6).error().message.find("has faces 0 to 5, not 6") != std::string::npos);
    CHECK(!select_face(ed, 999, 0).ok());
    REQUIRE(select_face(ed, id, 0, SelectMode::Add).ok());
    REQUIRE(select_face(ed, id, 0, SelectMode::Toggle).ok());
    CHECK(ed.doc().faces.size() == 1);
    // A wall is not a brush.
    auto wall = run_script_text("place wall at 10,0,0\n", "wall.kss", {}, ed);
    REQUIRE(wall.ok());
    CHECK(select_face(ed, ed.doc().selection.front(), 0).error().message.find("not a brush") !=
          std::string::npos);

    // A subtract rebuilds the brush: the top face is found again by its plane, whatever its new index.
    ed.set_face_selection({});
    REQUIRE(select_face(ed, id, top).ok());
    const int cutter = face_test_box(ed, {1, -1, 1}, {3, 2, 3});
    REQUIRE(select(ed, {cutter}).ok());
    REQUIRE(subtract_selected_brushes(ed).ok());
    for (const SelectedFace& f : selected_faces(ed.doc()))
        if (f.entity->id == id) CHECK(f.face.plane.normal.y == doctest::Approx(1.0));
    REQUIRE(ed.undo());
    REQUIRE(ed.doc().faces.size() == 1);
    CHECK(ed.doc().faces.front().face == top);
    // Undoing the brush's placement takes its faces out of the selection; redo does not bring them back.
    REQUIRE(ed.undo());
    REQUIRE(ed.undo());
    REQUIRE(ed.undo());
    CHECK(ed.level().find(id) == nullptr);
    CHECK(ed.doc().faces.empty());
}

TEST_CASE("faces: material, offset, scale and rotation are one step each; bad numbers are refused") {
    Editor ed;
    const int id = face_test_box(ed, {0, 0, 0}, {4, 4, 4});
    CHECK(set_face_material(ed, "metal").error().message.find("no face is selected") != std::string::npos);
    REQUIRE(select_face(ed, id, 0).ok());
    REQUIRE(select_face(ed, id, 1, SelectMode::Add).ok());
    const size_t steps = ed.history().undo_count();
    REQUIRE(set_face_material(ed, "metal").ok());
    REQUIRE(set_face_offset(ed, {0.25, -0.5}).ok());
    REQUIRE(set_face_scale(ed, {2, -3}).ok());
    REQUIRE(set_face_rotation(ed, 370).ok());
    CHECK(ed.history().undo_count() == steps + 4);
    for (int f : {0, 1}) {
        const brush::FaceAttributes& at = local_face(ed, id, f).attributes;
        CHECK(at.material == "metal");
        CHECK(at.offset == glm::dvec2(0.25, -0.5));
        CHECK(at.scale == glm::dvec2(2, -3));
        CHECK(at.rotation_degrees == doctest::Approx(10.0)); // wrapped
    }
    CHECK(local_face(ed, id, 2).attributes.material == "concrete");
    // Rotation wraps into (-180, 180] both ways.
    REQUIRE(set_face_rotation(ed, 170).ok());
    REQUIRE(turn_face_texture(ed, 20).ok());
    CHECK(local_face(ed, id, 0).attributes.rotation_degrees == doctest::Approx(-170.0));
    REQUIRE(set_face_rotation(ed, -180).ok());
    CHECK(local_face(ed, id, 0).attributes.rotation_degrees == doctest::Approx(180.0));
    REQUIRE(shift_face_offset(ed, {1, 1}).ok());
    CHECK(local_face(ed, id, 1).attributes.offset == glm::dvec2(1.25, 0.5));

    const size_t before_refusals = ed.history().undo_count();
    CHECK(set_face_scale(ed, {1e-4, 1}).error().message.find("outside") != std::string::npos);
    CHECK(!set_face_scale(ed, {0, 1}).ok());
    CHECK(!set_face_scale(ed, {1, -1e-5}).ok());
    CHECK(!set_face_scale(ed, {1, 1e9}).ok());
    CHECK(set_face_scale(ed, {kNaN, 1}).error().message.find("finite") != std::string::npos);
    CHECK(!set_face_offset(ed, {kNaN, 0}).ok());
    CHECK(!shift_face_offset(ed, {0, std::numeric_limits<double>::infinity()}).ok());
    CHECK(!set_face_rotation(ed, kNaN).ok());
    CHECK(!turn_face_texture(ed, kNaN).ok());
    CHECK(!set_face_material(ed, "").ok());
    CHECK(!set_face_material(ed, "two words").ok());
    CHECK(ed.history().undo_count() == before_refusals);
    // A locked brush's faces are left alone, and say so.
    REQUIRE(run_script_text("lock " + std::to_string(id) + "\n", "lock.kss", {}, ed).ok());
    CHECK(set_face_material(ed, "tiles").error().message.find("locked") != std::string::npos);
}

TEST_CASE("faces: fit puts the texture once across a face, turned, flipped, tiny; slivers are refused") {
    Editor ed;
    const int id = face_test_box(ed, {0, 0, 0}, {4, 2, 8});
    const int side = *face_facing(*ed.level().find(id), {1, 0, 0}); // 8 along u, 2 along v
    REQUIRE(select_face(ed, id, side).ok());
    for (double rotation : {0.0, 30.0, -90.0}) {
        REQUIRE(set_face_rotation(ed, rotation).ok());
        REQUIRE(set_face_scale(ed, {1, -1}).ok()); // v flipped: stays flipped
        REQUIRE(fit_face_texture(ed).ok());
        const brush::Face face = world_face(ed, id, side);
        CHECK(face.attributes.scale.y < 0);
        glm::dvec2 lo(1e9), hi(-1e9);
        for (const DVec3& p : world_corners(ed, id, side)) {
            const glm::dvec2 t = brush::texture_coordinates(face, p);
            lo = glm::min(lo, t), hi = glm::max(hi, t);
        }
        CHECK(lo.x == doctest::Approx(0.0).epsilon(1e-9));
        CHECK(lo.y == doctest::Approx(0.0).epsilon(1e-9));
        CHECK(hi.x == doctest::Approx(1.0));
        CHECK(hi.y == doctest::Approx(1.0));
    }
    REQUIRE(set_face_rotation(ed, 0).ok());
    REQUIRE(fit_face_texture(ed, {2, 3}).ok());
    CHECK(std::abs(local_face(ed, id, side).attributes.scale.x) == doctest::Approx(4.0));
    CHECK(std::abs(local_face(ed, id, side).attributes.scale.y) == doctest::Approx(2.0 / 3.0));
    CHECK(!fit_face_texture(ed, {0, 1}).ok());
    CHECK(!fit_face_texture(ed, {kNaN, 1}).ok());

    // A tiny face (0.01 across) fits; a sliver 1e-4 thick is refused along its thin side.
    ed.grid().snap = false;
    const int tiny = face_test_box(ed, {20, 0, 0}, {20.01f, 0.01f, 0.01f});
    REQUIRE(select_face(ed, tiny, 0).ok());
    REQUIRE(fit_face_texture(ed).ok());
    CHECK(std::abs(local_face(ed, tiny, 0).attributes.scale.x) == doctest::Approx(0.01).epsilon(1e-4));
    const int sliver = face_test_box(ed, {30, 0, 0}, {34, 0.0001f, 4});
    REQUIRE(select_face(ed, sliver, *face_facing(*ed.level().find(sliver), {1, 0, 0})).ok());
    const size_t steps = ed.history().undo_count();
    auto refused = fit_face_texture(ed);
    REQUIRE_FALSE(refused.ok());
    CHECK(refused.error().message.find("too small to fit") != std::string::npos);
    CHECK(ed.history().undo_count() == steps);
}

TEST_CASE("faces: align puts u along the chosen edge from its first corner, on a turned brush too") {
    Editor ed;
    const int id = face_test_box(ed, {0, 0, 0}, {4, 4, 4});
    REQUIRE(run_script_text("select " + std::to_string(id) + "\nrotate y 30\n", "turn.kss", {}, ed).ok());
    const int top = top_of(ed, id);
    REQUIRE(select_face(ed, id, top).ok());
    REQUIRE(set_face_scale(ed, {2, 2}).ok());
    for (int edge = 0; edge < 4; ++edge) {
        REQUIRE(align_face_texture_to_edge(ed, edge).ok());
        const brush::Face face = world_face(ed, id, top);
        const std::vector<DVec3> corners = world_corners(ed, id, top);
        const DVec3 along =
            glm::normalize(corners[static_cast<size_t>((edge + 1) % 4)] - corners[static_cast<size_t>(edge)]);
        CHECK(glm::dot(brush::texture_axes(face).u, along) == doctest::Approx(1.0));
        const glm::dvec2 origin = brush::texture_coordinates(face, corners[static_cast<size_t>(edge)]);
        CHECK(std::abs(origin.x) < 1e-9);
        CHECK(std::abs(origin.y) < 1e-9);
    }
    CHECK(align_face_texture_to_edge(ed, 4).error().message.find("edges 0 to 3, not 4") != std::string::npos);
    CHECK(!align_face_texture_to_edge(ed, -1).ok());
}

TEST_CASE("faces: copy and paste attributes; replace a texture across the level in one step") {
    Editor ed;
    const int a = face_test_box(ed, {0, 0, 0}, {4, 4, 4});
    const int b = face_test_box(ed, {10, 0, 0}, {14, 4, 4});
    CHECK(paste_face_attributes(ed).error().message.find("nothing is copied") != std::string::npos);
    CHECK(!copy_face_attributes(ed).ok());
    REQUIRE(select_face(ed, a, 2).ok());
    REQUIRE(set_face_material(ed, "metal").ok());
    REQUIRE(set_face_scale(ed, {3, 5}).ok());
    REQUIRE(set_face_rotation(ed, 45).ok());
    REQUIRE(copy_face_attributes(ed).ok());
    REQUIRE(select_face(ed, b, 0).ok());
    REQUIRE(select_face(ed, b, 4, SelectMode::Add).ok());
    REQUIRE(paste_face_attributes(ed).ok());
    CHECK(local_face(ed, b, 0).attributes == local_face(ed, a, 2).attributes);
    CHECK(local_face(ed, b, 4).attributes == local_face(ed, a, 2).attributes);

    REQUIRE(run_script_text("place wall at 20,0,0\nset texture metal\n", "wall.kss", {}, ed).ok());
    const int wall = ed.doc().selection.front();
    const size_t steps = ed.history().undo_count();
    auto replaced = replace_texture(ed, "metal", "tiles");
    REQUIRE(replaced.ok());
    CHECK(*replaced == 4); // three faces and the wall's texture
    CHECK(ed.history().undo_count() == steps + 1);
    CHECK(local_face(ed, b, 4).attributes.material == "tiles");
    CHECK(std::get<std::string>(*get_entity_field(*ed.level().find(wall), "texture")) == "tiles");
    REQUIRE(ed.undo());
    CHECK(local_face(ed, a, 2).attributes.material == "metal");
    CHECK(replace_texture(ed, "nothing_uses_this", "tiles").error().message.find("no unlocked") !=
          std::string::npos);
    CHECK(!replace_texture(ed, "metal", "metal").ok());
    CHECK(!replace_texture(ed, "metal", "").ok());
}

TEST_CASE("faces: texture lock keeps textures on the world through moves and turns; off, they travel") {
    Editor ed;
    const int id = face_test_box(ed, {0, 0, 0}, {4, 4, 4});
    REQUIRE(select_face(ed, id, top_of(ed, id)).ok());
    REQUIRE(set_face_rotation(ed, 20).ok());
    REQUIRE(set_face_offset(ed, {0.3, 0.1}).ok());
    const int top = top_of(ed, id);
    const DVec3 probe(1.25, 4.0, 1.5); // on the top face before and after the motions below
    const glm::dvec2 before = brush::texture_coordinates(world_face(ed, id, top), probe);
    REQUIRE(select(ed, {id}).ok());

    // Off (the default): the texture travels with the brush.
    const brush::Brush local_before = ed.level().find(id)->as<level::BrushProps>().brush;
    REQUIRE(move_selection(ed, {0.5f, 0, 0.25f}).ok());
    CHECK(ed.level().find(id)->as<level::BrushProps>().brush == local_before);
    const glm::dvec2 travelled = brush::texture_coordinates(world_face(ed, id, top), probe);
    CHECK(glm::length(travelled - before) > 0.01);
    REQUIRE(ed.undo());

    set_texture_lock(ed, true);
    REQUIRE(move_selection(ed, {0.5f, 0, 0.25f}).ok());
    REQUIRE(rotate_selection_about(ed, 1, 37.0f, RotationSpace::Local, false).ok());
    REQUIRE(move_selection(ed, {-0.75f, 0, 0.5f}).ok());
    const glm::dvec2 kept = brush::texture_coordinates(world_face(ed, id, top), probe);
    CHECK(kept.x == doctest::Approx(before.x).epsilon(1e-9));
    CHECK(kept.y == doctest::Approx(before.y).epsilon(1e-9));
    // A move alone leaves the stored angle exactly as it was.
    const double angle = local_face(ed, id, top).attributes.rotation_degrees;
    REQUIRE(move_selection(ed, {1, 0, 0}).ok());
    CHECK(local_face(ed, id, top).attributes.rotation_degrees == angle);
    // Undo takes the attributes back with the frame.
    for (int i = 0; i < 4; ++i) REQUIRE(ed.undo());
    CHECK(ed.level().find(id)->as<level::BrushProps>().brush == local_before);
}

TEST_CASE("faces: script lines select, edit, fit, align, copy, paste, replace and lock") {
    Editor ed;
    const char* script = R"(brush box 0,0,0 4,4,4 material concrete name Block
brush box 10,0,0 14,4,4 material concrete
face select 1:+y
face material metal
face scale 2,2
face rotation 45
face turn -15
face offset 0.5,0.25
face shift 0.5,0.25
face copy
face select 2:+y 2:-x
face paste
face select 1:0
face select add 1:1
face fit 2,1
face align 1
face lock on
face replace metal tiles
face select none
expect count brush 2
)";
    auto report = run_script_text(script, "faces.kss", {}, ed);
    REQUIRE_MESSAGE(report.ok(), (report.ok() ? std::string() : report.error().str()));
    CHECK(ed.doc().faces.empty());
    CHECK(ed.face_session().texture_lock);
    const int top2 = top_of(ed, 2);
    CHECK(local_face(ed, 2, top2).attributes.material == "tiles");
    CHECK(local_face(ed, 2, top2).attributes.rotation_degrees == doctest::Approx(30.0));
    CHECK(local_face(ed, 2, top2).attributes.offset == glm::dvec2(1.0, 0.5));

    Editor fresh;
    auto bad = run_script_text("face select 1:up\n", "bad.kss", {}, fresh);
    REQUIRE_FALSE(bad.ok());
    CHECK(bad.error().str().find("bad.kss:1:13: expected a face as ID:INDEX") != std::string::npos);
    auto lock = run_script_text("face lock maybe\n", "lock.kss", {}, fresh);
    REQUIRE_FALSE(lock.ok());
    CHECK(lock.error().str().find("expected on or off") != std::string::npos);
    auto none = run_script_text("brush box 0,0,0 2,2,2\nface select 1:9\n", "none.kss", {}, fresh);
    REQUIRE_FALSE(none.ok());
    CHECK(none.error().str().find("none.kss:2: Select face: brush 1 has faces 0 to 5, not 9") !=
          std::string::npos);
}

TEST_CASE("faces: a ray picks the face it enters through; a nearer entity hides it") {
    Editor ed;
    const int id = face_test_box(ed, {0, 0, 0}, {4, 4, 4});
    auto all = [](const level::Entity&) { return true; };
    geometry::Ray down;
    down.origin = {1, 20, 3}, down.direction = {0, -1, 0};
    auto top = pick_face(ed.doc(), down, all);
    REQUIRE(top.has_value());
    CHECK(top->entity == id);
    CHECK(top->face == top_of(ed, id));
    CHECK(top->distance == doctest::Approx(16.0f));
    geometry::Ray side;
    side.origin = {-10, 1, 2}, side.direction = {1, 0, 0};
    auto west = pick_face(ed.doc(), side, all);
    REQUIRE(west.has_value());
    CHECK(world_face(ed, id, west->face).plane.normal.x == doctest::Approx(-1.0));
    REQUIRE(click_face(ed, west).ok());
    REQUIRE(click_face(ed, top).ok());
    CHECK(ed.doc().faces.size() == 2);
    REQUIRE(click_face(ed, top).ok()); // a second click takes it out
    CHECK(ed.doc().faces.size() == 1);
    // A box brush in front is picked instead; a wall in front hides every face.
    const int front = face_test_box(ed, {-6, 0, 0}, {-5, 4, 4});
    CHECK(pick_face(ed.doc(), side, all)->entity == front);
    REQUIRE(run_script_text("place wall at -8,0,2 yaw 90\n", "wall.kss", {}, ed).ok());
    CHECK_FALSE(pick_face(ed.doc(), side, all).has_value());
    geometry::Ray miss;
    miss.origin = {50, 20, 50}, miss.direction = {0, -1, 0};
    CHECK_FALSE(pick_face(ed.doc(), miss, all).has_value());
    REQUIRE(click_face(ed, pick_face(ed.doc(), miss, all)).ok());
    CHECK(ed.doc().faces.empty());
}

namespace {

// A box turned 30 degrees about y with its top face selected, Snap off: the texture drag's test bed.
struct DragBed {
    Editor ed;
    int id = 0, top = 0;
    DVec3 centre{0.0}; // the top face's centre (world)
    DragBed() {
        id = face_test_box(ed, {0, 0, 0}, {4, 4, 4});
        REQUIRE(select(ed, {id}).ok());
        REQUIRE(rotate_selection_about(ed, 1, 30.0f, RotationSpace::World, false).ok());
        top = top_of(ed, id);
        REQUIRE(select_face(ed, id, top).ok());
        REQUIRE(set_face_scale(ed, {2, 2}).ok());
        ed.grid().snap = false;
        for (const DVec3& p : world_corners(ed, id, top)) centre += p / 4.0;
    }
    glm::dvec2 texel(const DVec3& p) const { return brush::texture_coordinates(world_face(ed, id, top), p); }
    const brush::FaceAttributes& attributes() const { return local_face(ed, id, top).attributes; }
};

} // namespace

TEST_CASE("face drag: a move carries the grabbed texel to the mouse, whole grid steps with Snap; one step") {
    DragBed bed;
    Editor& ed = bed.ed;
    const DVec3 grab = bed.centre + DVec3(0.3, 0, 0.2), to = grab + DVec3(1.3, 0, -0.7);
    const glm::dvec2 grabbed = bed.texel(grab);
    const brush::FaceAttributes start = bed.attributes();
    const size_t steps = ed.history().undo_count();
    FaceDrag drag;
    REQUIRE(drag.begin(ed, bed.id, bed.top, grab, face_drag_mode(false, false)));
    CHECK(drag.mode() == FaceDragMode::move);
    for (double f : {0.25, 0.5, 1.0}) REQUIRE(drag.drag_to(ed, grab + (to - grab) * f).ok());
    CHECK(drag.changed());
    CHECK(bed.texel(to).x == doctest::Approx(grabbed.x).epsilon(1e-9));
    CHECK(bed.texel(to).y == doctest::Approx(grabbed.y).epsilon(1e-9));
    drag.end(ed);
    CHECK(ed.history().undo_count() == steps + 1); // the whole drag is one step
    REQUIRE(ed.undo());
    CHECK(bed.attributes() == start);
    REQUIRE(ed.redo());

    // With Snap (grid 0.5): the texture moves by whole grid steps along u and v, each texel by 0.25 units.
    ed.grid().snap = true;
    ed.grid().step = 0.5f;
    const brush::FaceAttributes before = bed.attributes();
    REQUIRE(drag.begin(ed, bed.id, bed.top, grab, FaceDragMode::move));
    REQUIRE(drag.drag_to(ed, to).ok());
    drag.end(ed);
    CHECK(ed.history().undo_count() == steps + 2);
    for (int k = 0; k < 2; ++k) {
        const double shifted_world = (before.offset[k] - bed.attributes().offset[k]) * before.scale[k];
        CHECK(std::abs(shifted_world / 0.5 - std::round(shifted_world / 0.5)) < 1e-9);
    }
    CHECK(drag.describe().starts_with("texture move"));
}

TEST_CASE("face drag: Ctrl turns and Shift scales about the face's centre, snapped; Esc leaves no step") {
    DragBed bed;
    Editor& ed = bed.ed;
    const glm::dvec2 at_centre = bed.texel(bed.centre);
    const brush::FaceAttributes start = bed.attributes();
    // Floors' base axes: u along +x, v along -z, in the turned brush's frame.
    const glm::dmat3 turn = glm::mat3_cast(dquat_from_ypr_degrees(DVec3(ed.level().find(bed.id)->rotation)));
    const auto on_face = [&](double degrees, double radius) {
        const double a = glm::radians(degrees);
        return bed.centre + turn * DVec3(std::cos(a) * radius, 0, -std::sin(a) * radius);
    };
    FaceDrag drag;
    REQUIRE(drag.begin(ed, bed.id, bed.top, on_face(10, 1), face_drag_mode(true, false)));
    REQUIRE(drag.drag_to(ed, on_face(62, 1.5)).ok());
    CHECK(bed.attributes().rotation_degrees == doctest::Approx(start.rotation_degrees + 52));
    ed.grid().snap = true; // the grid's rotation step, 15 degrees
    REQUIRE(drag.drag_to(ed, on_face(62, 1.5)).ok());
    CHECK(bed.attributes().rotation_degrees == doctest::Approx(start.rotation_degrees + 45));
    CHECK(bed.texel(bed.centre).x == doctest::Approx(at_centre.x).epsilon(1e-9));
    CHECK(bed.texel(bed.centre).y == doctest::Approx(at_centre.y).epsilon(1e-9));
    drag.end(ed);

    const size_t steps = ed.history().undo_count();
    const brush::FaceAttributes turned = bed.attributes();
    REQUIRE(drag.begin(ed, bed.id, bed.top, on_face(0, 1), face_drag_mode(false, true)));
    CHECK(drag.mode() == FaceDragMode::scale);
    REQUIRE(drag.drag_to(ed, on_face(0, 2.05)).ok()); // 2.05 snaps to 2 (eighths)
    CHECK(bed.attributes().scale.x == doctest::Approx(turned.scale.x * 2));
    CHECK(bed.attributes().scale.y == doctest::Approx(turned.scale.y * 2));
    CHECK(bed.texel(bed.centre).x == doctest::Approx(at_centre.x).epsilon(1e-9));
    ed.grid().snap = false;
    REQUIRE(drag.drag_to(ed, on_face(0, 1.3)).ok());
    CHECK(bed.attributes().scale.x == doctest::Approx(turned.scale.x * 1.3));
    // Esc: as at the press, and no step left.
    drag.cancel(ed);
    CHECK(!drag.dragging());
    CHECK(bed.attributes() == turned);
    CHECK(ed.history().undo_count() == steps);
}

TEST_CASE("face drag: only a selected, unlocked face is grabbed; texture lock keeps a dragged texture") {
    DragBed bed;
    Editor& ed = bed.ed;
    FaceDrag drag;
    CHECK(!drag.begin(ed, bed.id, (bed.top + 1) % 6, bed.centre, FaceDragMode::move)); // not selected
    CHECK(!drag.begin(ed, 999, 0, bed.centre, FaceDragMode::move));
    CHECK(!drag.dragging());
    // A press that does not move changes nothing and leaves no step (the viewport takes it as a click).
    const size_t steps = ed.history().undo_count();
    REQUIRE(drag.begin(ed, bed.id, bed.top, bed.centre, FaceDragMode::move));
    REQUIRE(drag.drag_to(ed, bed.centre).ok());
    drag.end(ed);
    CHECK(!drag.changed());
    CHECK(ed.history().undo_count() == steps);

    // Texture lock on: the dragged texture then stays on the world while the brush moves under it.
    set_texture_lock(ed, true);
    REQUIRE(drag.begin(ed, bed.id, bed.top, bed.centre, FaceDragMode::move));
    REQUIRE(drag.drag_to(ed, bed.centre + DVec3(0.4, 0, 0.9)).ok());
    drag.end(ed);
    const DVec3 probe = bed.centre + DVec3(0.5, 0, 0.5);
    const glm::dvec2 dragged = bed.texel(probe);
    REQUIRE(select(ed, {bed.id}).ok());
    REQUIRE(move_selection(ed, {0.75f, 0, -0.5f}).ok());
    CHECK(bed.texel(probe).x == doctest::Approx(dragged.x).epsilon(1e-9));
    CHECK(bed.texel(probe).y == doctest::Approx(dragged.y).epsilon(1e-9));
    // Undo: the move, then the whole drag.
    REQUIRE(ed.undo());
    REQUIRE(ed.undo());
    CHECK(ed.history().undo_count() == steps);
}

TEST_CASE("faces: replace texture swaps attributes only; the level equals the one rebuilt from planes") {
    Editor ed;
    for (int i = 0; i < 6; ++i) {
        const int id =
            face_test_box(ed, {i * 6.0f, 0, 0}, {i * 6.0f + 3, 2 + i, 3}, i % 2 ? "metal" : "wood");
        REQUIRE(select(ed, {id}).ok());
        REQUIRE(rotate_selection_about(ed, 1, 17.0f * i, RotationSpace::World, false).ok());
    }
    level::Level slow = ed.level();
    for (level::Entity& e : slow.entities) {
        auto& b = e.as<level::BrushProps>().brush;
        std::vector<brush::Face> faces = b.anchored_faces();
        for (brush::Face& f : faces)
            if (f.attributes.material == "metal") f.attributes.material = "tiles";
        auto rebuilt = brush::Brush::from_anchored_faces(b.anchor(), std::move(faces));
        REQUIRE(rebuilt.ok());
        b = *rebuilt;
    }
    REQUIRE(replace_texture(ed, "metal", "tiles").ok());
    REQUIRE(ed.level().entities.size() == slow.entities.size());
    for (size_t i = 0; i < slow.entities.size(); ++i) {
        CHECK(ed.level().entities[i] == slow.entities[i]);
        const brush::Brush& fast = ed.level().entities[i].as<level::BrushProps>().brush;
        const brush::Brush& rebuilt = slow.entities[i].as<level::BrushProps>().brush;
        CHECK(fast.vertices() == rebuilt.vertices());
        CHECK(fast.polygons() == rebuilt.polygons());
        CHECK(fast.volume() == rebuilt.volume());
    }
    // The fast path refuses what from_faces refuses.
    const brush::Brush& b = ed.level().entities[0].as<level::BrushProps>().brush;
    std::vector<brush::FaceAttributes> bad(b.faces().size());
    bad[3].scale.y = 0.0;
    CHECK(b.with_attributes(bad).error().where.path == "faces[3].scale.y");
    CHECK(!b.with_attributes({}).ok());
}
