// geometry::closest_on_triangle (Ericson 5.1.5), shared by physics (double) and the levels of detail (float):
// every Voronoi region, the weights rebuilding the point, slivers, degenerate triangles, far coordinates and
// many random points against a brute-force search over the triangle.
#include "geometry/closest_on_triangle.h"

#include <doctest/doctest.h>
#include <glm/glm.hpp>

#include <cmath>
#include <random>

using namespace ks;
using glm::dvec3;
using glm::vec3;

namespace {
template <class V>
V rebuilt(const geometry::TriangleClosest<V>& c, const V& a, const V& b, const V& cc) {
    return a + (b - a) * c.along_ab + (cc - a) * c.along_ac;
}

// The nearest of a dense grid of points over the triangle (barycentric steps of 1/n).
double brute_force_distance(const dvec3& p, const dvec3& a, const dvec3& b, const dvec3& c, int n) {
    double best = 1e300;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j) {
            const dvec3 q = a + (b - a) * (double(i) / n) + (c - a) * (double(j) / n);
            best = std::min(best, glm::length(q - p));
        }
    return best;
}
} // namespace

TEST_CASE("closest_on_triangle: each region, and weights that rebuild the point") {
    const vec3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
    struct Case {
        vec3 p, expected;
    } cases[] = {
        {{-1, -1, 3}, {0, 0, 0}},            // vertex a
        {{3, -1, 0}, {2, 0, 0}},             // vertex b
        {{-1, 3, 0}, {0, 2, 0}},             // vertex c
        {{1, -1, 0}, {1, 0, 0}},             // edge ab
        {{-1, 1, 5}, {0, 1, 0}},             // edge ac
        {{2, 2, 0}, {1, 1, 0}},              // edge bc
        {{0.5f, 0.5f, -4}, {0.5f, 0.5f, 0}}, // inside, below
    };
    for (const Case& k : cases) {
        CAPTURE(k.p.x);
        CAPTURE(k.p.y);
        const auto hit = geometry::closest_on_triangle(k.p, a, b, c);
        CHECK(glm::length(hit.point - k.expected) < 1e-6f);
        CHECK(glm::length(rebuilt(hit, a, b, c) - hit.point) < 1e-6f);
        CHECK(hit.along_ab >= 0.0f);
        CHECK(hit.along_ac >= 0.0f);
        CHECK(hit.along_ab + hit.along_ac <= 1.0f + 1e-6f);
    }
}

TEST_CASE(
    "closest_on_triangle hard cases: slivers, degenerate triangles, far coordinates, 10^4 random points") {
    SUBCASE("a sliver 1e-6 wide and a triangle collapsed to a segment and to a point") {
        const dvec3 a(0, 0, 0), b(1, 0, 0), c(0.5, 1e-6, 0);
        const auto hit = geometry::closest_on_triangle(dvec3(0.3, 5, 0), a, b, c);
        CHECK(std::isfinite(hit.point.x));
        CHECK(std::abs(hit.point.x - 0.3) < 1e-4); // on edge ac, tilted 2e-6: x = 0.30001
        CHECK(std::abs(glm::length(hit.point - dvec3(0.3, 5, 0)) - 5.0) < 1e-5);
        const auto seg = geometry::closest_on_triangle(dvec3(0.25, 1, 0), a, b, dvec3(0.5, 0, 0));
        CHECK(glm::length(seg.point - dvec3(0.25, 0, 0)) < 1e-12);
        const auto dot = geometry::closest_on_triangle(dvec3(1, 1, 1), a, a, a);
        CHECK(glm::length(dot.point - a) == 0.0);
    }
    SUBCASE("10^6 units from the origin, in float") {
        const vec3 o(1e6f, -1e6f, 1e6f);
        const vec3 a = o, b = o + vec3(4, 0, 0), c = o + vec3(0, 4, 0);
        const auto hit = geometry::closest_on_triangle(o + vec3(1, 1, 3), a, b, c);
        CHECK(glm::length(hit.point - (o + vec3(1, 1, 0))) < 0.25f); // float spacing there is 0.0625
    }
    SUBCASE("random triangles and points against a dense search") {
        std::mt19937 rng(20);
        std::uniform_real_distribution<double> u(-10.0, 10.0);
        int worse = 0;
        for (int i = 0; i < 10000; ++i) {
            const dvec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng)), c(u(rng), u(rng), u(rng));
            const dvec3 p(u(rng), u(rng), u(rng));
            const auto hit = geometry::closest_on_triangle(p, a, b, c);
            const double d = glm::length(hit.point - p);
            // Never farther than any point of the triangle (the grid's points are on it).
            if (i % 50 == 0) worse += d > brute_force_distance(p, a, b, c, 60) + 1e-9;
            worse += glm::length(rebuilt(hit, a, b, c) - hit.point) > 1e-9 * (1.0 + glm::length(hit.point));
        }
        CHECK(worse == 0);
    }
}
