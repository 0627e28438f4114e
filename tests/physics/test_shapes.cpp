// Shapes: polyhedra built right (faces, planes, edges), convex hulls from mesh vertices, and bad input
// rejected with a clear error instead of NaN later.
#include "physics/shapes.h"

#include <cmath>
#include <doctest/doctest.h>
#include <vector>

using namespace ks;
using namespace ks::physics;

namespace {
void check_closed_convex(const Polyhedron& p) {
    // Every vertex lies on or behind every face plane; every face normal is unit and finite.
    for (const auto& f : p.faces) {
        CHECK(std::abs(glm::length(f.normal) - 1.0f) < 1e-5f);
        for (const Vec3& v : p.vertices) CHECK(glm::dot(f.normal, v) - f.offset <= 1e-4f);
    }
    // Euler characteristic of a convex polyhedron: V - E + F = 2.
    CHECK(static_cast<int>(p.vertices.size()) - static_cast<int>(p.edges.size()) +
              static_cast<int>(p.faces.size()) ==
          2);
}
} // namespace

TEST_CASE("box and wedge polyhedra are closed convex solids with merged faces") {
    const Polyhedron box = make_box_polyhedron({1, 2, 3});
    CHECK(box.vertices.size() == 8);
    CHECK(box.faces.size() == 6);
    CHECK(box.edges.size() == 12);
    CHECK(box.edge_directions.size() == 3);
    check_closed_convex(box);
    const Polyhedron wedge = make_wedge_polyhedron({6, 3, 6});
    CHECK(wedge.vertices.size() == 6);
    CHECK(wedge.faces.size() == 5);
    CHECK(wedge.edges.size() == 9);
    check_closed_convex(wedge);
    // The slope of the main level's stairs: rise 6 over run 12 = 26.57 degrees, facing up and toward +z.
    bool found_slope = false;
    for (const auto& f : wedge.faces)
        if (f.normal.y > 0.1f && f.normal.y < 0.99f) {
            found_slope = true;
            CHECK(degrees(std::acos(f.normal.y)) == doctest::Approx(26.565).epsilon(1e-4));
            CHECK(f.normal.z > 0.0f);
        }
    CHECK(found_slope);
}

TEST_CASE("convex hull from mesh vertices: duplicates welded, interior points dropped, coplanar merged") {
    std::vector<Vec3> pts;
    for (int i = 0; i < 8; ++i)
        pts.push_back({(i & 1) ? 1.f : -1.f, (i & 2) ? 1.f : -1.f, (i & 4) ? 1.f : -1.f});
    pts.push_back({1, 1, 1});       // duplicate vertex
    pts.push_back({0.2f, 0.1f, 0}); // interior point
    pts.push_back({1, 0, 0});       // on a face: the face stays one quad
    pts.push_back({1, 1, 0});       // on an edge
    auto hull = build_convex_hull(pts, "crate.obj");
    REQUIRE(hull.ok());
    CHECK(hull->faces.size() == 6);
    CHECK(hull->vertices.size() == 8);
    for (const auto& f : hull->faces) CHECK(f.count == 4);
    check_closed_convex(*hull);

    // A 16-gon prism (a polygonal prop): 18 faces, both caps merged into one polygon each.
    std::vector<Vec3> prism;
    for (int i = 0; i < 16; ++i) {
        const float a = 2.0f * kPi * i / 16.0f;
        prism.push_back({std::cos(a), -1.0f, std::sin(a)});
        prism.push_back({std::cos(a), 1.0f, std::sin(a)});
    }
    auto p = build_convex_hull(prism, "prism");
    REQUIRE(p.ok());
    CHECK(p->faces.size() == 18);
    check_closed_convex(*p);
}

TEST_CASE("degenerate collision meshes are rejected with a clear error, never NaN") {
    const std::vector<Vec3> flat = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {1, 0, 1}, {0.5f, 0, 0.5f}};
    auto r = build_convex_hull(flat, "levels/props/sign.obj");
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().str().find("levels/props/sign.obj") != std::string::npos);
    CHECK(r.error().message.find("coplanar") != std::string::npos);

    const std::vector<Vec3> line = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}};
    CHECK(build_convex_hull(line, "line").error().message.find("collinear") != std::string::npos);

    const std::vector<Vec3> dups = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {1, 1, 1}};
    CHECK(build_convex_hull(dups, "dups").error().message.find("4 distinct") != std::string::npos);

    const std::vector<Vec3> nan = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, NAN}};
    auto n = build_convex_hull(nan, "nan.obj");
    REQUIRE_FALSE(n.ok());
    CHECK(n.error().message.find("vertex 3") != std::string::npos);

    CHECK_FALSE(Shape::box({5, 8, 0}).validate("wall 3").ok()); // zero-thickness wall
    CHECK(Shape::box({5, 8, 0}).validate("wall 3").error().message.find("wall 3") != std::string::npos);
    CHECK_FALSE(Shape::box({5, NAN, 1}).validate("w").ok());
    CHECK_FALSE(Shape::capsule(-1, 0.5f).validate("robot").ok());
    CHECK_FALSE(Shape::cylinder(1, 0).validate("gas").ok());
    CHECK(Shape::capsule(1, 0.5f).validate("player").ok());
    CHECK(Shape::wedge({6, 3, 6}).validate("stairs").ok());
}

TEST_CASE("hull shapes are recentred on their bounding box; world bounds are exact for rotated boxes") {
    std::vector<Vec3> pts;
    for (int i = 0; i < 8; ++i)
        pts.push_back({(i & 1) ? 11.f : 10.f, (i & 2) ? 3.f : 1.f, (i & 4) ? 1.f : 0.f});
    auto hull = build_convex_hull(pts, "offset");
    REQUIRE(hull.ok());
    const Shape s = Shape::hull(std::move(*hull));
    CHECK(s.half_extents == Vec3(0.5f, 1.0f, 0.5f));
    CHECK(glm::length(s.polyhedron->bounds.center()) < 1e-6f);

    const Shape box = Shape::box({2, 1, 0.5f});
    const geometry::Aabb b = box.bounds({{0, 0, 0}, glm::angleAxis(kPi / 2, Vec3(0, 1, 0))});
    CHECK(b.max.x == doctest::Approx(0.5f));
    CHECK(b.max.z == doctest::Approx(2.0f));
}
