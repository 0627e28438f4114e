// brush_query.h: the top of a brush over a point and a ray's entry, on a box, a ramp, a turned brush, far
// from the origin, and along the edges where a vertical line only grazes the brush.
#include "brush/brush_build.h"
#include "brush/brush_query.h"
#include "brush/texture_mapping.h"

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

using namespace ks;
using namespace ks::brush;

namespace {

Brush solid_box(DVec3 min, DVec3 max) {
    auto b = make_box(min, max);
    REQUIRE(b.ok());
    return *b;
}

// A ramp 8 long (along -z) rising 4, 6 wide: a wedge extruded along x.
Brush ramp(DVec3 offset = DVec3(0.0)) {
    const std::vector<DVec3> profile = {offset + DVec3(-3, 0, 4), offset + DVec3(-3, 0, -4),
                                        offset + DVec3(-3, 4, -4)};
    auto b = make_extrusion(profile, DVec3(6, 0, 0));
    REQUIRE_MESSAGE(b.ok(), (b.ok() ? "" : b.error().str()));
    return *b;
}

} // namespace

TEST_CASE("top_at: a box's top inside, nothing outside or on a vertical side") {
    const Brush b = solid_box({-2, 0, -2}, {2, 3, 2});
    CHECK(top_at(b, 0, 0).value_or(-1) == doctest::Approx(3).epsilon(1e-15));
    CHECK(top_at(b, 1.999, -1.999).value_or(-1) == doctest::Approx(3));
    CHECK_FALSE(top_at(b, 2.5, 0).has_value());
    CHECK_FALSE(top_at(b, 2.0, 0).has_value()); // exactly on a side: grazing is a miss
}

TEST_CASE("top_at: a ramp rises linearly; a turned ramp too; exact far from the origin") {
    const Brush r = ramp();
    for (double z : {4.0 - 1e-9, 2.0, 0.0, -2.0, -4.0 + 1e-9}) {
        CAPTURE(z);
        CHECK(top_at(r, 0, z).value_or(-1) == doctest::Approx((4.0 - z) / 2.0).epsilon(1e-12));
    }
    // Turned a quarter about y: the rise now runs along x.
    const glm::dmat3 quarter(glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0), glm::dvec3(1, 0, 0));
    auto turned = transformed(r, quarter, DVec3(0.0));
    REQUIRE(turned.ok());
    const double at = *top_at(*turned, 2.0, 0.0);
    const double other = *top_at(*turned, -2.0, 0.0);
    CHECK(std::fabs(at - other) == doctest::Approx(2.0).epsilon(1e-12));
    // Ten thousand units out, the same heights to 1e-9.
    const Brush far = ramp(DVec3(10000, 0, -10000));
    CHECK(*top_at(far, 10000, -10000) == doctest::Approx(2.0).epsilon(1e-12));
    CHECK(std::fabs(*top_at(far, 10000, -10000 + 2) - 1.0) < 1e-9);
}

TEST_CASE("ray_entry: from outside, inside, missing, and parallel to a face") {
    const Brush b = solid_box({-1, -1, -1}, {1, 1, 1});
    CHECK(ray_entry(b, {-5, 0, 0}, {1, 0, 0}).value_or(-1) == doctest::Approx(4));
    CHECK(ray_entry(b, {-5, 0, 0}, {2, 0, 0}).value_or(-1) == doctest::Approx(2)); // in direction's units
    CHECK(ray_entry(b, {0, 0, 0}, {0, 0, 1}).value_or(-1) == 0.0);
    CHECK_FALSE(ray_entry(b, {-5, 3, 0}, {1, 0, 0}).has_value());
    CHECK_FALSE(ray_entry(b, {5, 0, 0}, {1, 0, 0}).has_value());  // behind
    CHECK_FALSE(ray_entry(b, {-5, 1, 0}, {1, 0, 0}).has_value()); // along the top face's plane
    CHECK_FALSE(ray_entry(b, {0, 0, 0}, {0, 0, 0}).has_value());
    const Brush r = ramp();
    // Straight down onto the slope at z = 0: the top is 2 high.
    CHECK(*ray_entry(r, {0, 10, 0}, {0, -1, 0}) == doctest::Approx(8).epsilon(1e-12));
}

TEST_CASE("ray_entry_face: the face a ray enters through; none from inside or when it misses") {
    const Brush b = solid_box({-1, -1, -1}, {1, 1, 1});
    auto from_left = ray_entry_face(b, {-5, 0.2, 0.3}, {1, 0, 0});
    REQUIRE(from_left.has_value());
    CHECK(from_left->distance == doctest::Approx(4));
    CHECK(b.faces()[static_cast<size_t>(from_left->face)].plane.normal.x == doctest::Approx(-1.0));
    auto from_above = ray_entry_face(b, {0.5, 9, 0}, glm::normalize(DVec3(0.01, -1, 0)));
    REQUIRE(from_above.has_value());
    CHECK(b.faces()[static_cast<size_t>(from_above->face)].plane.normal.y == doctest::Approx(1.0));
    CHECK_FALSE(ray_entry_face(b, {0, 0, 0}, {0, 0, 1}).has_value());
    CHECK_FALSE(ray_entry_face(b, {-5, 3, 0}, {1, 0, 0}).has_value());
    const Brush r = ramp();
    auto slope = ray_entry_face(r, {0, 10, 0}, {0, -1, 0});
    REQUIRE(slope.has_value());
    CHECK(r.faces()[static_cast<size_t>(slope->face)].plane.normal.y > 0.1);
    CHECK(r.faces()[static_cast<size_t>(slope->face)].plane.normal.y < 0.99);
}
