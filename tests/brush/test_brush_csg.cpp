// CSG: subtract (fragment counts of the standard cases, volume conserved, coplanar faces), intersect, merge,
// hollow; fragments keep their faces' materials.
#include "brush/brush_build.h"
#include "brush/brush_clip.h"
#include "brush/brush_csg.h"
#include "brush/texture_mapping.h"
#include "brush_checks.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace ks;
using namespace ks::brush;
using ks::brush_test::audit;

namespace {

Brush box(DVec3 lo, DVec3 hi, const char* material) {
    FaceAttributes a;
    a.material = material;
    auto b = make_box(lo, hi, a);
    REQUIRE(b.ok());
    return *b;
}

double smallest_face_area(const Brush& b) {
    double smallest = 1e300;
    for (const auto& poly : b.polygons()) {
        DVec3 sum(0.0);
        for (std::size_t k = 1; k + 1 < poly.size(); ++k)
            sum += glm::cross(b.vertices()[poly[k]] - b.vertices()[poly[0]],
                              b.vertices()[poly[k + 1]] - b.vertices()[poly[0]]);
        smallest = std::min(smallest, 0.5 * glm::length(sum));
    }
    return smallest;
}

// Subtracts and checks what every subtraction must hold; returns the fragment count.
std::size_t fragments_of(const Brush& a, const Brush& b, double removed_volume) {
    auto r = subtract(a, b);
    REQUIRE(r.ok());
    double sum = 0;
    for (const Brush& f : r->fragments) {
        CHECK(audit(f).empty());
        CHECK(smallest_face_area(f) > 1e-6); // no zero-area faces
        sum += f.volume();
        for (const Face& face : f.faces()) {
            const bool from_a = a.find_face(face.plane) >= 0;
            CHECK(face.attributes.material == (from_a ? "wall" : "cut"));
        }
    }
    // No holes, no overlaps: the fragments and the removed part are A.
    const double removed = r->removed ? r->removed->volume() : 0.0;
    CHECK(removed == doctest::Approx(removed_volume).epsilon(1e-12));
    CHECK(std::abs(sum + removed - a.volume()) <= 1e-12 * a.volume());
    return r->fragments.size();
}

} // namespace

TEST_CASE("subtract: fragment counts of the standard cases") {
    const Brush wall = box({0, 0, 0}, {10, 4, 0.5}, "wall");
    CHECK(fragments_of(wall, box({3, 1, -1}, {5, 3, 1.5}, "cut"), 2.0) == 4); // a window through a wall
    const Brush block = box({0, 0, 0}, {4, 4, 4}, "wall");
    CHECK(fragments_of(block, box({3, 3, -1}, {5, 5, 5}, "cut"), 4.0) == 2);    // notch along an edge
    CHECK(fragments_of(block, box({3, 3, 3}, {5, 5, 5}, "cut"), 1.0) == 3);     // notch on a corner
    CHECK(fragments_of(block, box({1, 3, 1}, {3, 5, 3}, "cut"), 4.0) == 5);     // dent in a face
    CHECK(fragments_of(block, box({1, 1, 1}, {3, 3, 3}, "cut"), 8.0) == 6);     // B inside A
    CHECK(fragments_of(block, box({-1, 3, 1}, {5, 5, 3}, "cut"), 8.0) == 3);    // a groove across a face
    CHECK(fragments_of(block, box({-1, -1, 1}, {5, 5, 3}, "cut"), 32.0) == 2);  // cut in two
    CHECK(fragments_of(block, box({-1, -1, -1}, {5, 5, 5}, "cut"), 64.0) == 0); // B swallows A
    CHECK(fragments_of(block, box({6, 0, 0}, {8, 4, 4}, "cut"), 0.0) == 1);     // apart: A itself
}

TEST_CASE("subtract with coplanar faces: no holes, no zero-area faces, no slivers") {
    const Brush block = box({0, 0, 0}, {4, 4, 4}, "wall");
    // A pocket flush with the top (B's top on A's top): the top plane cuts nothing.
    CHECK(fragments_of(block, box({1, 2, 1}, {3, 4, 3}, "cut"), 8.0) == 5);
    // B flush with two faces and the top: a corner notch whose three planes lie on A's faces.
    CHECK(fragments_of(block, box({2, 2, 2}, {4, 4, 4}, "cut"), 8.0) == 3);
    // B touching A from outside along a whole face: nothing removed, A itself.
    CHECK(fragments_of(block, box({4, 0, 0}, {6, 4, 4}, "cut"), 0.0) == 1);
    // B exactly A: everything removed.
    CHECK(fragments_of(block, box({0, 0, 0}, {4, 4, 4}, "cut"), 64.0) == 0);
}

TEST_CASE("subtract: the greedy order takes the biggest cut first and saves a fragment") {
    const Brush block = box({0, 0, 0}, {4, 4, 4}, "wall");
    // B's floor is two planes: y >= 1 (listed first) and 0.1 x + y >= 1.5, which lies above y = 1 all over
    // the block, so its cut contains the first one's. In list order that makes 2 fragments; biggest first, 1.
    const DVec3 slope = glm::normalize(DVec3(0.1, 1, 0));
    std::vector<Face> faces = {{{{0, -1, 0}, -1.0}, {}}, {{-slope, -1.5 / glm::length(DVec3(0.1, 1, 0))}, {}},
                               {{{-1, 0, 0}, 1.0}, {}},  {{{1, 0, 0}, 10.0}, {}},
                               {{{0, 0, -1}, 1.0}, {}},  {{{0, 0, 1}, 5.0}, {}},
                               {{{0, 1, 0}, 6.0}, {}}};
    for (Face& f : faces) f.attributes.material = "cut";
    auto cutter = Brush::from_faces(faces);
    REQUIRE(cutter.ok());
    CHECK(cutter->faces().size() == 7);
    auto r = subtract(block, *cutter);
    REQUIRE(r.ok());
    CHECK(r->fragments.size() == 1);
    CHECK(audit(r->fragments[0]).empty());
    auto plain = subtract(block, *cutter, CutOrder::in_order);
    REQUIRE(plain.ok());
    CHECK(plain->fragments.size() == 2);
    CHECK(plain->removed->volume() == doctest::Approx(r->removed->volume()).epsilon(1e-13));
}

TEST_CASE("subtract: B near A with overlapping bounds but no common volume leaves A whole") {
    const Brush block = box({0, 0, 0}, {4, 4, 4}, "wall");
    // A corner of a box beyond x + y + z = 13, over A's corner (4, 4, 4) where x + y + z = 12.
    auto corner =
        clip(box({3, 3, 3}, {6, 6, 6}, "cut"), {glm::normalize(DVec3(-1, -1, -1)), -13 / std::sqrt(3.0)});
    REQUIRE(corner.ok());
    for (CutOrder order : {CutOrder::largest_first, CutOrder::in_order}) {
        auto r = subtract(block, *corner, order);
        REQUIRE(r.ok());
        REQUIRE(r->fragments.size() == 1);
        CHECK(!r->removed);
        CHECK(r->fragments[0].faces().size() == 6);
        CHECK(r->fragments[0].volume() == doctest::Approx(64.0));
    }
}

TEST_CASE("intersect: the common part, refused when apart or only touching") {
    const Brush a = box({0, 0, 0}, {4, 4, 4}, "wall");
    auto common = intersect(a, box({2, 1, -1}, {6, 3, 5}, "cut"));
    REQUIRE(common.ok());
    CHECK(audit(*common).empty());
    CHECK(common->volume() == doctest::Approx(2 * 2 * 4));
    CHECK(common->faces().size() == 6);
    CHECK(!intersect(a, box({5, 0, 0}, {6, 1, 1}, "cut")).ok());
    CHECK(!intersect(a, box({4, 0, 0}, {6, 4, 4}, "cut")).ok());
}

TEST_CASE("intersect_all: refusals name the brushes and say why") {
    const Brush a = box({0, 0, 0}, {4, 4, 4}, "wall");
    const Brush overlapping = box({2, 2, 2}, {6, 6, 6}, "cut");
    const Brush apart = box({10, 0, 0}, {12, 4, 4}, "cut");
    CHECK(!intersect_all(std::span<const Brush>(&a, 1)).ok());
    const Brush disjoint[] = {a, overlapping, apart};
    auto refused = intersect_all(disjoint);
    REQUIRE(!refused.ok());
    CHECK(refused.error().message.find("brushes[0] and brushes[2]") != std::string::npos);
    CHECK(refused.error().message.find("do not overlap") != std::string::npos);
    CHECK(refused.error().where.path == "brushes[2]");
    // Touching along a face only: no volume in common.
    const Brush touching[] = {a, box({4, 0, 0}, {8, 4, 4}, "cut")};
    REQUIRE(!intersect_all(touching).ok());
    // Three bars overlapping two by two around a triangle, with nothing common to all three.
    const Brush along_x = box({0, 0, 0}, {10, 1, 1}, "a"), along_z = box({0, 0, 0}, {1, 1, 10}, "b");
    auto diagonal = clip(box({-1, 0, -1}, {11, 1, 11}, "c"),
                         {glm::normalize(DVec3(1, 0, 1)), 10.5 / std::sqrt(2.0)}, ClipSide::keep_back);
    REQUIRE(diagonal.ok());
    diagonal =
        clip(*diagonal, {glm::normalize(DVec3(-1, 0, -1)), -9.5 / std::sqrt(2.0)}, ClipSide::keep_back);
    REQUIRE(diagonal.ok());
    const Brush triangle[] = {along_x, along_z, *diagonal};
    auto none = intersect_all(triangle);
    REQUIRE(!none.ok());
    CHECK(none.error().message.find("no volume in common") != std::string::npos);
}

TEST_CASE("intersect_all: shared faces keep the first brush's attributes; three brushes at once") {
    const Brush a = box({0, 0, 0}, {4, 4, 4}, "wall");
    const Brush flush = box({0, 0, 2}, {4, 4, 6}, "cut"); // shares the four side planes with a
    const Brush pair[] = {a, flush};
    auto common = intersect_all(pair);
    REQUIRE(common.ok());
    CHECK(audit(*common).empty());
    CHECK(common->faces().size() == 6);
    CHECK(common->volume() == doctest::Approx(32.0));
    for (const Face& f : common->faces())
        CHECK(f.attributes.material == (f.plane.normal.z < -0.5 ? "cut" : "wall"));
    const Brush three[] = {a, flush, box({1, -1, -1}, {3, 5, 5}, "third")};
    auto all = intersect_all(three);
    REQUIRE(all.ok());
    CHECK(audit(*all).empty());
    CHECK(all->volume() == doctest::Approx(2 * 4 * 2));
}

TEST_CASE("intersect_all: nearly parallel planes and coordinates near the limit") {
    // A box turned 1e-6 rad about z: its sides are 1e-6 rad from a's.
    const double t = 1e-6;
    const glm::dmat3 turn{{std::cos(t), std::sin(t), 0}, {-std::sin(t), std::cos(t), 0}, {0, 0, 1}};
    auto tilted = transformed(box({1, 0, 0}, {5, 4, 4}, "cut"), turn, DVec3(0.0));
    REQUIRE(tilted.ok());
    const Brush near_parallel[] = {box({0, 0, 0}, {4, 4, 4}, "wall"), *tilted};
    auto slanted = intersect_all(near_parallel);
    REQUIRE(slanted.ok());
    CHECK(audit(*slanted).empty());
    CHECK(slanted->volume() == doctest::Approx(3 * 4 * 4).epsilon(1e-4));
    // Far out: 60 000 units from the origin on every axis.
    const DVec3 far(60000, -60000, 60000);
    const Brush distant[] = {box(far, far + DVec3(4), "wall"),
                             box(far + DVec3(2, 1, 3), far + DVec3(7), "cut")};
    auto out = intersect_all(distant);
    REQUIRE(out.ok());
    CHECK(audit(*out).empty());
    CHECK(out->volume() == doctest::Approx(2 * 3 * 1).epsilon(1e-9));
    for (const DVec3& v : out->vertices()) CHECK(glm::length(v - glm::round(v)) < 1e-9);
}

TEST_CASE("merge: a convex union is one brush; a non-convex one is refused") {
    const Brush left = box({0, 0, 0}, {2, 2, 2}, "wall");
    FaceAttributes other;
    other.material = "cut";
    auto right = make_box({2, 0, 0}, {5, 2, 2}, other);
    REQUIRE(right.ok());
    auto merged = merge(left, *right);
    REQUIRE(merged.ok());
    CHECK(audit(*merged).empty());
    CHECK(merged->faces().size() == 6);
    CHECK(merged->volume() == doctest::Approx(20.0));
    for (const Face& f : merged->faces())
        if (f.plane.normal.x < -0.5)
            CHECK(f.attributes.material == "wall");
        else if (f.plane.normal.x > 0.5)
            CHECK(f.attributes.material == "cut");
    // Overlapping halves merge too; a box inside another merges into the bigger.
    CHECK(merge(left, box({1, 0, 0}, {3, 2, 2}, "cut")).ok());
    auto inner = merge(box({0, 0, 0}, {4, 4, 4}, "wall"), left);
    REQUIRE(inner.ok());
    CHECK(inner->volume() == doctest::Approx(64.0));
    // An L and two boxes apart are not convex.
    auto l_shape = merge(left, box({2, 0, 0}, {4, 1, 2}, "cut"));
    REQUIRE(!l_shape.ok());
    CHECK(l_shape.error().message.find("not convex") != std::string::npos);
    CHECK(!merge(left, box({3, 0, 0}, {4, 2, 2}, "cut")).ok());
}

TEST_CASE("hollow: six walls of the thickness, the inside removed") {
    const Brush block = box({0, 0, 0}, {4, 4, 4}, "wall");
    auto walls = hollow(block, 0.5);
    REQUIRE(walls.ok());
    CHECK(walls->size() == 6);
    double sum = 0;
    for (const Brush& w : *walls) {
        CHECK(audit(w).empty());
        sum += w.volume();
        for (const Face& f : w.faces()) CHECK(f.attributes.material == "wall");
    }
    CHECK(sum == doctest::Approx(64.0 - 27.0).epsilon(1e-13));
    auto too_thick = hollow(block, 2.0);
    REQUIRE(!too_thick.ok());
    CHECK(too_thick.error().where.path == "thickness");
    CHECK(!hollow(block, 0.0).ok());
    CHECK(!hollow(block, std::nan("")).ok());
    // A slanted brush hollows too: every wall valid, volumes add up.
    auto wedge = make_extrusion(std::vector<DVec3>{{0, 0, 0}, {6, 0, 0}, {0, 0, 6}}, {0, 3, 0});
    REQUIRE(wedge.ok());
    auto wedge_walls = hollow(*wedge, 0.25);
    REQUIRE(wedge_walls.ok());
    CHECK(wedge_walls->size() == 5);
    for (const Brush& w : *wedge_walls) CHECK(audit(w).empty());
}
