// The 4-up view without a window (view/quad_view.h): four equal panes that tile the viewport at any size,
// the pane under a point, each pane's own camera (entering takes the single view into its pane, leaving
// gives back the active one, the others keep their pan and zoom), and picking through every pane's camera
// at its own pane size, before and after a resize. And the axis views' section (view/section_view.h).
#include "editor_test_util.h"
#include "model/edit_entities.h"
#include "model/edit_selection.h"
#include "view/picking.h"
#include "view/quad_view.h"
#include "view/section_view.h"

using namespace ks;
using namespace ks::editor;

using editor_test::all_shown;

namespace {
// Sets each pane's viewport to its rectangle's size, as the window does every frame.
void lay_out(QuadView& quad, const std::array<PaneRect, kQuadPanes>& panes) {
    for (int i = 0; i < kQuadPanes; ++i)
        quad.cameras[static_cast<size_t>(i)].set_viewport(panes[static_cast<size_t>(i)].size);
}
} // namespace

TEST_CASE("the 4-up panes tile the viewport in four equal whole-pixel panes at any size") {
    for (const Vec2 size : {Vec2(960, 540), Vec2(961, 541), Vec2(1280, 700), Vec2(300, 200), Vec2(3, 3)}) {
        CAPTURE(size.x);
        CAPTURE(size.y);
        const Vec2 origin(240.5f, 58.0f);
        const auto panes = quad_panes(origin, size, 2.0f);
        for (const PaneRect& p : panes) {
            CHECK(p.size == panes[0].size); // one size: the renderer's targets are reused
            CHECK(p.size.x >= 1.0f);
            CHECK(p.size.y >= 1.0f);
            CHECK(p.origin == glm::round(p.origin));
            CHECK(p.size == glm::round(p.size));
        }
        if (size.x < 10.0f) continue;
        CHECK(panes[0].origin == glm::round(origin));
        CHECK(panes[1].origin.x == panes[0].origin.x + panes[0].size.x + 2.0f); // right of it, a gap between
        CHECK(panes[2].origin.y == panes[0].origin.y + panes[0].size.y + 2.0f);
        CHECK(panes[3].origin.x + panes[3].size.x <= std::round(origin.x) + size.x);
        CHECK(panes[3].origin.y + panes[3].size.y <= std::round(origin.y) + size.y);
        CHECK(panes[3].origin.x + panes[3].size.x >= std::round(origin.x) + size.x - 1.0f); // no strip lost
        for (int i = 0; i < kQuadPanes; ++i)
            CHECK(pane_at(panes, panes[static_cast<size_t>(i)].origin +
                                     panes[static_cast<size_t>(i)].size * 0.5f) == i);
        CHECK(pane_at(panes, Vec2(panes[1].origin.x - 1.0f, panes[1].origin.y + 5.0f)) == -1); // the gap
        CHECK(pane_at(panes, origin - Vec2(5.0f)) == -1);
    }
    CHECK(kQuadModes[0] == ViewMode::Top);
    CHECK(kQuadModes[3] == ViewMode::Perspective);
}

TEST_CASE("entering the 4-up view frames the panes once, takes the single view into its pane, and leaving "
          "gives the active pane back") {
    QuadView quad;
    ViewCamera single;
    single.set_viewport(Vec2(960, 540));
    frame_box(single, ViewMode::Front, Vec3(-10), Vec3(10));
    single.zoom_at(3.0f, Vec2(100, 100)); // the designer's own zoom
    quad.enter(single, Vec3(-40.0f), Vec3(40.0f), Vec2(479, 269));
    CHECK(quad.on);
    CHECK(quad.active == 1); // the front pane
    CHECK(quad.cameras[1].camera.position == single.camera.position);
    CHECK(quad.cameras[1].camera.ortho_height == single.camera.ortho_height);
    for (int i = 0; i < kQuadPanes; ++i)
        CHECK(quad.cameras[static_cast<size_t>(i)].mode == kQuadModes[static_cast<size_t>(i)]);
    CHECK(quad.cameras[0].orthographic());
    CHECK_FALSE(quad.cameras[3].orthographic());

    // Pan the top pane; leave from the side pane; enter again: the top pane is where it was left.
    quad.cameras[0].set_viewport(Vec2(479, 269));
    quad.cameras[0].pan_pixels(50.0f, 0.0f);
    const Vec3 panned = quad.cameras[0].camera.position;
    quad.active = 2;
    const ViewCamera back = quad.leave();
    CHECK_FALSE(quad.on);
    CHECK(back.mode == ViewMode::Side);
    quad.enter(back, Vec3(-1000.0f), Vec3(1000.0f), Vec2(479, 269));
    CHECK(quad.active == 2);
    CHECK(quad.cameras[0].camera.position == panned);
}

TEST_CASE("a click picks through each pane's own camera, before and after the viewport is resized") {
    Editor editor;
    editor.grid().step = 1.0f;
    const int robot = *place(editor, level::EntityType::Robot, Vec3(12, 0, -8));
    const int pickup = *place(editor, level::EntityType::Pickup, Vec3(-15, 0, 10));
    QuadView quad;
    ViewCamera single;
    single.set_viewport(Vec2(960, 540));
    frame_box(single, ViewMode::Perspective, Vec3(-30, 0, -30), Vec3(30, 10, 30));
    quad.enter(single, Vec3(-30, 0, -30), Vec3(30, 10, 30), Vec2(479, 269));
    CHECK(quad.active == 3);
    for (const Vec2 size : {Vec2(960, 540), Vec2(1400, 380), Vec2(700, 640)}) {
        CAPTURE(size.x);
        const auto panes = quad_panes(Vec2(0.0f), size, 2.0f);
        lay_out(quad, panes);
        for (int i = 0; i < kQuadPanes; ++i) {
            CAPTURE(i);
            const ViewCamera& view = quad.cameras[static_cast<size_t>(i)];
            for (const auto& [id, centre] :
                 {std::pair{robot, Vec3(12, 1.5f, -8)}, std::pair{pickup, Vec3(-15, 0.5f, 10)}}) {
                Vec2 at;
                REQUIRE(view.project(centre, at));
                CHECK(at.x >= 0.0f);
                CHECK(at.x < panes[static_cast<size_t>(i)].size.x); // framed: inside its pane
                CHECK(at.y >= 0.0f);
                CHECK(at.y < panes[static_cast<size_t>(i)].size.y);
                CHECK(pick_entity(editor.doc(), view.ray(at), all_shown).id == id);
            }
        }
    }
}

TEST_CASE("fit_box fills an axis pane with the two sides of the box it shows, at the pane's aspect") {
    const Vec3 lo(-100, 0, -30), hi(60, 16, 50); // 160 wide (x), 80 deep (z), 16 high
    for (const Vec2 pane : {Vec2(479, 269), Vec2(300, 500)})
        for (const ViewMode mode : {ViewMode::Top, ViewMode::Front, ViewMode::Side}) {
            CAPTURE(pane.x);
            CAPTURE(view_mode_name(mode));
            ViewCamera view;
            fit_box(view, mode, lo, hi, pane);
            CHECK(view.viewport() == pane);
            // Every corner of the box is in the picture, and the box fills it along one side (1/1.1).
            Vec2 min_px(1e9f), max_px(-1e9f);
            for (int corner = 0; corner < 8; ++corner) {
                const Vec3 p((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y,
                             (corner & 4) ? hi.z : lo.z);
                Vec2 at;
                REQUIRE(view.project(p, at));
                min_px = glm::min(min_px, at), max_px = glm::max(max_px, at);
            }
            CHECK(min_px.x >= -0.5f);
            CHECK(min_px.y >= -0.5f);
            CHECK(max_px.x <= pane.x + 0.5f);
            CHECK(max_px.y <= pane.y + 0.5f);
            const Vec2 filled = (max_px - min_px) / pane;
            CHECK(std::max(filled.x, filled.y) == doctest::Approx(1.0f / 1.1f).epsilon(0.02));
        }
}

TEST_CASE("the section hides what stands between the front or side camera and the selection, nothing else") {
    Editor editor;
    editor.grid().step = 1.0f;
    using level::EntityType;
    const int floor = *place(editor, EntityType::Floor, Vec3(0, 0, 0)); // 20 x 20: z and x in -10 .. 10
    const int south = *place(editor, EntityType::Wall, Vec3(0, 0, 10));
    const int north = *place(editor, EntityType::Wall, Vec3(0, 0, -10));
    const int east = *place(editor, EntityType::Wall, Vec3(10, 0, 0), 90.0f);
    const int robot = *place(editor, EntityType::Robot, Vec3(0, 0, 0)); // selected
    auto entity = [&](int id) { return *editor.level().find(id); };
    ViewCamera view;
    view.set_viewport(Vec2(960, 540));

    view.set_view(ViewMode::Front, Vec3(0.0f), 40.0f); // looking along -z: the south wall is in front
    auto cut = section_cut(editor, view);
    REQUIRE(cut);
    CHECK(in_front_of_cut(*cut, entity(south)));
    CHECK_FALSE(in_front_of_cut(*cut, entity(north)));
    CHECK_FALSE(in_front_of_cut(*cut, entity(floor))); // reaches behind the robot
    CHECK_FALSE(in_front_of_cut(*cut, entity(east)));  // beside it, not in front
    CHECK_FALSE(in_front_of_cut(*cut, entity(robot)));

    view.set_view(ViewMode::Side, Vec3(0.0f), 40.0f); // looking along -x: the east wall is in front
    cut = section_cut(editor, view);
    REQUIRE(cut);
    CHECK(in_front_of_cut(*cut, entity(east)));
    CHECK_FALSE(in_front_of_cut(*cut, entity(south)));
    CHECK_FALSE(in_front_of_cut(*cut, entity(robot)));
    const std::uint64_t side_key = section_key(cut);
    CHECK(side_key != 0);

    // The cut follows the selection, and is the picture's key.
    REQUIRE(select(editor, {south}).ok());
    view.set_view(ViewMode::Front, Vec3(0.0f), 40.0f);
    cut = section_cut(editor, view);
    REQUIRE(cut);
    CHECK_FALSE(in_front_of_cut(*cut, entity(south)));
    CHECK(section_key(cut) != side_key);

    // No cut in the perspective and top views, or with nothing selected.
    view.set_view(ViewMode::Perspective, Vec3(0.0f), 40.0f);
    CHECK_FALSE(section_cut(editor, view));
    view.set_view(ViewMode::Top, Vec3(0.0f), 40.0f);
    CHECK_FALSE(section_cut(editor, view));
    view.set_view(ViewMode::Front, Vec3(0.0f), 40.0f);
    editor.clear_selection();
    CHECK_FALSE(section_cut(editor, view));
    CHECK(section_key(std::nullopt) == 0);
}
