// Clipping and splitting by a plane; texture coordinates and texture lock through moves, turns and clips.
#include "brush/brush_build.h"
#include "brush/brush_clip.h"
#include "brush/texture_mapping.h"
#include "brush_checks.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace ks;
using namespace ks::brush;
using ks::brush_test::audit;
using ks::brush_test::has_vertex;

namespace {

FaceAttributes mapping(const char* material, double ox, double oy, double sx, double sy, double rot) {
    FaceAttributes a;
    a.material = material;
    a.offset = {ox, oy};
    a.scale = {sx, sy};
    a.rotation_degrees = rot;
    return a;
}

// A box whose faces all have different mappings.
Brush mapped_box() {
    auto b = make_box({-1, 0, -2}, {3, 2, 1});
    REQUIRE(b.ok());
    std::vector<Face> faces = b->faces();
    for (std::size_t i = 0; i < faces.size(); ++i)
        faces[i].attributes = mapping(i % 2 ? "metal" : "concrete", 0.25 * i, -0.5 * i, 0.5 + 0.25 * i,
                                      2.0 - 0.2 * i, 17.0 * i);
    auto mapped = Brush::from_faces(faces);
    REQUIRE(mapped.ok());
    return *mapped;
}

// A point inside face f's polygon (the mean of its corners).
DVec3 face_point(const Brush& b, std::size_t f) {
    DVec3 c(0.0);
    for (int v : b.polygons()[f]) c += b.vertices()[v];
    return c / double(b.polygons()[f].size());
}

} // namespace

TEST_CASE("clip keeps the back, the front, or split gives both") {
    auto box = make_box({0, 0, 0}, {4, 2, 2});
    REQUIRE(box.ok());
    const Plane cut{glm::normalize(DVec3(1, 1, 0)), 3.0 / std::sqrt(2.0)}; // x + y = 3
    auto back = clip(*box, cut);
    REQUIRE(back.ok());
    CHECK(audit(*back).empty());
    CHECK(back->faces().size() == 6); // +x is wholly in front: dropped; the cut face came in
    CHECK(has_vertex(*back, {3, 0, 0}, 1e-12));
    CHECK(has_vertex(*back, {1, 2, 2}, 1e-12));
    auto front = clip(*box, cut, ClipSide::keep_front);
    REQUIRE(front.ok());
    CHECK(audit(*front).empty());
    CHECK(back->volume() + front->volume() == doctest::Approx(16.0).epsilon(1e-14));
    auto both = split(*box, cut);
    REQUIRE(both.ok());
    REQUIRE(both->back);
    REQUIRE(both->front);
    CHECK(both->back->volume() == doctest::Approx(back->volume()).epsilon(1e-15));
    CHECK(both->front->volume() == doctest::Approx(front->volume()).epsilon(1e-15));
}

TEST_CASE("a plane missing the brush leaves it whole on one side and clipping the empty side is refused") {
    auto box = make_box({0, 0, 0}, {1, 1, 1});
    REQUIRE(box.ok());
    const Plane above{{0, 1, 0}, 5.0};
    auto parts = split(*box, above);
    REQUIRE(parts.ok());
    CHECK(parts->back);
    CHECK(!parts->front);
    auto kept = clip(*box, above, ClipSide::keep_front);
    REQUIRE(!kept.ok());
    CHECK(kept.error().message.find("nothing") != std::string::npos);
    // A plane along a face: nothing is cut, no zero-area face appears.
    auto flush = split(*box, Plane{{0, 1, 0}, 1.0});
    REQUIRE(flush.ok());
    REQUIRE(flush->back);
    CHECK(!flush->front);
    CHECK(flush->back->faces().size() == 6);
}

TEST_CASE("a clip that cuts a face away drops that face") {
    auto box = make_box({0, 0, 0}, {2, 2, 2});
    REQUIRE(box.ok());
    auto corner = clip(*box, {glm::normalize(DVec3(1, 1, 1)), 4.0 / std::sqrt(3.0)}); // through 3 corners
    REQUIRE(corner.ok());
    CHECK(audit(*corner).empty());
    CHECK(corner->faces().size() == 7);
    CHECK(corner->vertices().size() == 7);
    CHECK(corner->volume() == doctest::Approx(8.0 - 8.0 / 6.0));
    auto wedge = clip(*box, {glm::normalize(DVec3(1, 1, 0)), 2.0 / std::sqrt(2.0)}); // x + y <= 2
    REQUIRE(wedge.ok());
    CHECK(wedge->faces().size() == 5); // +x and +y are gone: a triangular prism
    CHECK(wedge->volume() == doctest::Approx(4.0));
}

TEST_CASE("clipping a non-finite plane is refused") {
    auto box = make_box({0, 0, 0}, {1, 1, 1});
    REQUIRE(box.ok());
    CHECK(!split(*box, Plane{{0, std::nan(""), 0}, 0.5}).ok());
    CHECK(!split(*box, Plane{{0, 0, 0}, 0.5}).ok());
}

TEST_CASE("texture coordinates: walls map u horizontally and v up; floors map u along x") {
    const Face wall{{{0, 0, 1}, 2.0}, mapping("w", 0, 0, 1, 1, 0)};
    CHECK(texture_coordinates(wall, {3, 5, 2}) == glm::dvec2(3, 5));
    const Face east{{{1, 0, 0}, 0.0}, mapping("w", 0.5, 0, 2, 4, 0)};
    const auto e = texture_coordinates(east, {0, 8, -6});
    CHECK(e.x == doctest::Approx(6 / 2.0 + 0.5)); // u = cross(+y, +x) = -z
    CHECK(e.y == doctest::Approx(2.0));
    const Face floor{{{0, 1, 0}, 0.0}, mapping("f", 0, 0, 1, 1, 0)};
    CHECK(texture_coordinates(floor, {3, 0, 4}) == glm::dvec2(3, -4));
    const Face turned{{{0, 0, 1}, 0.0}, mapping("w", 0, 0, 1, 1, 90)};
    const auto t = texture_coordinates(turned, {1, 0, 0});
    CHECK(t.x == doctest::Approx(0.0).epsilon(1e-15));
    CHECK(t.y == doctest::Approx(-1.0));
    // A sloped face is not stretched: one unit along the slope is one texture unit.
    const Face slope{{glm::normalize(DVec3(0, 1, 1)), 0.0}, mapping("s", 0, 0, 1, 1, 0)};
    const auto a = texture_coordinates(slope, {0, 0, 0}),
               b = texture_coordinates(slope, DVec3(0, 1, -1) / std::sqrt(2.0));
    CHECK(glm::length(a - b) == doctest::Approx(1.0));
}

TEST_CASE("texture lock: moving and turning a brush keeps every face's world mapping") {
    const Brush box = mapped_box();
    const glm::dmat3 turns[] = {glm::dmat3(1.0),
                                glm::mat3_cast(glm::angleAxis(0.7, glm::normalize(DVec3(1, 2, 3)))),
                                glm::mat3_cast(glm::angleAxis(3.14159265358979 / 2, DVec3(0, 1, 0))),
                                glm::mat3_cast(glm::angleAxis(2.5, DVec3(1, 0, 0)))};
    for (const glm::dmat3& r : turns) {
        const DVec3 t(12.5, -3.25, 7.0);
        auto moved = transformed(box, r, t);
        REQUIRE(moved.ok());
        CHECK(audit(*moved).empty());
        CHECK(moved->volume() == doctest::Approx(box.volume()).epsilon(1e-12));
        for (std::size_t f = 0; f < box.faces().size(); ++f) {
            const DVec3 p = face_point(box, f) +
                            DVec3(0.1, 0.05, -0.07) * (DVec3(1.0) - glm::abs(box.faces()[f].plane.normal));
            const int g =
                moved->find_face({glm::normalize(r * box.faces()[f].plane.normal),
                                  box.faces()[f].plane.distance +
                                      glm::dot(glm::normalize(r * box.faces()[f].plane.normal), t)});
            REQUIRE(g >= 0);
            const auto before = texture_coordinates(box.faces()[f], p);
            const auto after = texture_coordinates(moved->faces()[g], r * p + t);
            CHECK(glm::length(before - after) < 1e-9);
            CHECK(moved->faces()[g].attributes.material == box.faces()[f].attributes.material);
            CHECK(moved->faces()[g].attributes.scale == box.faces()[f].attributes.scale);
        }
    }
    // Without the lock the attributes stay, so a moved face's texture slides.
    auto unlocked = translated(box, {0.3, 0, 0}, TextureLock::off);
    REQUIRE(unlocked.ok());
    CHECK(unlocked->faces()[4].attributes == box.faces()[4].attributes);
    CHECK(glm::length(texture_coordinates(unlocked->faces()[4], face_point(box, 4) + DVec3(0.3, 0, 0)) -
                      texture_coordinates(box.faces()[4], face_point(box, 4))) > 0.1);
}

TEST_CASE("texture lock: a clip keeps the mapping of every kept face") {
    const Brush box = mapped_box();
    auto cut =
        clip(box, {glm::normalize(DVec3(1, 1, 1)), 1.0}, ClipSide::keep_back, mapping("cap", 0, 0, 1, 1, 0));
    REQUIRE(cut.ok());
    for (std::size_t f = 0; f < cut->faces().size(); ++f) {
        const int original = box.find_face(cut->faces()[f].plane);
        if (original < 0) {
            CHECK(cut->faces()[f].attributes.material == "cap");
            continue;
        }
        const DVec3 p = face_point(*cut, f);
        CHECK(texture_coordinates(cut->faces()[f], p) == texture_coordinates(box.faces()[original], p));
    }
}

TEST_CASE("a motion that is not a rotation is refused") {
    const Brush box = mapped_box();
    CHECK(!transformed(box, glm::dmat3(2.0), DVec3(0.0)).ok());
    glm::dmat3 mirror(1.0);
    mirror[0][0] = -1.0;
    CHECK(!transformed(box, mirror, DVec3(0.0)).ok());
    CHECK(!translated(box, DVec3(std::nan(""), 0, 0)).ok());
}
