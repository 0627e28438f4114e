// Placing a stored brush in the world (brush::placed, Brush::carried): the geometry carried through the
// rigid motion instead of derived again must give what deriving gives — the same faces bit for bit (planes,
// anchor, locked texture attributes), the same topology, vertices within a few ulps of the world coordinate
// — for random hulls, slivers, near-parallel faces, tiny turns, quarter turns and placements far out.
#include "bench/brush/brush_error.h"
#include "brush/brush_build.h"
#include "brush/texture_mapping.h"
#include "brush_checks.h"
#include "core/random.h"

#include <doctest/doctest.h>

#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <vector>

using namespace ks;
using namespace ks::brush;
using ks::brush::bench::off_plane;
using ks::brush_test::random_unit;

namespace placed_test {

// The farthest vertex of `a` from its nearest vertex in `b`, relative to the coordinates' size (at least 1).
double relative_vertex_distance(const Brush& a, const Brush& b) {
    double worst = 0;
    for (const DVec3& p : a.vertices()) {
        double nearest = 1e300;
        for (const DVec3& q : b.vertices()) nearest = std::min(nearest, glm::length(p - q));
        const double size = std::max({1.0, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
        worst = std::max(worst, nearest / size);
    }
    return worst;
}

struct Comparison {
    int both = 0, only_carried = 0, refused = 0;
    double vertex_distance = 0, carried_off_plane = 0, derived_off_plane = 0;
};

// Places `b` both ways and checks they agree. Carrying must succeed wherever deriving again does, with the
// same faces and topology; where deriving again refuses (a near-degenerate corner whose planes moved by a
// rounding), a carried result must still be a valid brush.
void compare_placements(const Brush& b, const glm::dmat3& turn, const DVec3& move, Comparison& out) {
    auto derived = transformed(b, turn, move, TextureLock::on);
    auto carried = placed(b, turn, move);
    const double size = std::max(1.0, glm::length(move) + glm::length(b.bounds_max()));
    if (!derived) {
        if (!carried) { // both refuse: only a placement beyond the world may be refused
            CHECK(carried.error().message.find("beyond") != std::string::npos);
            ++out.refused;
            return;
        }
        ++out.only_carried;
        CHECK(brush_test::audit(*carried, 1e-9 * size) == "");
        return;
    }
    REQUIRE(carried.ok());
    ++out.both;
    CHECK(*carried == *derived); // anchor and faces (planes and attributes) exactly
    REQUIRE(carried->vertices().size() == derived->vertices().size());
    REQUIRE(carried->polygons().size() == derived->polygons().size());
    for (std::size_t f = 0; f < carried->polygons().size(); ++f)
        CHECK(carried->polygons()[f].size() == derived->polygons()[f].size());
    CHECK(carried->edges().size() == derived->edges().size());
    CHECK(carried->volume() == doctest::Approx(derived->volume()).epsilon(1e-9));
    CHECK(brush_test::audit(*carried, 1e-9 * size) == "");
    out.vertex_distance = std::max(out.vertex_distance, relative_vertex_distance(*carried, *derived));
    out.carried_off_plane = std::max(out.carried_off_plane, off_plane(*carried) / size);
    out.derived_off_plane = std::max(out.derived_off_plane, off_plane(*derived) / size);
}

void report(const char* what, const Comparison& c) {
    MESSAGE(std::string(what) << ": both " << c.both << ", only carried " << c.only_carried << ", refused "
                              << c.refused << "; worst relative vertex distance " << c.vertex_distance
                              << ", off-plane (relative) carried " << c.carried_off_plane
                              << ", derived again " << c.derived_off_plane);
}

glm::dmat3 random_turn(Rng& rng) {
    return glm::mat3_cast(glm::angleAxis(rng.uniform_double() * 6.283185307179586, random_unit(rng)));
}

} // namespace placed_test
using namespace placed_test;

TEST_CASE("placed brushes: random hulls at random placements match a fresh derivation") {
    Rng rng(25);
    Comparison c;
    for (int i = 0; i < 400; ++i) {
        std::vector<DVec3> points;
        const int n = 4 + static_cast<int>(rng.below(24));
        for (int k = 0; k < n; ++k) points.push_back(random_unit(rng) * (1.0 + rng.uniform_double() * 20.0));
        auto hull = make_from_points(points);
        if (!hull) continue;
        const double far = i % 3 == 0 ? 60000.0 : i % 3 == 1 ? 3000.0 : 10.0;
        const DVec3 move = random_unit(rng) * far * rng.uniform_double();
        compare_placements(*hull, random_turn(rng), move, c);
    }
    report("random hulls", c);
    CHECK(c.both > 300);
    // Both sets of vertices lie on the moved planes to the same order (a few ulps of the coordinates); they
    // differ from each other by up to the derivation's own conditioning (near-parallel faces of a hull).
    CHECK(c.carried_off_plane < 1e-12);
    CHECK(c.carried_off_plane <= 4 * c.derived_off_plane + 1e-15);
    CHECK(c.vertex_distance < 1e-9);
}

TEST_CASE("placed brushes: hard cases — slivers, near-parallel faces, tiny and quarter turns, far out") {
    Rng rng(7);
    std::vector<Brush> hard;
    hard.push_back(*make_box(DVec3(0), DVec3(1000, 1e-3, 1000)));          // a sliver
    hard.push_back(*make_box(DVec3(-1e-2), DVec3(1e-2)));                  // tiny
    hard.push_back(*make_box(DVec3(-30000), DVec3(30000, -29990, 30000))); // huge and thin
    // A wedge whose top is within 1e-6 rad of its base.
    const DVec3 wedge[] = {{0, 0, 0}, {100, 0, 0}, {0, 0, 100}, {100, 0, 100}, {0, 1e-4, 0}, {0, 1e-4, 100}};
    hard.push_back(*make_from_points(wedge));
    const std::vector<glm::dmat3> turns = {
        glm::dmat3(1.0),
        glm::mat3_cast(glm::angleAxis(1e-12, DVec3(0, 1, 0))), // tiny
        glm::mat3_cast(glm::angleAxis(1.5707963267948966, DVec3(0, 1, 0))),
        glm::mat3_cast(glm::angleAxis(3.141592653589793, DVec3(1, 0, 0))),
        random_turn(rng),
    };
    const std::vector<DVec3> moves = {DVec3(0), DVec3(16, 0, -32), DVec3(0.1, 0.2, 0.3),
                                      DVec3(-30000, 100, 30000), DVec3(1e-9, 0, 0)};
    Comparison c;
    for (const Brush& b : hard)
        for (const auto& turn : turns)
            for (const DVec3& move : moves) compare_placements(b, turn, move, c);
    report("hard cases", c);
    CHECK(c.both + c.only_carried + c.refused == static_cast<int>(hard.size() * turns.size() * moves.size()));
    CHECK(c.refused <= 1); // the 60 000-unit box turned at random, moved 30 000 out
    CHECK(c.carried_off_plane < 1e-13);
    CHECK(c.vertex_distance < 1e-9);
}

TEST_CASE("placed brushes: refusals match transformed's (not a rotation, not finite, beyond the world)") {
    const Brush box = *make_box(DVec3(-1), DVec3(1));
    glm::dmat3 scaled(1.0);
    scaled[0][0] = 2.0;
    glm::dmat3 mirrored(1.0);
    mirrored[0][0] = -1.0;
    for (const auto& [turn, move] : std::vector<std::pair<glm::dmat3, DVec3>>{
             {scaled, DVec3(0)},
             {mirrored, DVec3(0)},
             {glm::dmat3(1.0), DVec3(std::nan(""), 0, 0)},
             {glm::dmat3(1.0), DVec3(1e300, 0, 0)},
             {glm::dmat3(1.0), DVec3(65536, 0, 0)}, // its corner at 65537
         }) {
        auto carried = placed(box, turn, move);
        CHECK_FALSE(carried.ok());
        CHECK_FALSE(transformed(box, turn, move).ok());
    }
    // Attributes: one per face, each checked.
    std::vector<FaceAttributes> few(2);
    CHECK_FALSE(box.carried(glm::dmat3(1.0), DVec3(0), few).ok());
    std::vector<FaceAttributes> bad(box.faces().size());
    bad[3].scale.x = 0;
    auto refused = box.carried(glm::dmat3(1.0), DVec3(0), bad);
    REQUIRE_FALSE(refused.ok());
    CHECK(refused.error().where.path.find("faces[3]") != std::string::npos);
}
