// The plane convex hull: against a brute-force check that every point lies inside and every hull vertex is
// a corner, on random clouds, collinear and repeated points, slivers, huge coordinates and non-finite input.
#include "geometry/convex_hull_2d.h"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>

using namespace ks;
using namespace ks::geometry;

namespace {
double cross(const Vec2& o, const Vec2& a, const Vec2& b) {
    return (double(a.x) - o.x) * (double(b.y) - o.y) - (double(a.y) - o.y) * (double(b.x) - o.x);
}
// Every input point on or left of every hull edge, every turn strictly left (counter-clockwise, no collinear
// vertex), and every hull vertex one of the inputs.
void check_hull(const std::vector<Vec2>& input, const std::vector<Vec2>& hull) {
    REQUIRE(hull.size() >= 3);
    for (size_t i = 0; i < hull.size(); ++i) {
        const Vec2 &a = hull[i], &b = hull[(i + 1) % hull.size()], &c = hull[(i + 2) % hull.size()];
        CHECK(cross(a, b, c) > 0.0);
        for (const Vec2& p : input)
            if (std::isfinite(p.x) && std::isfinite(p.y)) CHECK(cross(a, b, p) >= 0.0);
        CHECK(std::find(input.begin(), input.end(), a) != input.end());
    }
}
} // namespace

TEST_CASE("convex hull 2d: a square with points inside and on its edges keeps the four corners") {
    std::vector<Vec2> pts = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 2}, {1, 3}, {2, 0}, {4, 2}, {0, 0}, {2, 4}};
    const std::vector<Vec2> input = pts;
    convex_hull_2d(pts);
    CHECK(pts == std::vector<Vec2>{{0, 0}, {4, 0}, {4, 4}, {0, 4}});
    check_hull(input, pts);
    CHECK(polygon_area2(pts) == doctest::Approx(32.0));
}

TEST_CASE("convex hull 2d: degenerate input gives no area") {
    std::vector<Vec2> none;
    convex_hull_2d(none);
    CHECK(none.empty());
    std::vector<Vec2> one = {{3, 3}, {3, 3}, {3, 3}};
    convex_hull_2d(one);
    CHECK(one == std::vector<Vec2>{{3, 3}});
    std::vector<Vec2> line = {{0, 0}, {2, 2}, {1, 1}, {5, 5}, {3, 3}};
    convex_hull_2d(line);
    CHECK(line == std::vector<Vec2>{{0, 0}, {5, 5}});
    CHECK(polygon_area2(line) == 0.0);
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    std::vector<Vec2> bad = {{nan, 0}, {0, inf}, {1, 0}, {0, 1}, {0, 0}, {-inf, nan}};
    convex_hull_2d(bad);
    CHECK(bad == std::vector<Vec2>{{0, 0}, {1, 0}, {0, 1}});
}

TEST_CASE("convex hull 2d: random clouds, slivers and huge coordinates against the brute-force check") {
    std::mt19937 rng(7);
    for (int round = 0; round < 200; ++round) {
        CAPTURE(round);
        const float scale = round % 4 == 0 ? 1e7f : (round % 4 == 1 ? 1e-3f : 640.0f);
        const float sliver = round % 5 == 0 ? 1e-4f : 1.0f; // nearly collinear clouds
        std::uniform_real_distribution<float> u(-1.0f, 1.0f);
        std::vector<Vec2> pts;
        const int n = 3 + round % 60;
        for (int i = 0; i < n; ++i) pts.push_back(Vec2(u(rng) * scale, u(rng) * scale * sliver) + 3e6f);
        const std::vector<Vec2> input = pts;
        convex_hull_2d(pts);
        if (pts.size() < 3) continue; // rounding made the cloud collinear
        check_hull(input, pts);
        CHECK(polygon_area2(pts) > 0.0);
    }
    // The same cloud repeated many times: the hull does not change.
    std::vector<Vec2> base = {{0, 0}, {10, 1}, {9, 9}, {1, 8}, {5, 5}};
    std::vector<Vec2> repeated;
    for (int i = 0; i < 1000; ++i) repeated.insert(repeated.end(), base.begin(), base.end());
    convex_hull_2d(base);
    convex_hull_2d(repeated);
    CHECK(repeated == base);
}

TEST_CASE("convex hull 2d: clipping a convex polygon to a rectangle") {
    // A diamond over the unit square's corner: the cut keeps the part inside, on the square's sides.
    std::vector<Vec2> diamond = {{0, -2}, {2, 0}, {0, 2}, {-2, 0}};
    clip_convex_polygon(diamond, Vec2(0, 0), Vec2(1, 1));
    CHECK(polygon_area2(diamond) == doctest::Approx(2.0)); // the whole unit square
    for (const Vec2& p : diamond) {
        CHECK(p.x >= 0.0f);
        CHECK(p.x <= 1.0f);
        CHECK(p.y >= 0.0f);
        CHECK(p.y <= 1.0f);
    }
    std::vector<Vec2> triangle = {{0, 0}, {4, 0}, {0, 4}};
    clip_convex_polygon(triangle, Vec2(1, 1), Vec2(10, 10)); // the corner (1,1)-(3,1)-(1,3) remains
    CHECK(polygon_area2(triangle) == doctest::Approx(4.0));
    std::vector<Vec2> outside = {{5, 5}, {6, 5}, {6, 6}};
    clip_convex_polygon(outside, Vec2(0, 0), Vec2(1, 1));
    CHECK(outside.empty());
    std::vector<Vec2> inside = {{0.2f, 0.2f}, {0.8f, 0.2f}, {0.5f, 0.9f}};
    const std::vector<Vec2> before = inside;
    clip_convex_polygon(inside, Vec2(0, 0), Vec2(1, 1));
    CHECK(inside == before);
}
