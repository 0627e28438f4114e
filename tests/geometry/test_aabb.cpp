// The shared axis-aligned box: empty boxes grow into exactly what is added, touching boxes overlap (closed
// intervals), and moving a box by a matrix bounds the moved corners exactly.
#include "geometry/aabb.h"

#include <doctest/doctest.h>

#include <glm/gtc/matrix_transform.hpp>

using namespace ks;
using namespace ks::geometry;

TEST_CASE("aabb: empty grows and merges into exactly what is added") {
    Aabb box = Aabb::empty();
    CHECK_FALSE(box.valid());
    box.grow(Vec3(1, 2, 3));
    CHECK(box.valid());
    CHECK(box.min == Vec3(1, 2, 3));
    CHECK(box.max == Vec3(1, 2, 3));
    box.grow(Aabb{Vec3(-1, 5, 0), Vec3(0, 6, 1)});
    CHECK(box.min == Vec3(-1, 2, 0));
    CHECK(box.max == Vec3(1, 6, 3));
    const Aabb merged = merge(Aabb::empty(), Aabb{Vec3(-2), Vec3(2)});
    CHECK(merged.min == Vec3(-2));
    CHECK(merged.max == Vec3(2));
    CHECK(is_finite(Aabb::empty().center())); // no inf - inf
}

TEST_CASE("aabb: overlap and containment are closed, expansion and measures") {
    const Aabb a{Vec3(0), Vec3(2, 4, 6)};
    CHECK(a.overlaps({Vec3(2, 0, 0), Vec3(3, 1, 1)}));               // faces touch
    CHECK(a.overlaps({Vec3(2, 4, 6), Vec3(3, 5, 7)}));               // corners touch
    CHECK_FALSE(a.overlaps({Vec3(2.0001f, 0, 0), Vec3(3, 1, 1)}));   // just apart on x
    CHECK_FALSE(a.overlaps({Vec3(0, -2, 0), Vec3(1, -0.0001f, 1)})); // just apart on y
    CHECK(a.overlaps({Vec3(-10), Vec3(10)}));                        // containing
    CHECK(a.contains(Vec3(2, 4, 6)));
    CHECK_FALSE(a.contains(Vec3(2, 4, 6.0001f)));
    CHECK_FALSE(a.contains(Vec3(NAN, 1, 1)));
    CHECK(a.center() == Vec3(1, 2, 3));
    CHECK(a.extent() == Vec3(1, 2, 3));
    CHECK(a.surface_area() == doctest::Approx(2 * (8 + 24 + 12)));
    const Aabb e = a.expanded(0.5f);
    CHECK(e.min == Vec3(-0.5f));
    CHECK(e.max == Vec3(2.5f, 4.5f, 6.5f));
}

TEST_CASE("aabb: transformed by a rotation and translation bounds the moved corners exactly") {
    const Aabb box{Vec3(-1, 0, -2), Vec3(1, 3, 2)};
    const Mat4 m = glm::rotate(glm::translate(Mat4(1.0f), Vec3(10, 0, 0)), radians(90.0f), Vec3(0, 1, 0));
    const Aabb t = transform_aabb(box, m);
    CHECK(t.min.x == doctest::Approx(8.0f));
    CHECK(t.max.x == doctest::Approx(12.0f));
    CHECK(t.min.z == doctest::Approx(-1.0f));
    CHECK(t.max.z == doctest::Approx(1.0f));
    CHECK(t.min.y == doctest::Approx(0.0f));
    CHECK(t.max.y == doctest::Approx(3.0f));
    // At 45° it is the bound of the turned corners, not of the box's own bounds.
    const Aabb d =
        transform_aabb({Vec3(-1), Vec3(1)}, glm::rotate(Mat4(1.0f), radians(45.0f), Vec3(0, 1, 0)));
    CHECK(d.max.x == doctest::Approx(std::sqrt(2.0f)));
    CHECK(d.max.y == doctest::Approx(1.0f));
}
