// The viewport camera's maths without a window: orthographic axis views (parallel rays, orientation, zoom
// about the cursor, pan, grid), perspective, and agreement of the closed-form rays and projection with the
// renderer's view-projection matrix (the picture) on ordinary and hard (far, tiny, grazing) cases.
#include "editor_test_util.h"
#include "view/view_camera.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace ks;
using namespace ks::editor;

using editor_test::kViewport;

namespace {

ViewCamera axis_view(ViewMode mode, Vec3 centre = Vec3(0.0f), float extent = 100.0f) {
    ViewCamera v;
    v.set_viewport(kViewport);
    v.set_view(mode, centre, extent);
    return v;
}

// The pixel a world point lands on in the picture: clip space of the renderer's matrix.
Vec2 picture_pixel(const ViewCamera& v, const Vec3& world) {
    const Vec4 clip = v.view_projection() * Vec4(world, 1.0f);
    const Vec2 ndc = Vec2(clip) / clip.w;
    return Vec2((ndc.x * 0.5f + 0.5f) * kViewport.x, (0.5f - ndc.y * 0.5f) * kViewport.y);
}

// Worst pixel error of ray(p) -> point along the ray -> project, over a grid of pixels and depths.
float worst_round_trip(const ViewCamera& v, float depth) {
    float worst = 0.0f;
    for (float y = 0.0f; y <= kViewport.y; y += kViewport.y / 6.0f)
        for (float x = 0.0f; x <= kViewport.x; x += kViewport.x / 8.0f) {
            const geometry::Ray r = v.ray(Vec2(x, y));
            Vec2 back;
            REQUIRE(v.project(r.origin + r.direction * depth, back));
            worst = std::max(worst, glm::length(back - Vec2(x, y)));
        }
    return worst;
}
} // namespace

TEST_CASE("axis views are orthographic and face the right way") {
    const ViewCamera top = axis_view(ViewMode::Top, Vec3(10, 0, -20));
    CHECK(top.orthographic());
    CHECK(top.camera.ortho_height == doctest::Approx(110.0f));
    CHECK(top.forward().y == doctest::Approx(-1.0f));
    CHECK(top.right().x == doctest::Approx(1.0f)); // east is right
    CHECK(top.up().z == doctest::Approx(-1.0f));   // north (-z) is up on screen
    Vec2 centre;
    REQUIRE(top.project(Vec3(10, 0, -20), centre));
    CHECK(centre.x == doctest::Approx(480.0f));
    CHECK(centre.y == doctest::Approx(270.0f));
    Vec2 north;
    REQUIRE(top.project(Vec3(10, 0, -30), north));
    CHECK(north.y < centre.y);

    const ViewCamera front = axis_view(ViewMode::Front);
    CHECK(front.forward().z == doctest::Approx(-1.0f));
    CHECK(front.up().y == doctest::Approx(1.0f));
    const ViewCamera side = axis_view(ViewMode::Side);
    CHECK(side.forward().x == doctest::Approx(-1.0f));
    CHECK(side.up().y == doctest::Approx(1.0f));
    CHECK(side.right().z == doctest::Approx(-1.0f));

    // Every corner of the framed box is inside the picture and between the clip planes.
    for (const ViewCamera* v : {&top, &front, &side})
        for (int i = 0; i < 8; ++i) {
            const Vec3 corner((i & 1) ? 50.0f : -50.0f, (i & 2) ? 16.0f : 0.0f, (i & 4) ? 50.0f : -50.0f);
            Vec2 p;
            REQUIRE(v->project(corner, p));
            CHECK(p.x >= 0.0f);
            CHECK(p.x <= kViewport.x);
            const float depth = glm::dot(corner - v->camera.position, v->forward());
            CHECK(depth > v->camera.near_plane);
            CHECK(depth < v->camera.far_plane);
        }
}

TEST_CASE("orthographic rays are parallel, start on the camera plane and project back to their pixel") {
    const ViewCamera top = axis_view(ViewMode::Top, Vec3(3, 0, 7), 60.0f);
    const geometry::Ray a = top.ray(Vec2(0, 0)), b = top.ray(Vec2(960, 540)), c = top.ray(Vec2(480, 270));
    for (const geometry::Ray& r : {a, b, c}) {
        CHECK(r.direction.x == doctest::Approx(0.0f));
        CHECK(r.direction.y == doctest::Approx(-1.0f));
        CHECK(r.direction.z == doctest::Approx(0.0f));
        CHECK(r.origin.y == doctest::Approx(top.camera.position.y)); // on the camera's plane
    }
    // Opposite corners are the picture's full width and height apart (66 units tall at 16:9).
    CHECK(b.origin.x - a.origin.x == doctest::Approx(66.0f * 960.0f / 540.0f));
    CHECK(b.origin.z - a.origin.z == doctest::Approx(66.0f));
    CHECK(c.origin.x == doctest::Approx(3.0f));
    CHECK(c.origin.z == doctest::Approx(7.0f));
    for (float depth : {1.0f, 100.0f, 500.0f}) CHECK(worst_round_trip(top, depth) < 1e-3f);
    CHECK(worst_round_trip(axis_view(ViewMode::Front), 150.0f) < 1e-3f);
    CHECK(worst_round_trip(axis_view(ViewMode::Side), 150.0f) < 1e-3f);
}

TEST_CASE("closed-form rays and projection agree with the picture's matrix in both projections") {
    ViewCamera persp;
    persp.set_viewport(kViewport);
    persp.camera.position = Vec3(12, 30, 40);
    persp.camera.yaw = radians(20.0f);
    persp.camera.pitch = radians(-40.0f);
    const ViewCamera top = axis_view(ViewMode::Top, Vec3(-30, 0, 15));
    const ViewCamera side = axis_view(ViewMode::Side, Vec3(0, 8, 0), 40.0f);
    for (const ViewCamera* v : {static_cast<const ViewCamera*>(&persp), &top, &side}) {
        const Mat4 inverse = glm::inverse(v->view_projection());
        for (Vec2 px : {Vec2(0, 0), Vec2(480, 270), Vec2(900, 40), Vec2(77, 500)}) {
            // The matrix's unprojection of the pixel at two depths gives the same line as ray().
            const float nx = 2.0f * px.x / kViewport.x - 1.0f, ny = 1.0f - 2.0f * px.y / kViewport.y;
            const Vec4 n = inverse * Vec4(nx, ny, -1.0f, 1.0f), f = inverse * Vec4(nx, ny, 1.0f, 1.0f);
            const Vec3 pn = Vec3(n) / n.w, pf = Vec3(f) / f.w;
            const geometry::Ray r = v->ray(px);
            CHECK(glm::dot(glm::normalize(pf - pn), r.direction) == doctest::Approx(1.0f).epsilon(1e-5));
            const Vec3 off = pn - r.origin;
            CHECK(glm::length(off - r.direction * glm::dot(off, r.direction)) < 1e-3f);
            // And project() puts points where the picture does.
            const Vec3 world = r.origin + r.direction * 37.0f;
            Vec2 p;
            REQUIRE(v->project(world, p));
            const Vec2 q = picture_pixel(*v, world);
            CHECK(glm::length(p - q) < 0.02f);
        }
    }
    CHECK(worst_round_trip(persp, 5.0f) < 2e-3f);
    CHECK(worst_round_trip(persp, 400.0f) < 0.02f);
}

TEST_CASE("hard cases: far from the origin, zoomed far in, and behind the camera") {
    // 5000 units out with a picture 2 units tall: float spacing there is 0.0005 units, an eighth of a
    // pixel (0.0037 units). The closed form stays within a pixel; the matrix inverse is printed beside it.
    ViewCamera far = axis_view(ViewMode::Top, Vec3(5000, 0, -5000), 10.0f);
    far.camera.ortho_height = 2.0f;
    const float closed_form = worst_round_trip(far, 100.0f);
    CHECK(closed_form < 1.0f);
    const Mat4 inverse = glm::inverse(far.view_projection());
    float matrix = 0.0f;
    for (float y = 0.0f; y <= kViewport.y; y += kViewport.y / 6.0f)
        for (float x = 0.0f; x <= kViewport.x; x += kViewport.x / 8.0f) {
            const float nx = 2.0f * x / kViewport.x - 1.0f, ny = 1.0f - 2.0f * y / kViewport.y;
            const Vec4 p = inverse * Vec4(nx, ny, 0.0f, 1.0f);
            matrix = std::max(matrix, glm::length(picture_pixel(far, Vec3(p) / p.w) - Vec2(x, y)));
        }
    MESSAGE("pixel round trip 5000 units out, 2-unit picture: closed form "
            << closed_form << " px, matrix inverse " << matrix << " px");

    // Zoom limits hold against absurd wheel values; NaN-free afterwards.
    ViewCamera v = axis_view(ViewMode::Top);
    v.zoom_at(1000.0f, Vec2(10, 10));
    CHECK(v.camera.ortho_height == doctest::Approx(0.5f));
    v.zoom_at(-5000.0f, Vec2(10, 10));
    CHECK(v.camera.ortho_height == doctest::Approx(20000.0f));
    CHECK(std::isfinite(v.camera.position.x));
    CHECK(std::isfinite(v.camera.position.z));

    // Points behind the camera do not project (so handles and boxes there are not drawn or hit).
    Vec2 p;
    CHECK_FALSE(v.project(v.camera.position - v.forward() * 1.0f, p));
    ViewCamera persp;
    persp.set_viewport(kViewport);
    CHECK_FALSE(persp.project(persp.camera.position - persp.forward() * 3.0f, p));
    CHECK_FALSE(persp.project(persp.camera.position, p));
}

TEST_CASE("zooming an axis view keeps the point under the cursor; panning follows the mouse") {
    ViewCamera v = axis_view(ViewMode::Top, Vec3(0.0f), 100.0f);
    const Vec2 cursor(700.0f, 120.0f);
    const Vec3 under = v.ray(cursor).origin;
    v.zoom_at(3.0f, cursor);
    CHECK(v.camera.ortho_height == doctest::Approx(110.0f * std::pow(0.85f, 3.0f)));
    const Vec3 after = v.ray(cursor).origin;
    CHECK(after.x == doctest::Approx(under.x).epsilon(1e-4));
    CHECK(after.z == doctest::Approx(under.z).epsilon(1e-4));

    // Pan: the world point that was under pixel p is under p + (dx, dy) afterwards.
    const Vec3 world = v.ray(Vec2(300, 300)).origin - v.forward() * 0.0f;
    v.pan_pixels(40.0f, -25.0f);
    Vec2 moved;
    REQUIRE(v.project(world + v.forward() * 10.0f, moved));
    CHECK(moved.x == doctest::Approx(340.0f).epsilon(1e-4));
    CHECK(moved.y == doctest::Approx(275.0f).epsilon(1e-4));

    // The same through update(): middle drag pans, right drag pans too in an axis view (no fly there).
    ViewInput in;
    in.hovered = true;
    in.mouse = Vec2(100, 100);
    in.right = true;
    CHECK(v.update(in, 0.016));
    in.mouse = Vec2(160, 100);
    const Vec3 before = v.camera.position;
    CHECK(v.update(in, 0.016));
    CHECK(v.orthographic());
    CHECK(v.camera.position.x == doctest::Approx(before.x - 60.0f * v.world_per_pixel(v.pivot)));
    in.right = false;
    CHECK_FALSE(v.update(in, 0.016));
    // The wheel zooms an axis view rather than dollying it.
    in.wheel = -2.0f;
    const float height = v.camera.ortho_height;
    v.update(in, 0.016);
    CHECK(v.camera.ortho_height > height);
}

TEST_CASE("orbiting an axis view turns it into a perspective view of the same size") {
    ViewCamera v = axis_view(ViewMode::Front, Vec3(0, 8, 0), 40.0f);
    const float wpp = v.world_per_pixel(v.pivot);
    ViewInput in;
    in.hovered = true;
    in.left = in.alt = true;
    in.mouse = Vec2(400, 300);
    v.update(in, 0.016); // grab: no motion yet
    CHECK_FALSE(v.orthographic());
    CHECK(v.mode == ViewMode::Perspective);
    CHECK(v.world_per_pixel(v.pivot) == doctest::Approx(wpp).epsilon(1e-3));
    in.mouse = Vec2(450, 300);
    v.update(in, 0.016);
    CHECK(v.camera.yaw == doctest::Approx(-50.0f * 0.005f));
}

TEST_CASE("perspective fly moves along the view with physical keys; wheel changes the speed") {
    ViewCamera v;
    v.set_viewport(kViewport);
    v.set_view(ViewMode::Perspective, Vec3(0.0f), 40.0f);
    ViewInput in;
    in.hovered = true;
    in.right = true;
    in.mouse = Vec2(200, 200);
    CHECK(v.update(in, 0.0));
    const Vec3 start = v.camera.position;
    const Vec3 fwd = v.forward();
    in.forward = true;
    CHECK(v.update(in, 0.5));
    CHECK(glm::length(v.camera.position - (start + fwd * 6.0f)) < 1e-4f); // 12 u/s for half a second
    in.wheel = 1.0f;
    v.update(in, 0.0);
    CHECK(v.speed == doctest::Approx(14.4f));
}

TEST_CASE("axis-view grid: the view plane's axes, spacing at least the minimum on screen") {
    ViewCamera top = axis_view(ViewMode::Top, Vec3(0.0f), 100.0f);
    GridPlan plan = plan_axis_grid(top, 1.0f, 10.0f);
    CHECK(plan.u_axis == 0);
    CHECK(plan.v_axis == 2);
    // 110 units over 540 px = 0.204 u/px: 1 and 2 are too dense (4.9, 9.8 px), 4 is the first >= 10 px.
    CHECK(plan.step == doctest::Approx(4.0f));
    CHECK(plan.step / top.world_per_pixel(top.pivot) >= 10.0f);
    // The lines cover the visible width exactly: first and last are within one step of the edges.
    const float half_w = 0.5f * 960.0f * top.world_per_pixel(top.pivot);
    CHECK(plan.u_first >= -half_w);
    CHECK(plan.u_first - plan.step < -half_w);
    const float last = plan.u_first + static_cast<float>(plan.u_count - 1) * plan.step;
    CHECK(last <= half_w);
    CHECK(last + plan.step > half_w);
    CHECK(std::fmod(std::abs(plan.u_first), plan.step) == doctest::Approx(0.0f));

    top.zoom_at(12.0f, Vec2(480, 270)); // zoomed in: the base step is wide enough
    plan = plan_axis_grid(top, 1.0f, 10.0f);
    CHECK(plan.step == doctest::Approx(1.0f));

    const GridPlan front = plan_axis_grid(axis_view(ViewMode::Front), 1.0f, 10.0f);
    CHECK(front.u_axis == 0);
    CHECK(front.v_axis == 1);
    const GridPlan side = plan_axis_grid(axis_view(ViewMode::Side), 1.0f, 10.0f);
    CHECK(side.u_axis == 2);
    CHECK(side.v_axis == 1);
}
