// Oriented-box overlap (separating axes) on the hard cases: parallel and anti-parallel axes (degenerate
// edge-edge axes), exact touching, tiny overlaps far from the origin, 45° turns, NaN and zero sizes; and
// the shared per-axis interval measure both SATs use.
#include "geometry/obb.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace ks;
using namespace ks::geometry;

namespace {
Obb box(Vec3 centre, Vec3 half, float yaw_degrees = 0, float pitch_degrees = 0) {
    Obb b;
    b.center = centre;
    b.half = half;
    b.axes = glm::mat3_cast(quat_from_ypr(radians(yaw_degrees), radians(pitch_degrees), 0));
    return b;
}
} // namespace

TEST_CASE("obb overlap: aligned boxes, touching is not overlapping, depth and axis are right") {
    auto a = box({0, 0, 0}, {1, 1, 1});
    CHECK(obb_overlap(a, box({2, 0, 0}, {1, 1, 1})).overlapping == false); // faces touch exactly
    auto ov = obb_overlap(a, box({1.5f, 0, 0}, {1, 1, 1}));
    CHECK(ov.overlapping);
    CHECK(ov.depth == doctest::Approx(0.5));
    CHECK(ov.axis.x == doctest::Approx(-1.0));                             // pushes a away from b
    CHECK(obb_overlap(a, box({0, 0, 0}, {0.1f, 0.1f, 0.1f})).overlapping); // containment
    CHECK_FALSE(obb_overlap(a, box({2.0005f, 0, 0}, {1, 1, 1})).overlapping);
}

TEST_CASE("obb overlap: parallel and anti-parallel rotations (degenerate cross axes) stay exact") {
    // Same yaw: all nine edge-edge cross products vanish; only face axes decide.
    for (float yaw : {0.0f, 90.0f, 180.0f, 37.0f}) {
        CAPTURE(yaw);
        auto a = box({0, 0, 0}, {5, 8, 0.25f}, yaw);
        const Vec3 along = a.axes[2] * 0.5f;
        CHECK_FALSE(
            obb_overlap(a, box(along * 1.0f + Vec3(0), {5, 8, 0.25f}, yaw)).overlapping); // 0.5 apart: touch
        CHECK(obb_overlap(a, box(along * 0.9f, {5, 8, 0.25f}, yaw + 180.0f)).overlapping);
    }
}

TEST_CASE("obb overlap: a 45° box near a corner, decided by an edge-edge or face axis") {
    // Unit cube and a cube turned 45° about y, centres 1 + sqrt(2) - tiny apart along x: overlap tiny.
    auto a = box({0, 0, 0}, {1, 1, 1});
    const float gap = 1.0f + std::sqrt(2.0f);
    CHECK(obb_overlap(a, box({gap - 0.01f, 0, 0}, {1, 1, 1}, 45)).overlapping);
    CHECK_FALSE(obb_overlap(a, box({gap + 0.01f, 0, 0}, {1, 1, 1}, 45)).overlapping);
    // Turned about two axes: diagonal along x only separates beyond the projected radius.
    auto b = box({0, 0, 0}, {1, 1, 1}, 45, 45);
    CHECK(obb_overlap(a, b).overlapping);
    CHECK_FALSE(obb_overlap(a, box({3.8f, 0, 0}, {1, 1, 1}, 45, 45)).overlapping);
}

TEST_CASE("obb overlap: far from the origin, a millimetre still decides (double precision inside)") {
    const Vec3 far(9000.0f, 0, -9000.0f);
    auto a = box(far, {5, 8, 0.25f}, 30);
    auto b = box(far + a.axes[0] * 5.1f, {0.5f, 0.5f, 0.5f}, 30);
    auto ov = obb_overlap(a, b, 1e-3f);
    // Float positions at 9000 carry ~0.001 of error; the overlap (0.4) is found with its depth.
    CHECK(ov.overlapping);
    CHECK(ov.depth == doctest::Approx(0.4).epsilon(0.01));
}

TEST_CASE("obb overlap: NaN, infinite and zero-size boxes do not crash and do not overlap") {
    auto a = box({0, 0, 0}, {1, 1, 1});
    CHECK_FALSE(obb_overlap(a, box({std::nanf(""), 0, 0}, {1, 1, 1})).overlapping);
    CHECK_FALSE(obb_overlap(a, box({0, 0, 0}, {INFINITY, 1, 1})).overlapping);
    CHECK(obb_overlap(a, box({0.5f, 0, 0}, {0, 0, 0})).overlapping); // a point inside still counts
    CHECK_FALSE(obb_overlap(a, box({1.5f, 0, 0}, {0, 0, 0})).overlapping);
}

TEST_CASE("obb overlap: at 1e4 from the origin, overlaps of a millimetre are told from touching and gaps") {
    // Float spacing at 1e4 is 2^-10 (about 1e-3), so the offsets are whole multiples of it and the expected
    // depths are computed from the stored floats.
    const float x = 10000.0f, ulp = std::ldexp(1.0f, -10);
    const Obb a = box({x, 0, -x}, {1, 1, 1});
    for (int k : {2, 3, 8}) { // overlaps of 2, 3 and 8 ulps: about 2e-3, 3e-3 and 8e-3
        CAPTURE(k);
        const float bx = x + 2.0f - static_cast<float>(k) * ulp;
        const Overlap ov = obb_overlap(a, box({bx, 0, -x}, {1, 1, 1}), 1e-3f);
        CHECK(ov.overlapping);
        CHECK(std::abs(ov.depth - static_cast<float>(k) * ulp) < 1e-6f);
        CHECK(ov.axis.x == doctest::Approx(-1.0));
        // The same gap on the other side: apart.
        CHECK_FALSE(
            obb_overlap(a, box({x + 2.0f + static_cast<float>(k) * ulp, 0, -x}, {1, 1, 1})).overlapping);
    }
    CHECK_FALSE(obb_overlap(a, box({x + 2.0f, 0, -x}, {1, 1, 1}), 0.0f).overlapping); // touching exactly
    // Turned 30° both: the face axis of the rotated pair still decides a 4e-3 overlap.
    const Obb r = box({x, 5, x}, {2, 1, 0.5f}, 30);
    const Obb s = box(r.center + r.axes[2] * (1.0f - 4e-3f), {2, 1, 0.5f}, 30);
    const Overlap ov = obb_overlap(r, s, 1e-3f);
    CHECK(ov.overlapping);
    CHECK(std::abs(ov.depth - 4e-3f) < 1.5e-3f); // the centres' float rounding at 1e4, projected
}

TEST_CASE("obb overlap: parallel edges that only touch along a line or a face do not overlap") {
    const Obb a = box({0, 0, 0}, {1, 1, 1});
    CHECK_FALSE(obb_overlap(a, box({2, 2, 0}, {1, 1, 1})).overlapping); // edge on edge
    CHECK_FALSE(obb_overlap(a, box({2, 2, 2}, {1, 1, 1})).overlapping); // corner on corner
    // A 45° box whose edge lies along the cube's top face: its lowest edge is parallel to the cube's x axis.
    const Obb diamond = box({0, 1.0f + std::sqrt(2.0f), 0}, {1, 1, 1}, 0, 45);
    CHECK_FALSE(obb_overlap(a, diamond).overlapping);
    CHECK(obb_overlap(a, box({0, 1.0f + std::sqrt(2.0f) - 0.01f, 0}, {1, 1, 1}, 0, 45)).overlapping);
}

TEST_CASE("interval overlap: the depth is the smaller push, its sign says which way A leaves") {
    const AxisOverlap<float> o = interval_overlap(0.0f, 2.0f, 1.5f, 5.0f); // B ahead of A
    CHECK(o.depth == 0.5f);
    CHECK_FALSE(o.push_a_positive);
    const AxisOverlap<double> back = interval_overlap(0.0, 2.0, -3.0, 0.25); // B behind A
    CHECK(back.depth == 0.25);
    CHECK(back.push_a_positive);
    CHECK(interval_overlap(0.0f, 1.0f, 1.0f, 2.0f).depth == 0.0f);  // touching
    CHECK(interval_overlap(0.0f, 1.0f, 3.0f, 4.0f).depth == -2.0f); // the gap, negative
}

TEST_CASE("ray against oriented boxes: entry distance, inside, rotated, miss") {
    Obb box;
    box.center = Vec3(0, 1, 0);
    box.half = Vec3(1, 1, 2);
    CHECK(ray_obb({Vec3(0, 10, 0), Vec3(0, -1, 0)}, box) == doctest::Approx(8.0f));
    CHECK(ray_obb({Vec3(0, 1, 0), Vec3(1, 0, 0)}, box) == doctest::Approx(0.0f)); // starts inside
    CHECK(ray_obb({Vec3(1.5f, 10, 0), Vec3(0, -1, 0)}, box) < 0.0f);
    CHECK(ray_obb({Vec3(0, 10, 0), Vec3(0, 1, 0)}, box) < 0.0f); // pointing away
    // Turned 90 degrees about y: the long side now lies along x.
    box.axes = Mat3(Vec3(0, 0, -1), Vec3(0, 1, 0), Vec3(1, 0, 0));
    CHECK(ray_obb({Vec3(1.5f, 10, 0), Vec3(0, -1, 0)}, box) == doctest::Approx(8.0f));
    CHECK(ray_obb({Vec3(0, 10, 1.5f), Vec3(0, -1, 0)}, box) < 0.0f);
}

TEST_CASE("ray against oriented boxes: max distance and non-finite rays miss") {
    Obb b;
    b.half = Vec3(1.0f);
    CHECK(ray_obb({Vec3(0, 10, 0), Vec3(0, -1, 0), 8.5f}, b) < 0.0f);
    CHECK(ray_obb({Vec3(0, 10, 0), Vec3(0, -1, 0), 9.0f}, b) == doctest::Approx(9.0f));
    CHECK(ray_obb({Vec3(NAN, 10, 0), Vec3(0, -1, 0)}, b) < 0.0f);
    CHECK(ray_obb({Vec3(0, 10, 0), Vec3(0, NAN, 0)}, b) < 0.0f);
    CHECK(ray_obb({Vec3(0, 0, 0), Vec3(INFINITY, 0, 0)}, b) < 0.0f);
}
