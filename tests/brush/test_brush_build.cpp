// Making brushes (box, extrusion, point cloud through Qhull) and deriving their geometry from planes.
#include "brush/brush_build.h"
#include "brush/convex_hull.h"
#include "brush_checks.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace ks;
using namespace ks::brush;
using ks::brush_test::audit;
using ks::brush_test::has_vertex;

TEST_CASE("a box derives 8 vertices, 12 edges and 6 quads from its 6 planes") {
    auto b = make_box({-1, -2, -3}, {1, 2, 3});
    REQUIRE(b.ok());
    CHECK(audit(*b).empty());
    CHECK(b->vertices().size() == 8);
    CHECK(b->edges().size() == 12);
    CHECK(b->faces().size() == 6);
    for (const auto& p : b->polygons()) CHECK(p.size() == 4);
    CHECK(b->volume() == doctest::Approx(48.0).epsilon(1e-14));
    CHECK(has_vertex(*b, {1, 2, 3}, 0.0));
    CHECK(has_vertex(*b, {-1, -2, -3}, 0.0));
    CHECK(b->bounds_min() == DVec3(-1, -2, -3));
    CHECK(b->bounds_max() == DVec3(1, 2, 3));
}

TEST_CASE("polygons run counter-clockwise seen from outside") {
    auto b = make_box({0, 0, 0}, {2, 3, 4});
    REQUIRE(b.ok());
    for (std::size_t f = 0; f < b->faces().size(); ++f) {
        const auto& poly = b->polygons()[f];
        const auto& v = b->vertices();
        const DVec3 n = glm::cross(v[poly[1]] - v[poly[0]], v[poly[2]] - v[poly[1]]);
        CHECK(glm::dot(n, b->faces()[f].plane.normal) > 0);
    }
}

TEST_CASE("a box refuses min not below max, naming the axis") {
    auto b = make_box({0, 0, 0}, {1, 0, 1});
    REQUIRE(!b.ok());
    CHECK(b.error().where.path == "min.y");
}

TEST_CASE("extrusion: a triangle swept up is a prism of 5 faces, either winding") {
    const DVec3 tri[] = {{0, 0, 0}, {4, 0, 0}, {0, 0, 3}};
    const DVec3 tri_reversed[] = {{0, 0, 3}, {4, 0, 0}, {0, 0, 0}};
    for (auto poly : {std::span<const DVec3>(tri), std::span<const DVec3>(tri_reversed)}) {
        auto b = make_extrusion(poly, {0, 2, 0});
        REQUIRE(b.ok());
        CHECK(audit(*b).empty());
        CHECK(b->faces().size() == 5);
        CHECK(b->vertices().size() == 6);
        CHECK(b->volume() == doctest::Approx(12.0).epsilon(1e-14));
        CHECK(has_vertex(*b, {4, 2, 0}, 0.0));
    }
}

TEST_CASE("extrusion along a slanted direction makes a sheared prism of the same volume") {
    const DVec3 square[] = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}};
    auto b = make_extrusion(square, {3, 1, 0});
    REQUIRE(b.ok());
    CHECK(audit(*b).empty());
    CHECK(b->volume() == doctest::Approx(1.0).epsilon(1e-13));
    CHECK(has_vertex(*b, {4, 1, 1}, 1e-12));
}

TEST_CASE("extrusion refuses a non-convex polygon, a collinear corner and a direction in the plane") {
    const DVec3 dart[] = {{0, 0, 0}, {4, 0, 0}, {1, 0, 1}, {0, 0, 4}};
    auto a = make_extrusion(dart, {0, 1, 0});
    REQUIRE(!a.ok());
    CHECK(a.error().where.path == "polygon[2]");
    const DVec3 straight[] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 0, 2}};
    auto b = make_extrusion(straight, {0, 1, 0});
    REQUIRE(!b.ok());
    CHECK(b.error().where.path == "polygon[1]");
    const DVec3 tri[] = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}};
    auto c = make_extrusion(tri, {1, 0, 1});
    REQUIRE(!c.ok());
    CHECK(c.error().where.path == "direction");
    const DVec3 bent[] = {{0, 0, 0}, {1, 0, 0}, {1, 0.5, 1}, {0, 0, 1}};
    CHECK(!make_extrusion(bent, {0, 1, 0}).ok());
}

TEST_CASE("from points: the hull of a cube's corners and inside points is the cube") {
    std::vector<DVec3> pts;
    for (int i = 0; i < 8; ++i) pts.push_back({i & 1 ? 2.0 : 0.0, i & 2 ? 2.0 : 0.0, i & 4 ? 2.0 : 0.0});
    pts.push_back({1, 1, 1});
    pts.push_back({0.5, 1.5, 1});
    pts.push_back({1, 0, 1}); // on a face: not a corner
    auto b = make_from_points(pts);
    REQUIRE(b.ok());
    CHECK(audit(*b).empty());
    CHECK(b->faces().size() == 6); // coplanar facets merged
    CHECK(b->vertices().size() == 8);
    CHECK(b->volume() == doctest::Approx(8.0).epsilon(1e-14));
}

TEST_CASE("from points: an octahedron and a random cloud") {
    const DVec3 octa[] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    auto b = make_from_points(octa);
    REQUIRE(b.ok());
    CHECK(b->faces().size() == 8);
    CHECK(b->vertices().size() == 6);
    CHECK(b->volume() == doctest::Approx(4.0 / 3.0).epsilon(1e-14));
    std::vector<DVec3> cloud;
    for (int i = 0; i < 200; ++i) {
        const double t = i * 2.399963, z = 1.0 - 2.0 * (i + 0.5) / 200;
        const double r = std::sqrt(1 - z * z);
        cloud.push_back({r * std::cos(t) * 10, r * std::sin(t) * 10, z * 10});
    }
    auto s = make_from_points(cloud);
    REQUIRE_MESSAGE(s.ok(), (s.ok() ? "" : s.error().str()));
    CHECK(audit(*s).empty());
    CHECK(s->vertices().size() == 200);
    CHECK(s->volume() < 4.0 / 3.0 * 3.14159265 * 1000);
    CHECK(s->volume() == doctest::Approx(4.0 / 3.0 * 3.14159265 * 1000).epsilon(0.05));
}

TEST_CASE("from points refuses too few, coplanar, non-finite and too many points") {
    const DVec3 three[] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    CHECK(!make_from_points(three).ok());
    const DVec3 flat[] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0.5, 0.2, 0}};
    auto f = make_from_points(flat);
    REQUIRE(!f.ok());
    CHECK(f.error().message.find("no volume") != std::string::npos);
    const DVec3 nan[] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, std::nan("")}};
    auto n = make_from_points(nan);
    REQUIRE(!n.ok());
    CHECK(n.error().where.path == "points[3]");
    std::vector<DVec3> many(kMaxHullPoints + 1, DVec3(0.0));
    CHECK(!make_from_points(many).ok());
}
