// Brush edits (edit_brushes.h) and their script commands: placing boxes, ramps and extrusions, subtract,
// hollow, merge and clip, each one undoable step, with errors that name the brush.
#include "editor_test_util.h"
#include "model/edit_brushes.h"
#include "model/edit_selection.h"
#include "model/edit_transforms.h"
#include "model/script.h"

#include "brush/brush_csg.h"
#include "level/entity_shapes.h"

#include <algorithm>
#include <cmath>

using namespace ks;
using namespace ks::editor;
using level::EntityType;

namespace {

double brush_edit_total_volume(const Editor& ed) {
    double volume = 0.0;
    for (const level::Entity& e : ed.level().entities)
        if (e.type() == EntityType::Brush) volume += editor_test::world_brush_of(ed, e.id).volume();
    return volume;
}

} // namespace

TEST_CASE("brushes: a box from two corners is snapped, stands on its bottom centre and undoes") {
    Editor ed;
    ed.grid().step = 0.5f;
    auto id = place_box_brush(ed, {4.2f, 3.1f, 1.0f}, {-2.1f, 0.1f, -1.0f}, {"metal", "Block"});
    REQUIRE(id.ok());
    const level::Entity& e = *ed.level().find(*id);
    CHECK(e.name == "Block");
    CHECK(e.position == Vec3(1.0f, 0.0f, 0.0f));
    const brush::Brush world = editor_test::world_brush_of(ed, *id);
    CHECK(world.bounds_min() == DVec3(-2.0, 0.0, -1.0));
    CHECK(world.bounds_max() == DVec3(4.0, 3.0, 1.0));
    for (const brush::Face& f : world.faces()) CHECK(f.attributes.material == "metal");
    CHECK(ed.doc().selection == std::vector<int>{*id});
    REQUIRE(ed.undo());
    CHECK(ed.level().find(*id) == nullptr);

    auto flat = place_box_brush(ed, {0, 0, 0}, {4, 0.1f, 4});
    REQUIRE_FALSE(flat.ok());
    CHECK(flat.error().message.find("flat box (no size along y)") != std::string::npos);
}

TEST_CASE("brushes: a ramp 4 high over 8 needs no trigonometry; an extruded polygon makes an angled wall") {
    Editor ed;
    auto ramp = place_ramp_brush(ed, {0, 0, 0}, {6, 4, 8}, {2, 1});
    REQUIRE(ramp.ok());
    const brush::Brush r = editor_test::world_brush_of(ed, *ramp);
    CHECK(r.volume() == doctest::Approx(6.0 * 4.0 * 8.0 / 2.0));
    CHECK(glm::length(r.bounds_max() - DVec3(6.0, 4.0, 8.0)) < 1e-9);
    // The slope: its normal leans back against the climb (up and toward -z), 4 over 8.
    bool slope = false;
    for (const brush::Face& f : r.faces())
        if (f.plane.normal.y > 0.1 && f.plane.normal.y < 0.99)
            slope = std::abs(f.plane.normal.z / f.plane.normal.y + 0.5) < 1e-9;
    CHECK(slope);

    const glm::vec2 wall[] = {{0, 0}, {8, 6}, {7.4f, 6.8f}, {-0.6f, 0.8f}};
    auto angled = place_extruded_brush(ed, 1, 0, 5, wall, {"tiles", ""});
    REQUIRE(angled.ok());
    CHECK(editor_test::world_brush_of(ed, *angled).volume() ==
          doctest::Approx(10.0 * 1.0 * 5.0).epsilon(1e-5));
    const glm::vec2 dent[] = {{0, 0}, {4, 0}, {2, 1}, {4, 4}};
    auto bad = place_extruded_brush(ed, 1, 0, 5, dent);
    CHECK_FALSE(bad.ok());
    CHECK(editor_test::brush_count(ed) == 2);
}

TEST_CASE("brushes: subtract cuts a window, keeps the wall's id and volume, removes the cutter; one undo") {
    Editor ed;
    ed.grid().step = 0.5f;
    const int wall = *place_box_brush(ed, {-8, 0, -0.5f}, {8, 8, 0.5f}, {"concrete", "Wall"});
    const int other = *place_box_brush(ed, {20, 0, 0}, {24, 4, 4});
    const int window = *place_box_brush(ed, {-2, 3, -2}, {2, 6, 2}, {"metal", ""});
    REQUIRE(select(ed, {window}).ok());
    const double before = brush_edit_total_volume(ed);
    REQUIRE(subtract_selected_brushes(ed).ok());
    CHECK(ed.level().find(window) == nullptr);
    CHECK(ed.level().find(wall) != nullptr);
    CHECK(editor_test::brush_count(ed) == 5); // four pieces around the window and the untouched box
    CHECK(brush_edit_total_volume(ed) ==
          doctest::Approx(before - 4.0 * 4.0 * 3.0 - 4.0 * 3.0 * 1.0).epsilon(1e-9));
    CHECK(ed.level().find(other)->position == Vec3(22, 0, 2));
    int named = 0, metal_faces = 0;
    for (const level::Entity& e : ed.level().entities) {
        if (e.name.rfind("Wall", 0) == 0) ++named;
        if (e.type() != EntityType::Brush || e.id == other) continue;
        const brush::Brush piece = editor_test::world_brush_of(ed, e.id);
        for (const brush::Face& f : piece.faces()) metal_faces += f.attributes.material == "metal";
    }
    CHECK(named == 4);
    // The window's reveal takes the cutter's material (4 faces), and so do the faces where the pieces meet,
    // which lie on the cutter's planes.
    CHECK(metal_faces == 8);
    REQUIRE(ed.undo());
    CHECK(editor_test::brush_count(ed) == 3);
    CHECK(brush_edit_total_volume(ed) == doctest::Approx(before));

    // A cutter that touches nothing is refused by name, and nothing changes.
    const int stray = *place_box_brush(ed, {50, 0, 50}, {52, 2, 52});
    REQUIRE(select(ed, {stray}).ok());
    auto refused = subtract_selected_brushes(ed);
    REQUIRE_FALSE(refused.ok());
    CHECK(refused.error().message.find("brush " + std::to_string(stray) + " overlaps no other brush") !=
          std::string::npos);
    CHECK(editor_test::brush_count(ed) == 4);
}

TEST_CASE("brushes: hollow, merge and clip; a non-convex merge and an empty clip are refused") {
    Editor ed;
    const int room = *place_box_brush(ed, {0, 0, 0}, {10, 6, 10});
    REQUIRE(hollow_selected_brushes(ed, 0.5f).ok());
    CHECK(editor_test::brush_count(ed) == 6);
    CHECK(brush_edit_total_volume(ed) == doctest::Approx(600.0 - 9.0 * 5.0 * 9.0));
    // The top piece (wholly in the top 0.5) is the room's ceiling; the walls and the floor are not.
    int ceilings = 0;
    for (const level::Entity& e : ed.doc().level.entities)
        if (const auto* b = e.try_as<level::BrushProps>(); b && b->ceiling) {
            ++ceilings;
            CHECK(editor_test::world_brush_of(ed, e.id).bounds_min().y == doctest::Approx(5.5));
        }
    CHECK(ceilings == 1);
    REQUIRE(ed.undo());
    CHECK(editor_test::brush_count(ed) == 1);

    const int right = *place_box_brush(ed, {10, 0, 0}, {14, 6, 10});
    REQUIRE(select(ed, {room, right}).ok());
    REQUIRE(merge_selected_brushes(ed).ok());
    CHECK(editor_test::brush_count(ed) == 1);
    CHECK(editor_test::world_brush_of(ed, room).volume() == doctest::Approx(14.0 * 6.0 * 10.0));
    const int corner = *place_box_brush(ed, {14, 0, 10}, {16, 6, 12});
    REQUIRE(select(ed, {room, corner}).ok());
    auto l_shape = merge_selected_brushes(ed);
    REQUIRE_FALSE(l_shape.ok());
    CHECK(l_shape.error().message.find("do not make one convex brush") != std::string::npos);

    REQUIRE(select(ed, {room}).ok());
    REQUIRE(clip_selected_brushes(ed, {0, 3, 0}, {0, 1, 0}, ClipKeep::back).ok());
    CHECK(editor_test::world_brush_of(ed, room).bounds_max().y == doctest::Approx(3.0));
    REQUIRE(clip_selected_brushes(ed, {7, 0, 0}, {1, 0, 0}, ClipKeep::both).ok());
    CHECK(editor_test::brush_count(ed) == 3);
    REQUIRE(select(ed, {room}).ok());
    auto nothing = clip_selected_brushes(ed, {-5, 0, 0}, {1, 0, 0}, ClipKeep::back);
    REQUIRE_FALSE(nothing.ok());
    CHECK(nothing.error().message.find("leaves nothing of brush " + std::to_string(room)) !=
          std::string::npos);
}

TEST_CASE("brushes: script commands place, cut and clip; bad words are reported at their column") {
    Editor ed;
    const char* script = R"(brush box -8,0,-0.5 8,8,0.5 material concrete name Arch wall
brush extrude z -1 1 -2,0 2,0 2,4 1.4142,5.4142 0,6 -1.4142,5.4142 -2,4 material metal
brush subtract
brush ramp 10,0,0 16,4,8 up -z material tiles
brush box 20,0,0 24,4,4
brush clip 0,3,0 0,1,1 front
expect count brush 8
)";
    auto report = run_script_text(script, "arch.kss", {}, ed);
    REQUIRE_MESSAGE(report.ok(), (report.ok() ? std::string() : report.error().str()));
    CHECK(brush_edit_total_volume(ed) > 0.0);

    Editor fresh;
    auto bad = run_script_text("brush ramp 0,0,0 4,4,4 up +y\n", "bad.kss", {}, fresh);
    REQUIRE_FALSE(bad.ok());
    CHECK(bad.error().str().find("bad.kss:1:27: expected the high side") != std::string::npos);
    auto few = run_script_text("brush extrude y 0 4 0,0 1,0\n", "few.kss", {}, fresh);
    REQUIRE_FALSE(few.ok());
    CHECK(few.error().str().find("at least 3 points") != std::string::npos);
    auto stray = run_script_text("brush box 0,0,0 2,2,2\nbrush subtract\n", "stray.kss", {}, fresh);
    REQUIRE_FALSE(stray.ok());
    CHECK(stray.error().str().find("stray.kss:2: Subtract: brush 1 overlaps no other brush") !=
          std::string::npos);
}

TEST_CASE("brushes: intersect keeps the common part in the first brush, one step; refusals name both") {
    Editor ed;
    auto a = place_box_brush(ed, {0, 0, 0}, {4, 4, 4}, {"metal", "A"});
    auto b = place_box_brush(ed, {2, 0, 2}, {6, 4, 6}, {"tiles", "B"});
    auto far = place_box_brush(ed, {20, 0, 20}, {22, 2, 22});
    REQUIRE((a.ok() && b.ok() && far.ok()));
    const size_t steps = ed.history().undo_count();
    REQUIRE(select(ed, {*a}).ok());
    auto alone = intersect_selected_brushes(ed);
    REQUIRE_FALSE(alone.ok());
    CHECK(alone.error().message.find("select two or more brushes") != std::string::npos);
    REQUIRE(select(ed, {*a, *b, *far}).ok());
    auto apart = intersect_selected_brushes(ed);
    REQUIRE_FALSE(apart.ok());
    CHECK(apart.error().message.find("brush " + std::to_string(*a) + " (\"A\") and brush " +
                                     std::to_string(*far) + " do not overlap") != std::string::npos);
    CHECK(ed.history().undo_count() == steps);
    REQUIRE(select(ed, {*a, *b}).ok());
    REQUIRE(intersect_selected_brushes(ed).ok());
    CHECK(ed.history().undo_count() == steps + 1);
    CHECK(ed.level().find(*b) == nullptr);
    const brush::Brush common = editor_test::world_brush_of(ed, *a);
    CHECK(common.volume() == doctest::Approx(2 * 4 * 2));
    CHECK(common.bounds_min() == DVec3(2, 0, 2));
    CHECK(ed.doc().selection == std::vector<int>{*a});
    REQUIRE(ed.undo());
    CHECK(editor_test::brush_count(ed) == 3);
    CHECK(editor_test::world_brush_of(ed, *a).volume() == doctest::Approx(64.0));

    auto report = run_script_text("select " + std::to_string(*a) + " " + std::to_string(*b) +
                                      "\nbrush intersect\nexpect count brush 2\n",
                                  "intersect.kss", {}, ed);
    REQUIRE_MESSAGE(report.ok(), (report.ok() ? std::string() : report.error().str()));
}

TEST_CASE("brushes: the CSG menu says why an item does not apply") {
    Editor ed;
    CHECK(csg_unavailable(ed.doc(), CsgOp::hollow) == "select brushes first");
    auto a = place_box_brush(ed, {0, 0, 0}, {4, 4, 4});
    REQUIRE(a.ok());
    CHECK(csg_unavailable(ed.doc(), CsgOp::hollow).empty());
    CHECK(csg_unavailable(ed.doc(), CsgOp::merge) == "select two or more brushes");
    CHECK(csg_unavailable(ed.doc(), CsgOp::subtract) == "there is no other unlocked brush to cut");
    auto b = place_box_brush(ed, {2, 0, 2}, {6, 4, 6});
    REQUIRE(b.ok());
    CHECK(csg_unavailable(ed.doc(), CsgOp::subtract).empty());
    REQUIRE(select(ed, {*a, *b}).ok());
    CHECK(csg_unavailable(ed.doc(), CsgOp::intersect).empty());
    REQUIRE(run_script_text("lock " + std::to_string(*b) + "\n", "lock.kss", {}, ed).ok());
    ed.set_selection({*a, *b});
    CHECK(csg_unavailable(ed.doc(), CsgOp::merge).find("is locked") != std::string::npos);
}

TEST_CASE("brushes: subtract skips far brushes by their bounds and cuts exactly what cutting all would") {
    // Boxes around a cutter: overlapping it, flush against it (touching a face: not cut), 1e-4 away, turned
    // (their boxes overlapping the cutter's, the brushes perhaps not), wholly inside it, and far away.
    Editor ed;
    ed.grid().snap = false;
    std::vector<int> ids;
    const auto box = [&](Vec3 a, Vec3 b, float turn = 0.0f) {
        auto id = place_box_brush(ed, a, b, {"concrete", ""});
        REQUIRE(id.ok());
        if (turn != 0.0f) {
            REQUIRE(select(ed, {*id}).ok());
            REQUIRE(rotate_selection_about(ed, 1, turn, RotationSpace::World, false).ok());
        }
        ids.push_back(*id);
    };
    box({-3, 0, -3}, {-1, 2, -1});                // overlaps the cutter's corner
    box({1, 0, -1}, {3, 2, 1});                   // flush against its +x face
    box({-1, 2.0001f, -1}, {1, 3, 1});            // just above it
    box({1.3f, 0, 1.3f}, {3.3f, 2, 3.3f}, 45.0f); // turned: a corner reaches into the cutter
    box({-1.2f, 0.5f, 1.5f}, {1.2f, 1.5f, 4}, 10.0f);
    box({-0.5f, 0.8f, -0.5f}, {0.5f, 1.5f, 0.5f}); // wholly inside: removed
    for (int i = 0; i < 20; ++i) box({10.0f + i * 3, 0, 0}, {11.0f + i * 3, 1, 1}, 7.0f * i);
    auto cutter = place_box_brush(ed, {-1.5f, 0.5f, -1.5f}, {1, 2, 1.6f}, {"wood", ""});
    REQUIRE(cutter.ok());

    // The reference: every brush taken into the world and cut.
    const brush::Brush cutter_world = editor_test::world_brush_of(ed, *cutter);
    std::vector<int> cut_ids;
    size_t pieces = 0;
    for (int id : ids) {
        auto result = brush::subtract(editor_test::world_brush_of(ed, id), cutter_world);
        REQUIRE(result.ok());
        if (result->removed) cut_ids.push_back(id), pieces += result->fragments.size();
    }
    REQUIRE(cut_ids.size() >= 3);
    const level::Level before = ed.level();
    REQUIRE(select(ed, {*cutter}).ok());
    REQUIRE(subtract_selected_brushes(ed).ok());
    std::vector<int> changed;
    for (int id : ids)
        if (const level::Entity* now = ed.level().find(id); !now || !(*now == *before.find(id)))
            changed.push_back(id); // cut, or removed whole
    CHECK(changed == cut_ids);
    CHECK(editor_test::brush_count(ed) == static_cast<int>(ids.size() - cut_ids.size() + pieces));
}
