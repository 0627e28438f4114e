// The player start as a viewport object, without a window: selected (by id, by a click on its body, by the
// script's `select player_start`), moved and turned with the selection and the gizmo as one undo step each,
// drawn as a body-sized figure facing its yaw.
#include "editor_test_util.h"
#include "level/entity_shapes.h"
#include "model/edit_entities.h"
#include "model/edit_selection.h"
#include "model/edit_transforms.h"
#include "model/script.h"
#include "view/gizmo.h"
#include "view/picking.h"
#include "view/player_start_marker.h"

#include <algorithm>

using namespace ks;
using namespace ks::editor;

using editor_test::all_shown;

using editor_test::kViewport;
using editor_test::top_view;

namespace {

// A floor, a robot at (-6, 0, 0) and the player start at (4, 0, 6) facing -z, on a 1-unit grid.
Editor small_level() {
    Editor e;
    e.grid().step = 1.0f;
    REQUIRE(place(e, level::EntityType::Floor, Vec3(0.0f)).ok());
    REQUIRE(place(e, level::EntityType::Robot, Vec3(-6, 0, 0)).ok());
    REQUIRE(set_player_start(e, {Vec3(4, 0, 6), 0.0f}).ok());
    e.clear_selection();
    return e;
}
} // namespace

TEST_CASE("the player start is selected like an entity, alone or with others") {
    Editor editor = small_level();
    REQUIRE(select(editor, {kPlayerStartId}).ok());
    CHECK(editor.doc().player_start_selected());
    CHECK(selected_entities(editor).empty()); // it has no level entity
    REQUIRE(select(editor, {2}, SelectMode::Add).ok());
    CHECK(editor.doc().selection == std::vector<int>{kPlayerStartId, 2});
    REQUIRE(select(editor, {kPlayerStartId}, SelectMode::Toggle).ok());
    CHECK_FALSE(editor.doc().player_start_selected());
    REQUIRE(select(editor, {kPlayerStartId}).ok());
    select_all(editor); // Ctrl+A: the entities
    CHECK_FALSE(editor.doc().player_start_selected());
    editor.clear_selection();
    CHECK(editor.doc().selection.empty());
    // A player_start issue selects it (the start floats above the floor here).
    REQUIRE(set_player_start(editor, {Vec3(4, 2, 6), 0.0f}).ok());
    editor.validation_options().check_reachability = false;
    const auto& issues = editor.issues();
    const auto floating = std::find_if(issues.begin(), issues.end(),
                                       [](const Issue& i) { return i.rule == Rule::PlayerStart; });
    REQUIRE(floating != issues.end());
    REQUIRE(select_issue(editor, *floating).ok());
    CHECK(editor.doc().selection == std::vector<int>{kPlayerStartId});
}

TEST_CASE("moving and turning the selected player start are undoable steps, with entities too") {
    Editor editor = small_level();
    REQUIRE(select(editor, {kPlayerStartId}).ok());
    const size_t steps = editor.history().undo_count();
    REQUIRE(move_selection(editor, Vec3(2, 0, -3)).ok());
    CHECK(editor.level().player_start.position == Vec3(6, 0, 3));
    CHECK(editor.history().undo_count() == steps + 1);
    REQUIRE(move_selection(editor, Vec3(0.4f, 0, 0.3f), true).ok()); // snapped: stays on the grid
    CHECK(editor.level().player_start.position == Vec3(6, 0, 3));
    REQUIRE(rotate_selection(editor, 92.0f).ok()); // snapped to the 15-degree step
    CHECK(editor.level().player_start.yaw == 90.0f);
    CHECK(editor.level().player_start.position == Vec3(6, 0, 3)); // alone: turns in place
    const auto about_x = rotate_selection_about(editor, 0, 30.0f, RotationSpace::World);
    REQUIRE_FALSE(about_x.ok()); // it turns about y only
    CHECK(about_x.error().message.find("player start turns about y only") != std::string::npos);
    CHECK(editor.undo());
    CHECK(editor.level().player_start.yaw == 0.0f);
    CHECK(editor.undo());
    CHECK(editor.level().player_start.position == Vec3(4, 0, 6));
    CHECK(editor.doc().player_start_selected()); // undo restores the selection with it
    CHECK(editor.redo());
    CHECK(editor.level().player_start.position == Vec3(6, 0, 3));

    // With a robot: one step moves both; a half turn swings them about the centre between them.
    REQUIRE(select(editor, {2}, SelectMode::Add).ok());
    REQUIRE(move_selection(editor, Vec3(0, 0, 1)).ok());
    CHECK(editor.level().find(2)->position == Vec3(-6, 0, 1));
    CHECK(editor.level().player_start.position == Vec3(6, 0, 4));
    REQUIRE(rotate_selection(editor, 180.0f).ok());
    CHECK(editor.level().find(2)->position == Vec3(6, 0, 4));
    CHECK(editor.level().player_start.position == Vec3(-6, 0, 1));
    CHECK(editor.level().player_start.yaw == 180.0f);
    const std::string before = editor_test::text_of(editor);
    editor.undo();
    editor.undo();
    CHECK(editor.level().player_start.position == Vec3(6, 0, 3));
    CHECK(editor.level().find(2)->position == Vec3(-6, 0, 0));
    editor.redo();
    editor.redo();
    CHECK(editor_test::text_of(editor) == before);
}

TEST_CASE("a click on the start's body picks it before the floor under it; the gizmo drags it as one step") {
    Editor editor = small_level();
    const ViewCamera top = top_view();
    const Vec3 body = player_obb(editor.level().player_start).center;
    Vec2 at;
    REQUIRE(top.project(body, at));
    const auto ray = top.ray(at);
    CHECK(pick_entity(editor.doc(), ray, all_shown).id == 1); // the floor is under it
    CHECK(pick_selectable(editor.doc(), ray, all_shown, true).id == kPlayerStartId);
    CHECK(pick_selectable(editor.doc(), ray, all_shown, false).id == 1); // its overlay hidden: not picked
    CHECK(pick_selectable(editor.doc(), top.ray(at + Vec2(200, 0)), all_shown, true).id != kPlayerStartId);

    REQUIRE(select(editor, {kPlayerStartId}).ok());
    const GizmoFrame frame = gizmo_frame(editor.doc(), RotationSpace::World);
    CHECK(frame.pivot == editor.level().player_start.position);
    CHECK_FALSE(frame.three_axes); // the yaw ring only
    const GizmoShape shape = gizmo_shape(top, frame);
    CHECK(shape.ring_visible[1]);
    CHECK_FALSE(shape.ring_visible[0]);
    CHECK_FALSE(shape.ring_visible[2]);
    Gizmo gizmo;
    const Vec2 grab = (shape.centre + shape.tips[0]) * 0.5f;
    REQUIRE(gizmo.hit(top, frame, grab) == Handle::AxisX);
    const size_t steps = editor.history().undo_count();
    gizmo.begin(editor, top, frame, Handle::AxisX, grab);
    const float wpp = top.world_per_pixel(frame.pivot);
    CHECK(gizmo.drag(editor, top, grab + Vec2(40, 0)).empty());
    CHECK(gizmo.drag(editor, top, grab + Vec2(80, 0)).empty());
    gizmo.end(editor);
    CHECK(editor.level().player_start.position.x == doctest::Approx(4.0f + std::round(80.0f * wpp)));
    CHECK(editor.history().undo_count() == steps + 1);

    // Turn it with the yaw ring: a quarter turn counterclockwise seen from above.
    gizmo.mode = GizmoMode::Rotate;
    const GizmoFrame moved = gizmo_frame(editor.doc(), RotationSpace::Local);
    const GizmoShape ring = gizmo_shape(top, moved);
    const float r = ring.length / wpp;
    const Vec2 east = ring.centre + Vec2(r, 0), north = ring.centre + Vec2(0, -r);
    REQUIRE(gizmo.hit(top, moved, east) == Handle::RingY);
    gizmo.begin(editor, top, moved, Handle::RingY, east);
    gizmo.drag(editor, top, north);
    gizmo.end(editor);
    CHECK(editor.level().player_start.yaw == 90.0f);
    CHECK(editor.history().undo_count() == steps + 2);
    editor.undo();
    editor.undo();
    CHECK(editor.level().player_start == level::PlayerStart{Vec3(4, 0, 6), 0.0f});
}

TEST_CASE("the start's figure is the player's body with its facing on the floor and at eye height") {
    const level::PlayerStart start{Vec3(10, 2, -4), 90.0f}; // yaw 90 faces -x
    CHECK(glm::length(player_start_facing(start) - Vec3(-1, 0, 0)) < 1e-6f);
    CHECK(glm::length(player_start_facing({Vec3(0.0f), 0.0f}) - Vec3(0, 0, -1)) < 1e-6f);
    std::vector<MarkerLine> lines;
    player_start_figure(start, lines);
    REQUIRE(lines.size() > 40);
    Vec3 lo(1e9f), hi(-1e9f);
    for (const MarkerLine& l : lines)
        lo = glm::min(lo, glm::min(l.a, l.b)), hi = glm::max(hi, glm::max(l.a, l.b));
    CHECK(lo.y == doctest::Approx(start.position.y));                        // from the feet ...
    CHECK(hi.y == doctest::Approx(start.position.y + level::kPlayerHeight)); // ... to the top of the head
    // The arrow reaches three units ahead (-x) and nothing reaches as far behind.
    CHECK(lo.x == doctest::Approx(start.position.x - kStartArrowLength));
    CHECK(hi.x == doctest::Approx(start.position.x + level::kPlayerRadius));
    CHECK(hi.z - lo.z == doctest::Approx(2.0f * level::kPlayerRadius).epsilon(0.01));
}

TEST_CASE("scripts select, move, turn and check the player start") {
    Editor editor;
    const char* script = R"(grid 1 15
place floor at 0,0,0
player_start 2,0,3 yaw 0
select player_start
expect selected 1
move 3,0,0
expect player_start 5,0,3 yaw 0
rotate 45
expect player_start 5,0,3 yaw 45
select add 1
expect selected 2
undo 2
expect player_start 2,0,3 yaw 0
)";
    auto report = run_script_text(script, "start.kss", {}, editor);
    REQUIRE_MESSAGE(report.ok(), report.error().str());
    CHECK(report->expectations_checked == 5);
    auto wrong = run_script_text("expect player_start 9,9,9\n", "wrong.kss", {}, editor);
    REQUIRE_FALSE(wrong.ok());
    CHECK(wrong.error().str().find("the player start is at 2,0,3 yaw 0, expected 9,9,9") !=
          std::string::npos);
    auto bad = parse_script("select player_stat\n", "bad.kss");
    CHECK_FALSE(bad.ok());
    CHECK_FALSE(parse_script("lock player_start\n", "bad.kss").ok()); // only selection knows it
}
