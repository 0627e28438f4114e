// What Brush::from_faces refuses, and that every refusal names the face and field and says the fix.
#include "brush/brush.h"
#include "brush/brush_build.h"

#include <doctest/doctest.h>

#include <chrono>
#include <cmath>
#include <limits>

using namespace ks;
using namespace ks::brush;

namespace {

std::vector<Face> cube_faces(double h = 1.0) {
    std::vector<Face> faces;
    for (int a = 0; a < 3; ++a)
        for (double s : {-1.0, 1.0}) {
            DVec3 n(0.0);
            n[a] = s;
            faces.push_back({{n, h}, {}});
        }
    return faces;
}

Error refusal(std::vector<Face> faces, RedundantPlanes mode = RedundantPlanes::refuse) {
    auto b = Brush::from_faces(std::move(faces), mode);
    REQUIRE(!b.ok());
    CHECK(!b.error().hint.empty());
    return b.error();
}

} // namespace

TEST_CASE("fewer than 4 planes are refused") {
    auto faces = cube_faces();
    faces.resize(3);
    const Error e = refusal(faces);
    CHECK(e.where.path == "faces");
    CHECK(e.message.find("at least 4") != std::string::npos);
}

TEST_CASE("a million planes are refused at once, without deriving") {
    std::vector<Face> faces(1000000, Face{{DVec3(0, 0, 1), 1.0}, {}});
    const auto t0 = std::chrono::steady_clock::now();
    const Error e = refusal(std::move(faces));
    CHECK(std::chrono::steady_clock::now() - t0 < std::chrono::seconds(1));
    CHECK(e.message.find("limit") != std::string::npos);
}

TEST_CASE("non-finite numbers are refused, naming the face and field") {
    const double nan = std::numeric_limits<double>::quiet_NaN(),
                 inf = std::numeric_limits<double>::infinity();
    auto a = cube_faces();
    a[2].plane.normal.y = nan;
    CHECK(refusal(a).where.path == "faces[2].plane.normal");
    auto b = cube_faces();
    b[4].plane.distance = inf;
    CHECK(refusal(b).where.path == "faces[4].plane.distance");
    auto c = cube_faces();
    c[1].attributes.offset.x = nan;
    CHECK(refusal(c).where.path == "faces[1].offset");
    auto d = cube_faces();
    d[5].attributes.scale.y = 0.0;
    CHECK(refusal(d).where.path == "faces[5].scale.y");
    auto e = cube_faces();
    e[0].attributes.rotation_degrees = inf;
    CHECK(refusal(e).where.path == "faces[0].rotation");
    auto f = cube_faces();
    f[3].plane.normal = DVec3(0.0);
    CHECK(refusal(f).where.path == "faces[3].plane.normal");
}

TEST_CASE("normals of any length are accepted and made unit") {
    auto faces = cube_faces();
    faces[0].plane = {DVec3(-4, 0, 0), 4.0}; // x >= -1
    auto b = Brush::from_faces(faces);
    REQUIRE(b.ok());
    CHECK(b->faces()[0].plane.normal == DVec3(-1, 0, 0));
    CHECK(b->faces()[0].plane.distance == 1.0);
    CHECK(b->volume() == doctest::Approx(8.0));
}

TEST_CASE("duplicate and opposite planes are refused") {
    auto dup = cube_faces();
    dup.push_back(dup[3]);
    const Error e = refusal(dup);
    CHECK(e.where.path == "faces[6]");
    CHECK(e.message.find("faces[3]") != std::string::npos);
    // In drop mode the duplicate goes.
    auto dropped = Brush::from_faces(dup, RedundantPlanes::drop);
    REQUIRE(dropped.ok());
    CHECK(dropped->faces().size() == 6);

    auto zero = cube_faces();
    zero[1].plane.distance = -1.0; // +x face at x = -1: the -x face turned around
    CHECK(refusal(zero).message.find("zero thickness") != std::string::npos);
    auto empty = cube_faces();
    empty[1].plane.distance = -2.0; // x <= -2 and x >= -1
    CHECK(refusal(empty).message.find("empty") != std::string::npos);
}

TEST_CASE("all-coplanar and prism-like plane sets are refused as unbounded") {
    std::vector<Face> stack;
    for (int i = 0; i < 5; ++i) stack.push_back({{DVec3(0, 1, 0), double(i)}, {}});
    stack.push_back({{DVec3(0, -1, 0), 1.0}, {}});
    CHECK(refusal(stack, RedundantPlanes::drop).message.find("parallel") != std::string::npos);
    auto prism = cube_faces();
    prism.erase(prism.begin() + 4, prism.end()); // no z planes
    prism.push_back({{glm::normalize(DVec3(1, 1, 0)), 1.2}, {}});
    const Error e = refusal(prism);
    CHECK(e.message.find("unbounded") != std::string::npos);
    CHECK(e.message.find("(0, 0, 1)") != std::string::npos);
}

TEST_CASE("an open cone of planes is refused as unbounded, naming a face") {
    std::vector<Face> faces;
    for (int i = 0; i < 5; ++i) {
        const double a = i * 2 * 3.141592653589793 / 5;
        faces.push_back({{glm::normalize(DVec3(std::cos(a), -0.5, std::sin(a))), 1.0}, {}});
    }
    const Error e = refusal(faces);
    CHECK(e.message.find("unbounded") != std::string::npos);
    CHECK(e.where.path.rfind("faces[", 0) == 0);
}

TEST_CASE("a redundant plane is refused, or dropped when asked") {
    auto faces = cube_faces();
    faces.push_back({{glm::normalize(DVec3(1, 1, 1)), 5.0}, {}}); // far outside the cube
    const Error e = refusal(faces);
    CHECK(e.where.path == "faces[6]");
    CHECK(e.message.find("contributes no face") != std::string::npos);
    faces.push_back({{glm::normalize(DVec3(1, 1, 0)), std::sqrt(2.0)}, {}}); // touches along an edge only
    auto dropped = Brush::from_faces(faces, RedundantPlanes::drop);
    REQUIRE(dropped.ok());
    CHECK(dropped->faces().size() == 6);
    CHECK(dropped->vertices().size() == 8);
}

TEST_CASE("planes enclosing nothing are refused as having no volume") {
    std::vector<Face> faces = cube_faces();
    faces.push_back({{glm::normalize(DVec3(-1, -1, -1)), -10.0}, {}}); // x + y + z >= 10 sqrt(3): beyond
    const Error e = refusal(faces, RedundantPlanes::drop);
    CHECK(e.message.find("no volume") != std::string::npos);
}

TEST_CASE("a brush beyond the world's limit is refused") {
    auto b = make_box({0, 0, 0}, {70000, 1, 1});
    REQUIRE(!b.ok());
    CHECK(b.error().message.find("65536") != std::string::npos);
}
