// Ray casts: exact single-shape tests against the double reference, and the hard cases — shared edges and
// vertices (exactly one hit, never zero), rays parallel to and lying in faces, starting inside or on the
// surface, grazing at 1e-6 rad, geometry 10 km away.
#include "physics/physics_scene.h"
#include "physics/ray.h"

#include "bench/physics/ray_reference.h"
#include "core/random.h"

#include <cmath>
#include <doctest/doctest.h>

using namespace ks;
using namespace ks::physics;

using physics_test::yaw;

namespace {
geometry::Ray ray(Vec3 o, Vec3 d, float max = 1e6f) {
    return {o, glm::normalize(d), max};
}
double ref_box(const geometry::Ray& r, Vec3 half, const geometry::Transform& xf) {
    return reference::ray_box(DVec3(r.origin), DVec3(r.direction),
                              {DVec3(xf.position), glm::dquat(xf.rotation), DVec3(half)}, r.max_distance);
}
} // namespace

TEST_CASE("ray vs box: entry distance and normal; inside and on the surface") {
    const Vec3 half(1, 2, 3);
    const geometry::Transform xf{{10, 0, 0}, Quat(1, 0, 0, 0)};
    ShapeHit h;
    REQUIRE(ray_box(ray({0, 0, 0}, {1, 0, 0}), half, xf, h));
    CHECK(h.distance == doctest::Approx(9.0f));
    CHECK(h.normal == Vec3(-1, 0, 0));
    CHECK_FALSE(ray_box(ray({0, 0, 0}, {1, 0, 0}, 8.9f), half, xf, h)); // max distance
    CHECK_FALSE(ray_box(ray({0, 0, 0}, {-1, 0, 0}), half, xf, h));      // pointing away
    REQUIRE(ray_box(ray({10, 0, 0}, {0, 1, 0}), half, xf, h));          // starts inside
    CHECK(h.distance == 0.0f);
    REQUIRE(ray_box(ray({9, 0, 0}, {1, 0, 0}), half, xf, h)); // on the surface, heading in
    CHECK(h.distance == 0.0f);
    CHECK_FALSE(ray_box(ray({9, 0, 0}, {-1, 0, 0}), half, xf, h)); // on the surface, leaving
}

TEST_CASE(
    "ray vs box and wedge agree with the double reference on random rays (several step sizes of angle)") {
    Rng rng(11);
    const Polyhedron wedge = make_wedge_polyhedron({6, 3, 6});
    int hits = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 half(rng.uniform(0.1f, 3), rng.uniform(0.1f, 3), rng.uniform(0.1f, 3));
        const geometry::Transform xf{{rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2)},
                                     glm::normalize(Quat(rng.uniform(-1, 1), rng.uniform(-1, 1),
                                                         rng.uniform(-1, 1), rng.uniform(-1, 1)))};
        Vec3 d(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
        if (glm::length(d) < 1e-3f) continue;
        const geometry::Ray r = ray({rng.uniform(-8, 8), rng.uniform(-8, 8), rng.uniform(-8, 8)}, d, 20.0f);
        ShapeHit h;
        const bool fast = ray_box(r, half, xf, h);
        const double ref = ref_box(r, half, xf);
        CHECK(fast == (ref >= 0.0));
        if (fast && ref >= 0.0) {
            CHECK(std::abs(h.distance - ref) < 1e-4);
            ++hits;
        }
        const bool fw = ray_polyhedron(r, wedge, xf, h);
        const double rw =
            reference::ray_polyhedron(DVec3(r.origin), DVec3(r.direction), wedge, DVec3(xf.position),
                                      glm::dquat(xf.rotation), r.max_distance);
        CHECK(fw == (rw >= 0.0));
        if (fw && rw >= 0.0) CHECK(std::abs(h.distance - rw) < 1e-4);
    }
    CHECK(hits > 500);
}

TEST_CASE("rays through shared edges and vertices of adjacent faces: exactly one hit, never zero") {
    // A hull made of triangles (a cube from 12 triangles' worth of vertices) hit exactly on a face diagonal,
    // an edge and a vertex, from many directions.
    const Polyhedron cube = make_box_polyhedron({1, 1, 1});
    const geometry::Transform xf{{0, 0, 0}, Quat(1, 0, 0, 0)};
    int missed = 0;
    for (int i = 0; i < 64; ++i) {
        const float a = 0.01f + 1.5f * i / 64.0f;
        const Vec3 targets[] = {{1, 1, 1}, {1, 1, 0}, {1, 0.3f, 0.3f}, {1, -1, -1}, {0, 1, 1}};
        for (const Vec3& t : targets) {
            const Vec3 o = t + Vec3(std::cos(a), std::sin(a) * 0.5f, std::sin(a)) * 5.0f;
            ShapeHit h;
            if (!ray_polyhedron(ray(o, t - o), cube, xf, h)) ++missed;
            if (!ray_box(ray(o, t - o), {1, 1, 1}, xf, h)) ++missed;
        }
    }
    CHECK(missed == 0);
    // Two boxes sharing a face: rays along the seam from above hit (closest-hit picks one), for every step.
    for (float x = -1.0f; x < 1.0f; x += 0.125f) { // z = +1 is the outer max edge: tangent, half-open
        ShapeHit ha, hb;
        const geometry::Ray down = ray({0.0f, 5.0f, x}, {0, -1, 0});
        const bool a = ray_box(down, {1, 1, 1}, {{-1, 0, 0}, Quat(1, 0, 0, 0)}, ha);
        const bool b = ray_box(down, {1, 1, 1}, {{1, 0, 0}, Quat(1, 0, 0, 0)}, hb);
        CHECK((a || b));
    }
    // Rotated pair sharing a face (yaw 30°): a sweep of rays across the seam never slips through.
    const Quat q = yaw(0.5236f);
    const geometry::Transform left{q * Vec3(-1, 0, 0), q}, right{q * Vec3(1, 0, 0), q};
    int slipped = 0;
    for (int i = -500; i <= 500; ++i) {
        const Vec3 seam = q * Vec3(0, 0, i * 0.001f);
        const geometry::Ray down = ray(seam + Vec3(1e-7f * i, 5, 0), {0, -1, 0});
        ShapeHit h;
        if (!ray_box(down, {1, 1, 1}, left, h) && !ray_box(down, {1, 1, 1}, right, h)) ++slipped;
    }
    CHECK(slipped == 0);
}

TEST_CASE("rays parallel to a face and lying in its plane: half-open, so stacked boxes share a face") {
    const Vec3 half(1, 1, 1);
    const geometry::Transform lower{{0, 0, 0}, Quat(1, 0, 0, 0)}, upper{{0, 2, 0}, Quat(1, 0, 0, 0)};
    ShapeHit h;
    const geometry::Ray in_plane = ray({-5, 1, 0}, {1, 0, 0}); // along y = 1, the shared face
    const int count = ray_box(in_plane, half, lower, h) + ray_box(in_plane, half, upper, h);
    CHECK(count == 1);
    CHECK(ref_box(in_plane, half, lower) < 0.0);
    CHECK(ref_box(in_plane, half, upper) == doctest::Approx(4.0));
    CHECK_FALSE(ray_box(ray({-5, 1.0001f, 0}, {1, 0, 0}), half, lower, h)); // parallel just above: miss
    REQUIRE(ray_box(ray({-5, 0.9999f, 0}, {1, 0, 0}), half, lower, h));     // just below: hit
    CHECK(h.distance == doctest::Approx(4.0f));
    CHECK(std::isfinite(h.distance));
}

TEST_CASE("grazing rays at 1e-6 rad and geometry 10 km from the origin keep millimetre accuracy") {
    const Vec3 half(5000, 0.5f, 50);
    for (float angle : {1e-6f, 1e-5f, 1e-4f, 1e-3f}) {
        // From 1 mm above the floor's top, descending at `angle`: hits at 1e-3/tan(angle) (up to 1 km).
        // The distance is ill-conditioned (one rounding of the 0.5-unit coordinates, 3e-8, moves it by
        // 3e-8/angle), so the bound is millimetre plus that conditioning.
        const geometry::Transform xf{{0, -0.5f, 0}, Quat(1, 0, 0, 0)};
        const geometry::Ray r = ray({-4000, 1e-3f, 0}, {std::cos(angle), -std::sin(angle), 0}, 1e7f);
        ShapeHit h;
        const bool hit = ray_box(r, half, xf, h);
        const double ref = ref_box(r, half, xf);
        REQUIRE(hit);
        REQUIRE(ref >= 0.0);
        CAPTURE(angle);
        CHECK(std::abs(h.distance - ref) < 1e-3 + 2.4e-7 / angle);
        CHECK(h.normal.y == 1.0f);
    }
    Rng rng(3);
    for (int i = 0; i < 2000; ++i) {
        const Vec3 far(10000.0f, 20.0f, -10000.0f);
        const geometry::Transform xf{far + Vec3(rng.uniform(-5, 5), 0, rng.uniform(-5, 5)),
                                     yaw(rng.uniform(0, 3))};
        const geometry::Ray r =
            ray(far + Vec3(rng.uniform(-20, 20), rng.uniform(-20, 20), rng.uniform(-20, 20)),
                Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)) + Vec3(1e-3f), 100.0f);
        ShapeHit h;
        const bool hit = ray_box(r, {1, 2, 3}, xf, h);
        const double ref = ref_box(r, {1, 2, 3}, xf);
        CHECK(hit == (ref >= 0.0));
        if (hit && ref >= 0.0) CHECK(std::abs(h.distance - ref) < 1e-3); // millimetre
    }
}

TEST_CASE("ray vs capsule and cylinder: analytic, inside at 0, caps and sides") {
    ShapeHit h;
    REQUIRE(ray_capsule(ray({-5, 1.5f, 0}, {1, 0, 0}), {0, 1, 0}, {0, 2, 0}, 1.0f, h));
    CHECK(h.distance == doctest::Approx(4.0f));
    REQUIRE(ray_capsule(ray({0, 10, 0}, {0, -1, 0}), {0, 1, 0}, {0, 2, 0}, 1.0f, h)); // top sphere
    CHECK(h.distance == doctest::Approx(7.0f));
    CHECK(h.normal.y == doctest::Approx(1.0f));
    REQUIRE(ray_capsule(ray({0, 1.5f, 0}, {1, 0, 0}), {0, 1, 0}, {0, 2, 0}, 1.0f, h));
    CHECK(h.distance == 0.0f);
    CHECK_FALSE(ray_capsule(ray({-5, 1.5f, 1.01f}, {1, 0, 0}), {0, 1, 0}, {0, 2, 0}, 1.0f, h));
    REQUIRE(ray_cylinder(ray({0, 10, 0.2f}, {0, -1, 0}), {0, 1, 0}, 0.5f, 1.0f, h)); // top cap
    CHECK(h.distance == doctest::Approx(8.0f));
    CHECK(h.normal.y == 1.0f);
    REQUIRE(ray_cylinder(ray({-5, 1, 0}, {1, 0, 0}), {0, 1, 0}, 0.5f, 1.0f, h));
    CHECK(h.distance == doctest::Approx(4.5f));
    CHECK_FALSE(ray_cylinder(ray({-5, 2.01f, 0}, {1, 0, 0}), {0, 1, 0}, 0.5f, 1.0f, h));
}
