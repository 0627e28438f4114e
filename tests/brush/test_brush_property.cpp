// The property test of issue 25: 10 000 random clip, vertex-move and subtract edits from a seeded generator.
// Every result is audited independently (closed, convex, on its planes, positive volume): 0 invalid brushes.
// Snapping on (grid 1/8): every vertex of every snapped result, and of every vertex move of a snapped brush
// by a grid step, is within 1e-9 of the grid. Subtract conserves volume: volume(A) = sum of the fragments +
// volume(A n B) to 1e-9 relative. Brushes live near the origin and near (9000, -9000, 5000), so the far case
// is covered too.
#include "brush/brush_build.h"
#include "brush/brush_clip.h"
#include "brush/brush_csg.h"
#include "brush/brush_edit.h"
#include "brush/texture_mapping.h"
#include "brush_checks.h"
#include "core/random.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <array>
#include <cmath>

using namespace ks;
using namespace ks::brush;
using ks::brush_test::audit;
using ks::brush_test::grid_distance;
using ks::brush_test::random_unit;

namespace {

constexpr double kGrid = 0.125;
const DVec3 kCentres[] = {{0, 0, 0}, {9000, -9000, 5000}};

struct Tally {
    int edits = 0, accepted = 0, refused = 0, invalid = 0, off_grid = 0, volume_errors = 0,
        world_round_trip = 0;
    double worst_grid = 0, worst_volume = 0, worst_round_trip = 0;
    std::array<int, 3> accepted_by_kind{};
};

double grid_value(Rng& rng, int lo, int hi) {
    return kGrid * (lo + static_cast<int>(rng.below(static_cast<std::uint32_t>(hi - lo + 1))));
}

// A grid box, turned at random and snapped back to the grid: slanted faces through grid points.
Result<Brush> random_brush(Rng& rng, const DVec3& centre) {
    const DVec3 lo(grid_value(rng, -40, 0), grid_value(rng, -40, 0), grid_value(rng, -40, 0));
    const DVec3 hi = lo + DVec3(grid_value(rng, 8, 48), grid_value(rng, 8, 48), grid_value(rng, 8, 48));
    FaceAttributes attributes;
    attributes.material = "m" + std::to_string(rng.below(4));
    auto box = make_box(centre + lo, centre + hi, attributes);
    if (!box || rng.chance(0.3f)) return box;
    const glm::dmat3 turn = glm::mat3_cast(glm::angleAxis(rng.uniform_double() * 6.28, random_unit(rng)));
    auto turned = transformed(*box, turn, centre - turn * centre); // about the centre
    if (!turned) return turned;
    return snap_to_grid(*turned, kGrid);
}

// The farthest a vertex of `a` lies from every vertex of `b`.
double vertex_set_distance(const Brush& a, const Brush& b) {
    double worst = 0;
    for (const DVec3& p : a.vertices()) {
        double nearest = 1e300;
        for (const DVec3& q : b.vertices()) nearest = std::min(nearest, glm::length(p - q));
        worst = std::max(worst, nearest);
    }
    return worst;
}

void check_valid(const Brush& b, Tally& t) {
    const std::string problem = audit(b);
    if (!problem.empty()) {
        ++t.invalid;
        MESSAGE("invalid brush: " << problem);
    }
    // What a file would hold: the world planes, each rounded once. They must make the same brush again.
    // (Near a vertex where four planes nearly meet, rounding may split or join a corner below 1e-6 units.)
    auto again = Brush::from_faces(b.faces(), RedundantPlanes::drop);
    const double apart =
        again ? std::max(vertex_set_distance(b, *again), vertex_set_distance(*again, b)) : 1e300;
    t.worst_round_trip = std::max(t.worst_round_trip, apart);
    if (!again || apart > 1e-6) {
        ++t.world_round_trip;
        MESSAGE("world planes do not make the brush again: " << (again ? std::to_string(apart)
                                                                       : again.error().str()));
    }
}

void check_on_grid(const Brush& b, Tally& t) {
    const double d = grid_distance(b, kGrid);
    t.worst_grid = std::max(t.worst_grid, d);
    if (d > 1e-9) {
        ++t.off_grid;
        MESSAGE("off grid by " << d << " near " << b.vertex_centre().x << " faces " << b.faces().size()
                               << " vertices " << b.vertices().size());
        for (const DVec3& p : b.vertices()) {
            const DVec3 r = glm::round(p / kGrid) * kGrid;
            if (glm::length(p - r) > 1e-9) {
                std::string planes;
                for (const Face& f : b.faces())
                    if (std::abs(f.plane.signed_distance(r)) < 1e-6)
                        planes += " (" + std::to_string(f.plane.normal.x) + "," +
                                  std::to_string(f.plane.normal.y) + "," + std::to_string(f.plane.normal.z) +
                                  ")";
                MESSAGE("  vertex off by " << glm::length(p - r) << " planes:" << planes);
            }
        }
    }
}

// One edit of `b`; returns the brush to keep in its place (snapped), or nothing when refused.
std::optional<Brush> edit(Rng& rng, const Brush& b, Tally& t) {
    const int kind = static_cast<int>(rng.below(3));
    std::optional<Brush> out;
    if (kind == 0) { // clip by a random plane through a point inside, then snap
        const DVec3 through = b.vertex_centre() + random_unit(rng) * 0.5;
        const DVec3 n = random_unit(rng);
        auto cut =
            clip(b, {n, glm::dot(n, through)}, rng.chance(0.5f) ? ClipSide::keep_back : ClipSide::keep_front);
        if (cut) check_valid(*cut, t);
        if (cut) out = std::move(*cut);
    } else if (kind == 1) { // move one vertex, an edge or a face by grid steps: stays on the grid unsnapped
        const DVec3 delta(grid_value(rng, -8, 8), grid_value(rng, -8, 8), grid_value(rng, -8, 8));
        const int what = static_cast<int>(rng.below(3));
        Result<Brush> moved =
            what == 0 ? move_vertices(b, std::array{static_cast<int>(rng.below(b.vertices().size()))}, delta)
            : what == 1 ? move_edge(b, static_cast<int>(rng.below(b.edges().size())), delta)
                        : move_face(b, static_cast<int>(rng.below(b.faces().size())), delta);
        if (moved) {
            check_valid(*moved, t);
            check_on_grid(*moved, t);
            out = std::move(*moved);
        }
    } else { // subtract a random brush placed over this one; keep the largest fragment
        auto cutter = random_brush(rng, b.vertex_centre() + random_unit(rng) * 2.0);
        if (!cutter) return std::nullopt;
        auto r = subtract(b, *cutter);
        if (!r) return std::nullopt;
        double sum = r->removed ? r->removed->volume() : 0.0;
        for (const Brush& f : r->fragments) check_valid(f, t), sum += f.volume();
        if (r->removed) check_valid(*r->removed, t);
        const double error = std::abs(sum - b.volume()) / b.volume();
        t.worst_volume = std::max(t.worst_volume, error);
        if (error > 1e-9) ++t.volume_errors;
        for (const Brush& f : r->fragments)
            if (!out || f.volume() > out->volume()) out = f;
    }
    if (!out) return std::nullopt;
    ++t.accepted_by_kind[static_cast<std::size_t>(kind)];
    auto snapped = snap_to_grid(*out, kGrid);
    if (!snapped) return std::nullopt;
    check_valid(*snapped, t);
    check_on_grid(*snapped, t);
    return std::move(*snapped);
}

} // namespace

TEST_CASE("property: 10 000 random clip, vertex-move and subtract edits") {
    Rng rng(2025);
    Tally t;
    std::vector<Brush> pool;
    std::vector<DVec3> home;
    for (int i = 0; i < 8; ++i) {
        const DVec3 centre = kCentres[i % 2];
        auto b = random_brush(rng, centre);
        REQUIRE(b.ok());
        pool.push_back(std::move(*b));
        home.push_back(centre);
    }
    const int edits = ks::test::iterations(10000); // 2 500 in the sanitized build
    for (t.edits = 0; t.edits < edits; ++t.edits) {
        const std::size_t k = rng.below(static_cast<std::uint32_t>(pool.size()));
        auto next = edit(rng, pool[k], t);
        next ? ++t.accepted : ++t.refused;
        // Keep the pool from wearing down to slivers: a small or refused brush is replaced by a new one.
        if (next && next->volume() > 2.0)
            pool[k] = std::move(*next);
        else if (auto fresh = random_brush(rng, home[k]))
            pool[k] = std::move(*fresh);
    }
    MESSAGE("edits " << t.edits << ": accepted " << t.accepted << " (clip " << t.accepted_by_kind[0]
                     << ", move " << t.accepted_by_kind[1] << ", subtract " << t.accepted_by_kind[2]
                     << "), refused " << t.refused << "; worst grid distance " << t.worst_grid
                     << ", worst relative volume error " << t.worst_volume
                     << ", world planes remake the brush to " << t.worst_round_trip);
    CHECK(t.invalid == 0);
    CHECK(t.world_round_trip == 0);
    CHECK(t.off_grid == 0);
    CHECK(t.volume_errors == 0);
    CHECK(t.worst_grid <= 1e-9);
    // The edits must mostly do something, or the test proves little.
    CHECK(t.accepted > t.edits / 2);
}
