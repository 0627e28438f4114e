// The hard cases of issue 25: slivers (faces 1e-4 apart), nearly parallel planes (1e-6 rad), coordinates up
// to +-10 000, coplanar CSG far out, and repetition without drift. Errors are measured against the exact
// answers worked out by hand.
#include "brush/brush_build.h"
#include "brush/brush_clip.h"
#include "brush/brush_csg.h"
#include "brush/texture_mapping.h"
#include "brush_checks.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace ks;
using namespace ks::brush;
using ks::brush_test::audit;
using ks::brush_test::has_vertex;

namespace {

Brush box(const DVec3& lo, const DVec3& hi) {
    auto b = make_box(lo, hi);
    REQUIRE(b.ok());
    return *b;
}

// The farthest any vertex lies from the nearest of `expected`.
double worst_distance(const Brush& b, const std::vector<DVec3>& expected) {
    double worst = 0;
    for (const DVec3& v : b.vertices()) {
        double nearest = 1e300;
        for (const DVec3& e : expected) nearest = std::min(nearest, glm::length(v - e));
        worst = std::max(worst, nearest);
    }
    return worst;
}

// A unit-square-based block [0,1]^2 x [0,1] (z) whose top is a roof of two planes meeting at x = 0.5, each
// tilted by `angle` from flat, placed at `at`; its planes are anchored at `at`.
Result<Brush> shallow_roof(double angle, const DVec3& at) {
    const double s = std::sin(angle), c = std::cos(angle);
    const double ridge = 1.0 + 0.5 * std::tan(angle);
    std::vector<Face> faces = {{{{-1, 0, 0}, 0.0}, {}},
                               {{{1, 0, 0}, 1.0}, {}},
                               {{{0, -1, 0}, 0.0}, {}},
                               {{{0, 0, -1}, 0.0}, {}},
                               {{{0, 0, 1}, 1.0}, {}}};
    faces.push_back({{{-s, c, 0}, c * ridge - s * 0.5}, {}}); // through (0.5, ridge), falling towards x = 0
    faces.push_back({{{s, c, 0}, c * ridge + s * 0.5}, {}});  // falling towards x = 1
    return Brush::from_anchored_faces(at, faces);
}

} // namespace

TEST_CASE("slivers: faces 1e-4 apart make valid brushes with exact vertices") {
    const Brush sheet = box({0, 0, 0}, {10, 1e-4, 10});
    CHECK(audit(sheet).empty());
    CHECK(sheet.vertices().size() == 8);
    CHECK(sheet.volume() == doctest::Approx(1e-2).epsilon(1e-12));
    CHECK(has_vertex(sheet, {10, 1e-4, 10}, 0.0));

    const Brush cube = box({0, 0, 0}, {1, 1, 1});
    auto parts = split(cube, {{0, 1, 0}, 1.0 - 1e-4});
    REQUIRE(parts.ok());
    REQUIRE(parts->front);
    CHECK(audit(*parts->front).empty());
    CHECK(parts->front->volume() == doctest::Approx(1e-4).epsilon(1e-10));
    CHECK(parts->back->volume() + parts->front->volume() == doctest::Approx(1.0).epsilon(1e-15));

    // A wedge 1e-4 thick at one edge and nothing at the other.
    const DVec3 n = glm::normalize(DVec3(1e-4, 1, 0));
    auto wedge = clip(cube, {n, glm::dot(n, DVec3(0, 1, 0))}, ClipSide::keep_front);
    REQUIRE(wedge.ok());
    CHECK(audit(*wedge).empty());
    CHECK(wedge->vertices().size() == 6);
    CHECK(wedge->volume() == doctest::Approx(0.5e-4).epsilon(1e-10));
    CHECK(worst_distance(*wedge,
                         {{0, 1, 0}, {0, 1, 1}, {1, 1, 0}, {1, 1, 1}, {1, 1 - 1e-4, 0}, {1, 1 - 1e-4, 1}}) <
          1e-15);

    // Subtract leaving a sliver fragment 1e-4 thick.
    auto r = subtract(box({0, 0, 0}, {4, 4, 4}), box({-1, -1, -1}, {5, 4 - 1e-4, 5}));
    REQUIRE(r.ok());
    REQUIRE(r->fragments.size() == 1);
    CHECK(audit(r->fragments[0]).empty());
    CHECK(r->fragments[0].volume() == doctest::Approx(16e-4).epsilon(1e-10));
}

TEST_CASE("nearly parallel planes: a roof 1e-6 rad from flat, near the origin and at 10 000") {
    for (const DVec3 at : {DVec3(0.0), DVec3(-9999, 9999, 9999)}) {
        const double angle = 1e-6;
        auto roof = shallow_roof(angle, at);
        REQUIRE(roof.ok());
        CHECK(audit(*roof).empty());
        CHECK(roof->vertices().size() == 10);
        const double ridge = 1.0 + 0.5 * std::tan(angle);
        std::vector<DVec3> expected;
        for (double z : {0.0, 1.0})
            for (DVec3 p :
                 {DVec3(0, 0, z), DVec3(1, 0, z), DVec3(0, 1, z), DVec3(1, 1, z), DVec3(0.5, ridge, z)})
                expected.push_back(p + at);
        const double error = worst_distance(*roof, expected);
        MESSAGE("roof 1e-6 rad at " << at.x << ": worst vertex error " << error);
        CHECK(error < 1e-9);
        CHECK(roof->volume() == doctest::Approx(1.0 + 0.25 * std::tan(angle)).epsilon(1e-12));
    }
}

TEST_CASE("nearly parallel planes: a clip 1e-6 rad off a face, and a slab 1e-6 rad from parallel") {
    const Brush cube = box({0, 0, 0}, {1, 1, 1});
    const double a = 1e-6;
    const Plane tilted{{std::sin(a), std::cos(a), 0},
                       std::sin(a) * 0.5 + std::cos(a) * 1.0}; // through (0.5, 1)
    auto parts = split(cube, tilted);
    REQUIRE_MESSAGE(parts.ok(), (parts.ok() ? "" : parts.error().str()));
    REQUIRE(parts->front);
    REQUIRE(parts->back);
    CHECK(audit(*parts->front).empty());
    CHECK(audit(*parts->back).empty());
    CHECK(parts->front->volume() == doctest::Approx(0.125 * std::tan(a)).epsilon(1e-6));
    CHECK(std::abs(parts->front->volume() + parts->back->volume() - 1.0) < 1e-15);
    auto slab = Brush::from_faces({{{{0, -1, 0}, 0.0}, {}},
                                   {{{std::sin(a), std::cos(a), 0}, 1.0}, {}},
                                   {{{-1, 0, 0}, 100.0}, {}},
                                   {{{1, 0, 0}, 100.0}, {}},
                                   {{{0, 0, -1}, 1.0}, {}},
                                   {{{0, 0, 1}, 1.0}, {}}});
    REQUIRE(slab.ok());
    CHECK(audit(*slab).empty());
    CHECK(slab->volume() == doctest::Approx(2.0 * 200.0 / std::cos(a)).epsilon(1e-9));
}

TEST_CASE("coordinates up to +-10 000: boxes, clips, hulls and CSG keep their precision") {
    for (const DVec3 far : {DVec3(9990, -10000, 9995), DVec3(-10000, 10000, -10000)}) {
        const Brush b = box(far, far + DVec3(10, 4, 0.5));
        CHECK(audit(b).empty());
        CHECK(has_vertex(b, far + DVec3(10, 4, 0.5), 0.0));
        CHECK(b.volume() == doctest::Approx(20.0).epsilon(1e-12));
        // A window cut through the wall: 4 fragments, coplanar with nothing, volumes conserved.
        auto window = subtract(b, box(far + DVec3(3, 1, -1), far + DVec3(5, 3, 1.5)));
        REQUIRE(window.ok());
        CHECK(window->fragments.size() == 4);
        double sum = window->removed->volume();
        for (const Brush& f : window->fragments) {
            CHECK(audit(f).empty());
            sum += f.volume();
        }
        CHECK(std::abs(sum - 20.0) < 1e-12 * 20.0);
        CHECK(window->removed->volume() == doctest::Approx(2.0).epsilon(1e-12));
        // Coplanar CSG far out: a notch flush with the top and the front.
        auto notch = subtract(b, box(far + DVec3(8, 2, 0), far + DVec3(10, 4, 0.5)));
        REQUIRE(notch.ok());
        CHECK(notch->fragments.size() == 2);
        for (const Brush& f : notch->fragments) CHECK(audit(f).empty());
        // A slanted clip: its new vertices lie on the cut plane to 1e-11.
        const Plane cut{glm::normalize(DVec3(1, 2, 3)),
                        glm::dot(glm::normalize(DVec3(1, 2, 3)), far + DVec3(5, 2, 0.25))};
        auto clipped = clip(b, cut);
        REQUIRE(clipped.ok());
        CHECK(audit(*clipped, 1e-9).empty());
        for (const DVec3& v : clipped->vertices()) CHECK(cut.signed_distance(v) < 1e-11);
        // The hull of the wall's corners and its derived vertices agree.
        auto hull = make_from_points(b.vertices());
        REQUIRE(hull.ok());
        CHECK(hull->faces().size() == 6);
        CHECK(worst_distance(*hull, b.vertices()) == 0.0);
    }
}

TEST_CASE("repetition: the same clip 1000 times, 1000 moves there and back, 1000 splits merged back") {
    const Brush cube = box({-1, -1, -1}, {2, 3, 4});
    const Plane cut{glm::normalize(DVec3(1, 1, 0.3)), 0.7};
    auto once = clip(cube, cut);
    REQUIRE(once.ok());
    Brush b = *once;
    for (int i = 0; i < 1000; ++i) {
        auto again = clip(b, cut);
        REQUIRE(again.ok());
        b = std::move(*again);
    }
    CHECK(b.vertices() == once->vertices()); // bit for bit: the plane is already a face
    CHECK(b.faces().size() == once->faces().size());

    FaceAttributes mapped;
    mapped.material = "m";
    mapped.offset = {0.3, 0.1};
    mapped.scale = {0.5, 2};
    mapped.rotation_degrees = 30;
    auto start = make_box({-1, -1, -1}, {2, 3, 4}, mapped);
    REQUIRE(start.ok());
    Brush moving = *start;
    const glm::dmat3 quarter = glm::mat3_cast(glm::angleAxis(3.14159265358979323846 / 2, DVec3(0, 1, 0)));
    for (int i = 0; i < 1000; ++i) {
        auto there = transformed(moving, quarter, DVec3(0.1, 0.2, 0.3));
        REQUIRE(there.ok());
        auto back =
            transformed(*there, glm::transpose(quarter), -(glm::transpose(quarter) * DVec3(0.1, 0.2, 0.3)));
        REQUIRE(back.ok());
        moving = std::move(*back);
    }
    const double drift = worst_distance(moving, start->vertices());
    MESSAGE("1000 turns and moves there and back: vertex drift " << drift);
    CHECK(drift < 1e-12);
    for (std::size_t f = 0; f < start->faces().size(); ++f) {
        const int g = moving.find_face(start->faces()[f].plane);
        REQUIRE(g >= 0);
        const DVec3 p(0.5, 0.5, 0.5);
        CHECK(glm::length(texture_coordinates(moving.faces()[g], p) -
                          texture_coordinates(start->faces()[f], p)) < 1e-10);
    }

    Brush whole = cube;
    for (int i = 0; i < 1000; ++i) {
        auto halves = split(whole, {{1, 0, 0}, 0.37});
        REQUIRE(halves.ok());
        auto merged = merge(*halves->back, *halves->front);
        REQUIRE(merged.ok());
        whole = std::move(*merged);
    }
    CHECK(whole.faces().size() == 6);
    CHECK(worst_distance(whole, cube.vertices()) < 1e-12);
}
