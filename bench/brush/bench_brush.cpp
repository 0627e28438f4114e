// ks_bench brush: each convex-brush operation's cost (µs per brush, this thread's CPU time) against its
// error, on random brushes near the origin and near (9000, -9000, 5000): deriving vertices from planes
// against Qhull on the same vertices (the baseline, in the same run), clip, vertex move, subtract,
// intersect, merge, hollow, snap, a texture-locked turn and a level's placement (derived again or carried).
// Errors: the largest distance of a vertex from the planes of its faces (long double), volume conservation,
// distance from the grid, texture coordinate drift. Writes docs/bench/brush_ops.csv; --quick runs fewer
// brushes and leaves it alone.
#include "bench_registry.h"
#include "brush/brush_error.h"
#include "physics/bench_util.h"

#include "brush/brush_build.h"
#include "brush/brush_clip.h"
#include "brush/brush_csg.h"
#include "brush/brush_edit.h"
#include "brush/convex_hull.h"
#include "brush/texture_mapping.h"
#include "core/random.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace ks::brush::bench {
namespace {

using physics::bench::cpu_seconds;
using physics::bench::fmt;

constexpr double kGrid = 0.125;

struct Row {
    std::string where, operation;
    double us = 0;
    double off_plane = 0, volume = 0, grid = 0, texture = 0;
    int done = 0, refused = 0;
    long pieces = 0; // subtract and hollow: the fragments made
};

DVec3 random_unit(Rng& rng) {
    for (;;) {
        const DVec3 v(rng.uniform_double() * 2 - 1, rng.uniform_double() * 2 - 1,
                      rng.uniform_double() * 2 - 1);
        if (glm::length(v) > 0.1 && glm::length(v) <= 1.0) return glm::normalize(v);
    }
}

// A grid box 1..6 units a side, turned at random about its centre and snapped: slanted faces, grid vertices.
std::optional<Brush> random_brush(Rng& rng, const DVec3& centre) {
    const DVec3 half(kGrid * (4 + rng.below(20)), kGrid * (4 + rng.below(20)), kGrid * (4 + rng.below(20)));
    auto box = make_box(centre - half, centre + half);
    if (!box) return std::nullopt;
    const glm::dmat3 turn = glm::mat3_cast(glm::angleAxis(rng.uniform_double() * 6.28, random_unit(rng)));
    auto turned = transformed(*box, turn, centre - turn * centre);
    if (!turned) return std::nullopt;
    auto snapped = snap_to_grid(*turned, kGrid);
    if (!snapped) return std::nullopt;
    return std::move(*snapped);
}

double grid_distance(const Brush& b) {
    double worst = 0;
    for (const DVec3& p : b.vertices())
        for (int a = 0; a < 3; ++a)
            worst = std::max(worst, std::abs(p[a] - std::round(p[a] / kGrid) * kGrid));
    return worst;
}

// Times `op` over every brush (best of `reps` passes), then runs it once more to measure its error.
Row measure(const std::string& where, const std::string& name, const std::vector<Brush>& brushes, int reps,
            const std::function<bool(const Brush&, std::size_t, Row*)>& op) {
    Row row{where, name};
    double best = 1e300;
    for (int r = 0; r < reps; ++r) {
        const double t0 = cpu_seconds();
        for (std::size_t i = 0; i < brushes.size(); ++i) op(brushes[i], i, nullptr);
        best = std::min(best, cpu_seconds() - t0);
    }
    row.us = best * 1e6 / double(brushes.size());
    for (std::size_t i = 0; i < brushes.size(); ++i) (op(brushes[i], i, &row) ? row.done : row.refused)++;
    return row;
}

// The brushes and, per brush, a plane through it, a cutter over it and a grid step.
struct Inputs {
    std::vector<Brush> brushes;
    std::vector<Plane> cuts;
    std::vector<Brush> cutters;
    std::vector<DVec3> steps;
};

Inputs make_inputs(const DVec3& centre, int count) {
    Rng rng(7);
    Inputs in;
    while (static_cast<int>(in.brushes.size()) < count)
        if (auto b = random_brush(rng, centre)) in.brushes.push_back(std::move(*b));
    for (const Brush& b : in.brushes) {
        const DVec3 n = random_unit(rng);
        in.cuts.push_back({n, glm::dot(n, b.vertex_centre() + random_unit(rng) * 0.5)});
        auto c = random_brush(rng, b.vertex_centre() + random_unit(rng) * 2.0);
        in.cutters.push_back(c ? *c : b);
        in.steps.push_back(DVec3(kGrid * (int(rng.below(9)) - 4), kGrid * (int(rng.below(9)) - 4), kGrid));
    }
    return in;
}

// Deriving (against Qhull), splitting and moving a vertex.
void measure_edits(const std::string& where, const Inputs& in, int reps, std::vector<Row>& rows) {
    const auto& brushes = in.brushes;
    const auto& cuts = in.cuts;
    const auto& steps = in.steps;
    rows.push_back(
        measure(where, "derive from planes", brushes, reps, [](const Brush& b, std::size_t, Row* row) {
            auto again = Brush::from_anchored_faces(b.anchor(), b.anchored_faces());
            if (again && row)
                row->off_plane = std::max(row->off_plane, off_plane(*again)),
                row->grid = std::max(row->grid, grid_distance(*again));
            return again.ok();
        }));
    rows.push_back(measure(where, "baseline: Qhull on the same vertices", brushes, reps,
                           [](const Brush& b, std::size_t, Row* row) {
                               auto hull = convex_hull(b.vertices());
                               if (hull && row)
                                   for (const HullFace& f : hull->faces)
                                       for (int p : f.points)
                                           row->off_plane =
                                               std::max(row->off_plane,
                                                        std::abs(f.plane.signed_distance(b.vertices()[p])));
                               return hull.ok();
                           }));
    rows.push_back(measure(
        where, "split by a plane (both sides)", brushes, reps, [&](const Brush& b, std::size_t i, Row* row) {
            auto s = split(b, cuts[i]);
            if (s && row) {
                double v = 0;
                for (const auto* part : {&s->back, &s->front})
                    if (*part)
                        v += (*part)->volume(), row->off_plane = std::max(row->off_plane, off_plane(**part));
                row->volume = std::max(row->volume, std::abs(v - b.volume()) / b.volume());
            }
            return s.ok();
        }));
    rows.push_back(measure(where, "move a vertex (grid step)", brushes, reps,
                           [&](const Brush& b, std::size_t i, Row* row) {
                               const int v[] = {static_cast<int>(i % b.vertices().size())};
                               auto m = move_vertices(b, v, steps[i]);
                               if (m && row)
                                   row->off_plane = std::max(row->off_plane, off_plane(*m)),
                                   row->grid = std::max(row->grid, grid_distance(*m));
                               return m.ok();
                           }));
}

// Subtract (greedy against listed order), intersect, merge, hollow, snapping and texture lock.
void measure_csg_and_turns(const std::string& where, const Inputs& in, int reps, std::vector<Row>& rows) {
    const auto& brushes = in.brushes;
    const auto& cuts = in.cuts;
    const auto& cutters = in.cutters;
    for (auto [name, order] : {std::pair{"subtract A - B (largest cut first)", CutOrder::largest_first},
                               std::pair{"baseline: subtract, planes as listed", CutOrder::in_order}})
        rows.push_back(
            measure(where, name, brushes, reps, [&, order](const Brush& b, std::size_t i, Row* row) {
                auto r = subtract(b, cutters[i], order);
                if (r && row) {
                    double v = r->removed ? r->removed->volume() : 0.0;
                    for (const Brush& f : r->fragments)
                        v += f.volume(), row->off_plane = std::max(row->off_plane, off_plane(f));
                    row->volume = std::max(row->volume, std::abs(v - b.volume()) / b.volume());
                    row->pieces += static_cast<long>(r->fragments.size());
                }
                return r.ok();
            }));
    rows.push_back(
        measure(where, "intersect A n B", brushes, reps, [&](const Brush& b, std::size_t i, Row* row) {
            auto r = intersect(b, cutters[i]);
            if (r && row) row->off_plane = std::max(row->off_plane, off_plane(*r));
            return r.ok();
        }));
    rows.push_back(measure(
        where, "merge the halves of a split", brushes, reps, [&](const Brush& b, std::size_t i, Row* row) {
            auto s = split(b, cuts[i]);
            if (!s || !s->back || !s->front) return false;
            auto m = merge(*s->back, *s->front);
            if (m && row)
                row->off_plane = std::max(row->off_plane, off_plane(*m)),
                row->volume = std::max(row->volume, std::abs(m->volume() - b.volume()) / b.volume()),
                row->grid = std::max(row->grid, grid_distance(*m));
            return m.ok();
        }));
    rows.push_back(
        measure(where, "hollow (walls 0.25)", brushes, reps, [&](const Brush& b, std::size_t, Row* row) {
            auto walls = hollow(b, 0.25);
            if (walls && row) {
                std::vector<Face> inner = b.anchored_faces();
                for (Face& f : inner) f.plane.distance -= 0.25;
                auto inside = Brush::from_anchored_faces(b.anchor(), inner, RedundantPlanes::drop);
                double v = inside ? inside->volume() : 0.0;
                for (const Brush& w : *walls)
                    v += w.volume(), row->off_plane = std::max(row->off_plane, off_plane(w));
                row->volume = std::max(row->volume, std::abs(v - b.volume()) / b.volume());
                row->pieces += static_cast<long>(walls->size());
            }
            return walls.ok();
        }));
    rows.push_back(measure(
        where, "turn 37 deg + snap to grid", brushes, reps, [&](const Brush& b, std::size_t, Row* row) {
            const glm::dmat3 turn = glm::mat3_cast(glm::angleAxis(0.6458, glm::normalize(DVec3(1, 2, 3))));
            auto t = transformed(b, turn, b.vertex_centre() - turn * b.vertex_centre());
            if (!t) return false;
            auto s = snap_to_grid(*t, kGrid);
            if (s && row)
                row->off_plane = std::max(row->off_plane, off_plane(*s)),
                row->grid = std::max(row->grid, grid_distance(*s));
            return s.ok();
        }));
    rows.push_back(
        measure(where, "turn with texture lock", brushes, reps, [&](const Brush& b, std::size_t, Row* row) {
            const glm::dmat3 turn = glm::mat3_cast(glm::angleAxis(0.6458, glm::normalize(DVec3(1, 2, 3))));
            const DVec3 t = b.vertex_centre() - turn * b.vertex_centre();
            auto moved = transformed(b, turn, t);
            if (moved && row)
                for (std::size_t f = 0; f < b.faces().size(); ++f) {
                    const DVec3 p = b.vertices()[b.polygons()[f][0]];
                    const glm::dvec2 before = texture_coordinates(b.faces()[f], p);
                    const glm::dvec2 after = texture_coordinates(moved->faces()[f], turn * p + t);
                    row->texture = std::max(row->texture, glm::length(before - after));
                }
            return moved.ok();
        }));
}

// A level's brush entity placed in the world (turned about y by a yaw, moved): deriving again after the
// motion (transformed) against carrying the derived geometry through it (placed), same faces; the carried
// row's off-plane error is the vertices' distance from the moved planes.
void measure_placement(const std::string& where, const Inputs& in, int reps, std::vector<Row>& rows) {
    const glm::dmat3 yaw = glm::mat3_cast(glm::angleAxis(0.6458, DVec3(0, 1, 0)));
    const DVec3 offset(160, 0, -96);
    const auto place = [&](bool carry) {
        return [&, carry](const Brush& b, std::size_t, Row* row) {
            auto moved = carry ? placed(b, yaw, offset) : transformed(b, yaw, offset);
            if (moved && row) row->off_plane = std::max(row->off_plane, off_plane(*moved));
            return moved.ok();
        };
    };
    rows.push_back(measure(where, "place: derive again (transformed)", in.brushes, reps, place(false)));
    rows.push_back(measure(where, "place: carry geometry (placed)", in.brushes, reps, place(true)));
}

std::vector<Row> run_set(const std::string& where, const DVec3& centre, int count, int reps) {
    const Inputs in = make_inputs(centre, count);
    std::vector<Row> rows;
    measure_edits(where, in, reps, rows);
    measure_csg_and_turns(where, in, reps, rows);
    measure_placement(where, in, reps, rows);
    return rows;
}

int run(int argc, const char* const* argv) {
    const std::optional<bool> quick_given = ks::bench::quick_option(argc, argv);
    if (!quick_given) return 2;
    const bool quick = *quick_given;
    const int count = quick ? 100 : 1000, reps = quick ? 1 : 3;
    std::printf("load average %s; %d random snapped brushes (grid %g) per place, best of %d passes\n\n",
                physics::bench::load_average().c_str(), count, kGrid, reps);
    std::printf("%-6s %-36s %9s %10s %10s %10s %10s %9s %7s\n", "where", "operation", "µs/brush", "off-plane",
                "rel. vol.", "off-grid", "texture", "refused", "pieces");
    std::vector<std::string> csv;
    for (auto [where, centre] :
         {std::pair{"origin", DVec3(0.0)}, std::pair{"far", DVec3(9000, -9000, 5000)}}) {
        for (const Row& r : run_set(where, centre, count, reps)) {
            std::printf("%-6s %-36s %9.2f %10.3g %10.3g %10.3g %10.3g %4d/%-4d %7ld\n", r.where.c_str(),
                        r.operation.c_str(), r.us, r.off_plane, r.volume, r.grid, r.texture, r.refused,
                        r.refused + r.done, r.pieces);
            csv.push_back(r.where + "," + r.operation + "," + fmt("%.3f", r.us) + "," +
                          fmt("%.3g", r.off_plane) + "," + fmt("%.3g", r.volume) + "," + fmt("%.3g", r.grid) +
                          "," + fmt("%.3g", r.texture) + "," + std::to_string(r.refused) + "," +
                          std::to_string(r.refused + r.done) + "," + std::to_string(r.pieces));
        }
    }
    if (quick) {
        std::printf("\n--quick: docs/bench/brush_ops.csv left as it is\n");
        return 0;
    }
    physics::bench::write_csv("brush_ops",
                              "where,operation,us_per_brush,max_off_plane,max_rel_volume_error,max_off_grid,"
                              "max_texture_drift,refused,brushes,pieces",
                              csv);
    return 0;
}

const ks::bench::Registrar registrar({"brush", "convex brush operations: µs per brush against error", run});

} // namespace
} // namespace ks::brush::bench
