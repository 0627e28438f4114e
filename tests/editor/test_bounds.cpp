// Oriented-box overlap (separating axes) on the hard cases: parallel and anti-parallel axes (degenerate
// edge-edge axes), exact touching, tiny overlaps far from the origin, 45° turns, NaN and zero sizes.
#include "model/bounds.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace ks;
using namespace ks::editor;

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

TEST_CASE("entity boxes follow the level conventions (bottom-centre positions, floors below the surface)") {
    level::Entity wall;
    wall.props = level::WallProps{};
    wall.position = {0, 0, -30};
    wall.rotation = {90, 0, 0};
    auto b = entity_obb(wall).aabb();
    CHECK(b.min.y == doctest::Approx(0));
    CHECK(b.max.y == doctest::Approx(16));
    CHECK(b.min.z == doctest::Approx(-35)); // 10 wide along local x, turned onto z
    CHECK(b.max.x == doctest::Approx(0.25));

    level::Entity floor;
    floor.props = level::FloorProps{};
    floor.position = {0, 6, 0};
    auto f = entity_obb(floor).aabb();
    CHECK(f.max.y == doctest::Approx(6));
    CHECK(f.min.y == doctest::Approx(5.5));
    CHECK(surface_height_at(floor, 9.9f, -9.9f) == doctest::Approx(6));
    CHECK_FALSE(surface_height_at(floor, 10.1f, 0).has_value());

    // Stairs rise toward local -z in `steps` treads: reference S1 rises from z -66 to z -78.
    level::Entity stair;
    stair.props = level::StairProps{};
    stair.position = {-4, 0, -72};
    stair.rotation = {0, 0, 0}; // as levels/main.json stores it
    CHECK(*surface_height_at(stair, -4, -66.5f) == doctest::Approx(0.6));
    CHECK(*surface_height_at(stair, -4, -77.5f) == doctest::Approx(6.0));
}
