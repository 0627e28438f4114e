// Narrowphase: full SAT (faces + edge×edge) against face-only SAT, touching/contained/coincident boxes,
// nearly parallel edges, far from the origin; capsule closest features against every shape.
#include "physics/collide.h"
#include "physics/physics_scene.h"

#include "core/random.h"

#include <cmath>
#include <doctest/doctest.h>

using namespace ks;
using namespace ks::physics;

using physics_test::yaw;

namespace {
geometry::Transform at(Vec3 p, Quat q = Quat(1, 0, 0, 0)) {
    return {p, q};
}
bool finite(const Contact& c) {
    return is_finite(c.normal) && std::isfinite(c.penetration) && is_finite(c.point);
}
} // namespace

TEST_CASE("SAT: separated, touching (zero penetration) and overlapping boxes") {
    const Polyhedron unit = make_box_polyhedron({1, 1, 1});
    CHECK_FALSE(collide_convex(unit, at({0, 0, 0}), unit, at({2.001f, 0, 0})));
    auto touch = collide_convex(unit, at({0, 0, 0}), unit, at({2, 0, 0}));
    REQUIRE(touch);
    CHECK(touch->penetration == doctest::Approx(0.0f).epsilon(1e-6));
    auto c = collide_convex(unit, at({0, 0, 0}), unit, at({1.5f, 0.2f, 0}));
    REQUIRE(c);
    CHECK(c->penetration == doctest::Approx(0.5f));
    CHECK(c->normal.x == doctest::Approx(-1.0f)); // pushes A (at the origin) away from B (at +x)
    CHECK(c->point.x == doctest::Approx(0.75f));
}

TEST_CASE("SAT: crossed edges — face-only SAT reports a false contact, full SAT does not") {
    // Two long boxes crossed like an X in plan view, rotated 45° about their long axis so edges face each
    // other: their AABBs and all face projections overlap, but an edge×edge axis separates them.
    const Polyhedron bar = make_box_polyhedron({3, 0.5f, 0.5f});
    const Quat roll = glm::angleAxis(kPi / 4, Vec3(1, 0, 0));
    const geometry::Transform a = at({0, 0, 0}, roll);
    const geometry::Transform b = at({0, 1.5f, 0}, yaw(kPi / 2) * roll);
    CHECK(collide_convex(bar, a, bar, b, SatAxes::FacesOnly)); // false contact
    CHECK_FALSE(collide_convex(bar, a, bar, b, SatAxes::FacesAndEdges));
    // Closer: a true edge-edge contact, with the exact penetration 2·0.5·√2 − 1.3.
    const geometry::Transform b2 = at({0, 1.2f, 0}, yaw(kPi / 2) * roll);
    auto c = collide_convex(bar, a, bar, b2);
    REQUIRE(c);
    CHECK(c->penetration == doctest::Approx(std::sqrt(2.0f) - 1.2f).epsilon(1e-4));
    CHECK(c->normal.y == doctest::Approx(-1.0f).epsilon(1e-4));
}

TEST_CASE(
    "SAT: contained, coincident, nearly parallel edges and 10 km from the origin stay finite and exact") {
    const Polyhedron big = make_box_polyhedron({2, 2, 2}), small = make_box_polyhedron({0.5f, 0.5f, 0.5f});
    auto contained = collide_convex(big, at({0, 0, 0}), small, at({0.3f, 0, 0}));
    REQUIRE(contained);
    CHECK(contained->penetration == doctest::Approx(2.5f - 0.3f + 0.0f).epsilon(1e-5)); // push out along -x
    auto coincident = collide_convex(small, at({1, 1, 1}), small, at({1, 1, 1}));
    REQUIRE(coincident);
    CHECK(coincident->penetration == doctest::Approx(1.0f));
    CHECK(finite(*coincident));
    for (float angle : {1e-7f, 1e-6f, 1e-5f, 1e-3f}) {
        CAPTURE(angle);
        auto c = collide_convex(big, at({0, 0, 0}), big, at({0, 3.9f, 0}, yaw(angle)));
        REQUIRE(c);
        CHECK(finite(*c));
        CHECK(c->penetration == doctest::Approx(0.1f).epsilon(1e-3));
        CHECK(c->normal.y == doctest::Approx(-1.0f).epsilon(1e-4));
    }
    const Vec3 far(10000.0f, 5.0f, -10000.0f);
    auto f = collide_convex(small, at(far), small, at(far + Vec3(0.999f, 0, 0)));
    REQUIRE(f);
    CHECK(std::abs(f->penetration - 0.001f) < 1e-3f); // float spacing at 10 km is ~1 mm
}

TEST_CASE("capsule against a yaw-only box: the fast path agrees with the general polyhedron path") {
    Rng rng(7);
    const Vec3 half(2.0f, 1.0f, 0.5f);
    const Polyhedron poly = make_box_polyhedron(half);
    for (int i = 0; i < 2000; ++i) {
        const geometry::Transform xf =
            at({rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)}, yaw(rng.uniform(0, 6.28f)));
        const Vec3 c(rng.uniform(-4, 4), rng.uniform(-4, 4), rng.uniform(-4, 4));
        const Segment s{c - Vec3(0, 0.5f, 0), c + Vec3(0, 0.5f, 0)};
        auto fast = collide_capsule_box(s, 1.0f, half, xf);
        auto slow = collide_capsule_polyhedron(s, 1.0f, poly, xf);
        REQUIRE(fast.has_value() == slow.has_value());
        if (!fast) continue;
        CHECK(fast->penetration == doctest::Approx(slow->penetration).epsilon(1e-4));
        CHECK(glm::dot(fast->normal, slow->normal) > 0.999f);
        CHECK(finite(*fast));
    }
}

TEST_CASE("capsule closest features: floor, box edge, wedge slope, cylinder, capsule") {
    const Segment s{{0, 1.0f, 0}, {0, 2.0f, 0}}; // feet at y = 0 for radius 1
    auto floor = collide_capsule_box(s, 1.0f, {10, 0.5f, 10}, at({0, -0.5f, 0}));
    REQUIRE(floor);
    CHECK(floor->penetration == doctest::Approx(0.0f));
    CHECK(floor->normal.y == doctest::Approx(1.0f));
    // The box edge at 45 degrees below-left: distance sqrt(2)·0.5 from the segment's bottom.
    auto edge = collide_capsule_box(s, 1.0f, {1, 1, 1}, at({-1.5f, -0.5f, 0}));
    REQUIRE(edge);
    CHECK(edge->penetration == doctest::Approx(1.0f - std::sqrt(0.5f)).epsilon(1e-5));
    CHECK(edge->normal.x == doctest::Approx(std::sqrt(0.5f)).epsilon(1e-5));
    // On the 26.6° ramp: the contact normal is the slope normal.
    const Polyhedron wedge = make_wedge_polyhedron({6, 3, 6});
    auto ramp = collide_capsule_polyhedron({{0, 4.0f, 0}, {0, 5.0f, 0}}, 1.0f, wedge, at({0, 3, 0}));
    REQUIRE(ramp);
    CHECK(ramp->normal.y == doctest::Approx(2.0f / std::sqrt(5.0f)).epsilon(1e-4));
    // Upright cylinder (gas cylinder r 0.5, h 2) beside the capsule: horizontal push.
    auto cyl = collide_capsule_cylinder(s, 1.0f, {1.2f, 1.0f, 0}, 0.5f, 1.0f);
    REQUIRE(cyl);
    CHECK(cyl->penetration == doctest::Approx(0.3f).epsilon(1e-5));
    CHECK(cyl->normal.x == doctest::Approx(-1.0f));
    // Standing on the cylinder's top rim edge: distance from the bottom sphere centre to the rim.
    auto rim = collide_capsule_cylinder({{1.0f, 2.5f, 0}, {1.0f, 3.5f, 0}}, 1.0f, {0, 1.0f, 0}, 0.5f, 1.0f);
    REQUIRE(rim);
    CHECK(rim->penetration == doctest::Approx(1.0f - std::sqrt(0.5f)).epsilon(1e-5));
    CHECK(rim->normal.x == doctest::Approx(std::sqrt(0.5f)).epsilon(1e-5));
    auto cap = collide_capsule_capsule(s, 1.0f, {{1.5f, 1.0f, 0}, {1.5f, 2.0f, 0}}, 1.0f);
    REQUIRE(cap);
    CHECK(cap->penetration == doctest::Approx(0.5f));
    auto same = collide_capsule_capsule(s, 1.0f, s, 1.0f); // coincident: finite, any direction
    REQUIRE(same);
    CHECK(finite(*same));
}

TEST_CASE("capsule whose core is inside a box or wedge is pushed out along the least penetration") {
    const Segment s{{0, 0.0f, 0}, {0, 1.0f, 0}};
    auto box = collide_capsule_box(s, 1.0f, {5, 5, 5}, at({4.5f, 0, 0}));
    REQUIRE(box);
    CHECK(box->normal.x == doctest::Approx(-1.0f));
    CHECK(box->penetration == doctest::Approx(0.5f + 1.0f));
    auto general =
        collide_capsule_polyhedron(s, 1.0f, make_box_polyhedron({5, 5, 5}), at({4.5f, 0, 0}, yaw(0.3f)));
    REQUIRE(general);
    CHECK(finite(*general));
    CHECK(general->penetration > 1.0f);
}
