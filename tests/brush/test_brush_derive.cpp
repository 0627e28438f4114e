// The derivation itself (brush_derive.h, internal): corners where many planes meet weld into one vertex,
// large plane counts stay quick, and a vertex is as exact as its planes whatever the clipping order.
#include "brush/brush.h"
#include "brush/brush_build.h"
#include "brush/brush_derive.h"
#include "brush_checks.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <cmath>

using namespace ks;
using namespace ks::brush;
using ks::brush_test::audit;
using ks::brush_test::has_vertex;

namespace {

constexpr double kTau = 6.283185307179586;

// A pyramid of `sides` faces over a regular polygon: its apex lies on `sides` planes.
std::vector<Face> pyramid(int sides, double height) {
    std::vector<Face> faces = {{{{0, -1, 0}, 0.0}, {}}};
    for (int i = 0; i < sides; ++i) {
        const double a = kTau * (i + 0.5) / sides;
        const DVec3 out(std::cos(a), 0, std::sin(a));
        // Through the apex (0, height, 0) and the base edge at distance cos(pi / sides) from the axis.
        const double r = std::cos(kTau / 2 / sides);
        const DVec3 n = glm::normalize(DVec3(out.x * height, r, out.z * height));
        faces.push_back({{n, n.y * height}, {}});
    }
    return faces;
}

} // namespace

TEST_CASE("an apex where 64 planes meet is one vertex, exact") {
    auto b = Brush::from_faces(pyramid(64, 3.0));
    REQUIRE(b.ok());
    CHECK(audit(*b).empty());
    CHECK(b->vertices().size() == 65);
    CHECK(b->faces().size() == 65);
    CHECK(has_vertex(*b, {0, 3, 0}, 1e-14));
}

TEST_CASE("a vertex does not depend on the order of the planes") {
    std::vector<Face> faces = pyramid(7, 2.0);
    auto a = Brush::from_faces(faces);
    std::reverse(faces.begin(), faces.end());
    auto b = Brush::from_faces(faces);
    REQUIRE(a.ok());
    REQUIRE(b.ok());
    for (const DVec3& v : a->vertices()) CHECK(has_vertex(*b, v, 1e-15));
}

TEST_CASE("derive_geometry reports a plane that contributes nothing as an empty polygon") {
    std::vector<Plane> planes;
    for (const Face& f : pyramid(4, 1.0)) planes.push_back(f.plane);
    planes.push_back({{0, 1, 0}, 5.0}); // above the apex: cuts nothing
    auto d = derive_geometry(planes);
    REQUIRE(d.ok());
    CHECK(d->polygons.back().empty());
    CHECK(d->vertices.size() == 5);
}

TEST_CASE("a hull of 996 faces derives, and quickly enough for an editor") {
    std::vector<DVec3> cloud;
    for (int i = 0; i < 500; ++i) {
        const double t = i * 2.399963229728653, z = 1.0 - 2.0 * (i + 0.5) / 500;
        const double r = std::sqrt(1 - z * z);
        cloud.push_back({r * std::cos(t) * 20, z * 20, r * std::sin(t) * 20});
    }
    const auto t0 = std::chrono::steady_clock::now();
    auto b = make_from_points(cloud);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    REQUIRE_MESSAGE(b.ok(), (b.ok() ? "" : b.error().str()));
    CHECK(audit(*b).empty());
    CHECK(b->faces().size() > 990);
    CHECK(b->faces().size() <= kMaxFaces);
    CHECK(b->vertices().size() == 500);
    MESSAGE(b->faces().size() << " faces derived in " << seconds << " s");
    CHECK(seconds < 10.0); // generous: sanitizer builds and a shared machine
}
