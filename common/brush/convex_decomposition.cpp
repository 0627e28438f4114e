#include "brush/convex_decomposition.h"

#include "brush/convex_hull.h"
#include "brush/plane.h"
#include "brush/solid_voxels.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>

namespace ks::brush {
namespace {

using Triangles = std::span<const std::array<std::uint32_t, 3>>;

// A part: a box of voxels and how far its hull is from convex.
struct Part {
    VoxelBox box;           // what the part is measured by
    DVec3 lo{0.0}, hi{0.0}; // the region of space it takes: its hull is the mesh clipped to this
    long long count = 0;    // solid voxels
    double hull = 0.0;      // its hull's volume, in voxels
    double gap = 0.0;       // (hull - count) / skin voxels: the hull's mean distance from the part, in voxels
    bool settled = false;   // convex enough, or no cut helps
    double excess() const { return hull - static_cast<double>(count); }
};

class Partition {
  public:
    Partition(const SolidVoxels& voxels) : voxels_(voxels) {}

    double hull_volume(const VoxelBox& box) {
        voxels_.hull_points(box, points_);
        Result<double> volume = convex_hull_volume(points_);
        // Voxel corners always span a volume; a refusal would be Qhull's own failure: count the voxels.
        return volume ? *volume : static_cast<double>(voxels_.solid_count(box));
    }

    Part measure(const VoxelBox& box) {
        Part part;
        part.box = voxels_.shrink(box);
        part.count = voxels_.solid_count(part.box);
        if (part.count == 0) return part;
        part.hull = hull_volume(part.box);
        const long long skin = std::max<long long>(voxels_.boundary_count(part.box), 1);
        part.gap = std::max(part.excess(), 0.0) / static_cast<double>(skin);
        return part;
    }

    // The two halves' hull volumes summed, for a cut of `box` at `position` on `axis`, plus the solid's
    // section at the cut (one voxel thick): where cuts leave the same hulls (a table's top or a leg first:
    // each alone saves nothing), the cut through the thinner neck wins; plus V-HACD's balance term (a share
    // of the difference between the halves' volumes), or a ring, which no single cut makes less hollow, is
    // shaved a voxel at a time instead of halved.
    static constexpr double kBalance = 0.05;
    double cut_cost(const VoxelBox& box, int axis, int position) {
        VoxelBox left = box, right = box, section = box;
        left.hi[axis] = position;
        right.lo[axis] = position;
        section.lo[axis] = position - 1;
        section.hi[axis] = position + 1;
        const double balance =
            std::abs(static_cast<double>(voxels_.solid_count(left) - voxels_.solid_count(right)));
        return hull_volume(voxels_.shrink(left)) + hull_volume(voxels_.shrink(right)) +
               0.5 * static_cast<double>(voxels_.solid_count(section)) + kBalance * balance;
    }

    // The best cut of the part: a coarse search of up to eight planes per axis, then the planes between the
    // best one's neighbours. nullopt when the part is one voxel thick on every axis.
    std::optional<std::pair<int, int>> best_cut(const VoxelBox& box) {
        constexpr int kCoarse = 16;
        double best = std::numeric_limits<double>::max();
        std::optional<std::pair<int, int>> cut;
        int best_step = 1;
        for (int axis = 0; axis < 3; ++axis) {
            const int n = box.size(axis);
            if (n < 2) continue;
            const int step = std::max(1, (n + kCoarse - 1) / kCoarse);
            for (int p = box.lo[axis] + step / 2 + (step == 1 ? 1 : 0); p < box.hi[axis]; p += step) {
                const double cost = cut_cost(box, axis, p);
                if (cost < best) best = cost, cut = {axis, p}, best_step = step;
            }
        }
        if (!cut || best_step == 1) return cut;
        const auto [axis, centre] = *cut;
        const int fine = std::max(1, best_step / 4);
        for (int p = std::max(box.lo[axis] + 1, centre - best_step + fine);
             p < std::min(box.hi[axis], centre + best_step); p += fine) {
            if (p == centre) continue;
            const double cost = cut_cost(box, axis, p);
            if (cost < best) best = cost, cut = {axis, p};
        }
        return cut;
    }

  private:
    const SolidVoxels& voxels_;
    std::vector<DVec3> points_;
};

// The triangle clipped to the box [lo, hi] (Sutherland-Hodgman against its six planes): its corners, in
// `out`.
void clip_triangle_to_box(const std::array<DVec3, 3>& triangle, const DVec3& lo, const DVec3& hi,
                          std::vector<DVec3>& out) {
    out.clear();
    std::vector<DVec3> polygon(triangle.begin(), triangle.end()), next;
    for (int axis = 0; axis < 3 && !polygon.empty(); ++axis)
        for (int side = 0; side < 2 && !polygon.empty(); ++side) {
            // Inside: x <= hi (side 0) or x >= lo (side 1), measured as a signed distance <= 0.
            auto distance = [&](const DVec3& p) {
                return side == 0 ? p[axis] - hi[axis] : lo[axis] - p[axis];
            };
            next.clear();
            for (std::size_t i = 0; i < polygon.size(); ++i) {
                const DVec3& a = polygon[i];
                const DVec3& b = polygon[(i + 1) % polygon.size()];
                const double da = distance(a), db = distance(b);
                if (da <= 0.0) next.push_back(a);
                if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0)) {
                    DVec3 crossing = a + (b - a) * (da / (da - db));
                    crossing[axis] = side == 0 ? hi[axis] : lo[axis]; // on the plane exactly
                    next.push_back(crossing);
                }
            }
            polygon.swap(next);
        }
    out = polygon;
}

// Whether the triangle's piece in the region lies in one of the region's sides with no solid of the region
// behind it: a neighbour's face or edge touching the side (a cut snapped onto a table leg's side meets the
// leg's face and the edges of its top). Such a piece bounds the neighbouring part, not this one; a face lying
// in the side belongs to the part its outward normal points away from, so whatever the winding exactly one
// of the two parts on a cut keeps it.
bool only_touches(const std::vector<DVec3>& piece, const std::array<DVec3, 3>& t, const DVec3& lo,
                  const DVec3& hi) {
    if (piece.empty()) return true;
    const DVec3 normal = glm::cross(t[1] - t[0], t[2] - t[0]);
    bool keep_in_side = false, in_a_side = false;
    for (int axis = 0; axis < 3; ++axis)
        for (const double side : {lo[axis], hi[axis]}) {
            const auto on_side = [&](const DVec3& p) { return p[axis] == side; };
            if (!std::all_of(piece.begin(), piece.end(), on_side)) continue;
            if (!std::all_of(t.begin(), t.end(), on_side))
                return true; // the triangle leaves through this side
            in_a_side = true;
            keep_in_side |= (side == hi[axis] ? normal[axis] : -normal[axis]) > 0.0;
        }
    return in_a_side && !keep_in_side;
}

// Sorts the points and drops repeats (Qhull's input, in a deterministic order).
void keep_each_once(std::vector<DVec3>& points) {
    std::sort(points.begin(), points.end(), [](const DVec3& a, const DVec3& b) {
        return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
    });
    points.erase(std::unique(points.begin(), points.end()), points.end());
}

// Whether `p` is inside the closed mesh: the parity of a ray's crossings (Möller-Trumbore), along a
// direction no modelled surface is likely to graze.
bool inside_by_parity(const DVec3& p, std::span<const DVec3> vertices, Triangles triangles) {
    const DVec3 direction = glm::normalize(DVec3(1.0, 0.7548776662466927, 0.5698402909980532));
    int crossings = 0;
    for (const auto& t : triangles) {
        const DVec3 a = vertices[t[0]], e1 = vertices[t[1]] - a, e2 = vertices[t[2]] - a;
        const DVec3 q = glm::cross(direction, e2);
        const double det = glm::dot(e1, q);
        if (std::abs(det) < 1e-300) continue;
        const DVec3 s = p - a;
        const double u = glm::dot(s, q) / det;
        if (u < 0.0 || u > 1.0) continue;
        const DVec3 r = glm::cross(s, e1);
        const double v = glm::dot(direction, r) / det;
        if (v < 0.0 || u + v > 1.0) continue;
        if (glm::dot(e2, r) / det > 0.0) ++crossings;
    }
    return crossings % 2 == 1;
}

// The hull points of one part: the mesh clipped to its box and the box corners inside the solid; the
// voxels' own hull points (in model space) when those span no volume or are too many.
std::vector<DVec3> part_points(const SolidVoxels& voxels, const Part& part, std::span<const DVec3> vertices,
                               Triangles triangles, std::span<const std::pair<DVec3, DVec3>> bounds) {
    const VoxelBox& box = part.box;
    const DVec3 lo = part.lo, hi = part.hi;
    const double margin = voxels.cell() * 1e-9;
    std::vector<DVec3> points, clipped;
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        const auto& [tmin, tmax] = bounds[i];
        if (glm::any(glm::greaterThan(tmin, hi + margin)) || glm::any(glm::lessThan(tmax, lo - margin)))
            continue;
        const auto& t = triangles[i];
        const std::array<DVec3, 3> corners{vertices[t[0]], vertices[t[1]], vertices[t[2]]};
        clip_triangle_to_box(corners, lo, hi, clipped);
        if (!only_touches(clipped, corners, lo, hi))
            points.insert(points.end(), clipped.begin(), clipped.end());
    }
    for (int corner = 0; corner < 8; ++corner) {
        DVec3 p, nudged; // the corner, and a point a hair inside the region from it
        for (int axis = 0; axis < 3; ++axis) {
            const bool high = (corner >> axis) & 1;
            p[axis] = high ? hi[axis] : lo[axis];
            nudged[axis] =
                p[axis] + (high ? -1.0 : 1.0) * std::min(voxels.cell() * 1e-3, (hi[axis] - lo[axis]) * 0.5);
        }
        const Voxel state = voxels.at_point(nudged);
        if (state == Voxel::Inside ||
            (state == Voxel::Surface && inside_by_parity(nudged, vertices, triangles)))
            points.push_back(p);
    }
    keep_each_once(points);
    if (points.size() <= kMaxHullPoints && convex_hull_volume(points)) return points;
    std::vector<DVec3> grid;
    voxels.hull_points(box, grid);
    for (DVec3& p : grid)
        p = voxels.corner({static_cast<int>(p.x), static_cast<int>(p.y), static_cast<int>(p.z)});
    return grid;
}

Result<void> check_input(std::span<const DVec3> vertices, Triangles triangles,
                         const DecompositionOptions& o) {
    if (triangles.empty())
        return Error("the mesh has no triangles", Location({}, 0, 0, "triangles"), "give a mesh with volume");
    if (triangles.size() > kMaxDecompositionTriangles)
        return Error(std::to_string(triangles.size()) + " triangles, more than " +
                         std::to_string(kMaxDecompositionTriangles),
                     Location({}, 0, 0, "triangles"), "simplify the mesh");
    if (o.max_hulls < 1 || o.max_hulls > kMaxDecompositionHulls || o.resolution < 8 ||
        o.resolution > kMaxDecompositionResolution || !(o.tolerance >= 0.0 && o.tolerance <= 1.0) ||
        !(o.max_excess >= 0.0 && o.max_excess <= 1.0))
        return Error("decomposition options out of range", Location({}, 0, 0, "options"),
                     "hulls 1.." + std::to_string(kMaxDecompositionHulls) + ", resolution 8.." +
                         std::to_string(kMaxDecompositionResolution) + ", tolerance and max_excess 0..1");
    for (std::size_t i = 0; i < vertices.size(); ++i)
        if (!is_finite(vertices[i]))
            return Error("vertex is not finite", Location({}, 0, 0, "vertices[" + std::to_string(i) + "]"),
                         "fix the model's vertices");
    for (std::size_t i = 0; i < triangles.size(); ++i)
        for (std::uint32_t v : triangles[i])
            if (v >= vertices.size())
                return Error("vertex index " + std::to_string(v) + " is out of range (" +
                                 std::to_string(vertices.size()) + " vertices)",
                             Location({}, 0, 0, "triangles[" + std::to_string(i) + "]"),
                             "fix the model's indices");
    return ok();
}

// Where a cut at the lattice plane `plane` goes: onto the mesh's nearest vertex coordinate within two voxels
// of it (the corner of an L, the top of a table's legs: a cut there leaves both parts convex), else the
// lattice plane; always strictly inside the part's region (lo, hi).
double snapped_cut(const std::vector<double>& coordinates, double plane, double cell, double lo, double hi) {
    double best = plane;
    double nearest = 2.0 * cell;
    auto it = std::lower_bound(coordinates.begin(), coordinates.end(), plane - nearest);
    for (; it != coordinates.end() && *it <= plane + 2.0 * cell; ++it)
        if (std::abs(*it - plane) < nearest && *it > lo && *it < hi)
            nearest = std::abs(*it - plane), best = *it;
    return std::clamp(best, std::nextafter(lo, hi), std::nextafter(hi, lo));
}

// Whether the triangles' corners span a volume: not all within a hair of one plane (the plane through the
// first corner, the corner farthest from it, and the one farthest from the line through both).
bool spans_volume(std::span<const DVec3> vertices, Triangles triangles) {
    const DVec3 a = vertices[triangles[0][0]];
    DVec3 b = a, c = a;
    for (const auto& t : triangles)
        for (std::uint32_t i : t)
            if (glm::length(vertices[i] - a) > glm::length(b - a)) b = vertices[i];
    const double size = glm::length(b - a);
    double widest = 0.0;
    for (const auto& t : triangles)
        for (std::uint32_t i : t)
            if (const double w = glm::length(glm::cross(b - a, vertices[i] - a)); w > widest)
                widest = w, c = vertices[i];
    const DVec3 normal = glm::cross(b - a, c - a);
    if (!(size > 0.0) || glm::length(normal) <= 1e-12 * size * size) return false;
    const DVec3 unit = glm::normalize(normal);
    for (const auto& t : triangles)
        for (std::uint32_t i : t)
            if (std::abs(glm::dot(vertices[i] - a, unit)) > 1e-9 * size) return true;
    return false;
}

// Every vertex coordinate on each axis, sorted, once: where cuts snap to.
std::array<std::vector<double>, 3> vertex_coordinates(std::span<const DVec3> vertices, Triangles triangles) {
    std::array<std::vector<double>, 3> coordinates;
    for (const auto& t : triangles)
        for (std::uint32_t i : t)
            for (int axis = 0; axis < 3; ++axis) coordinates[axis].push_back(vertices[i][axis]);
    for (std::vector<double>& c : coordinates) {
        std::sort(c.begin(), c.end());
        c.erase(std::unique(c.begin(), c.end()), c.end());
    }
    return coordinates;
}

// Phase one: the part whose hull exceeds its voxels the most is cut, while some part's mean gap is above
// the tolerance or its hull is more than `max_excess` empty, up to `limit` parts.
std::vector<Part> split(const SolidVoxels& voxels, const std::array<std::vector<double>, 3>& coordinates,
                        const DVec3& lo, const DVec3& hi, double tolerance, double max_excess, int limit) {
    Partition partition(voxels);
    std::vector<Part> parts{partition.measure(voxels.all())};
    parts[0].lo = lo;
    parts[0].hi = hi;
    while (static_cast<int>(parts.size()) < limit) {
        Part* worst = nullptr;
        for (Part& p : parts)
            if (!p.settled && (p.gap > tolerance || p.excess() > max_excess * p.hull) &&
                (!worst || p.excess() > worst->excess()))
                worst = &p;
        if (!worst) break;
        const std::optional<std::pair<int, int>> cut = partition.best_cut(worst->box);
        if (!cut) {
            worst->settled = true;
            continue;
        }
        const auto [axis, position] = *cut;
        VoxelBox left = worst->box, right = worst->box;
        left.hi[axis] = position;
        right.lo[axis] = position;
        std::array<int, 3> lattice{};
        lattice[axis] = position;
        const double plane = snapped_cut(coordinates[axis], voxels.corner(lattice)[axis], voxels.cell(),
                                         worst->lo[axis], worst->hi[axis]);
        Part low = partition.measure(left), high = partition.measure(right);
        low.lo = high.lo = worst->lo;
        low.hi = high.hi = worst->hi;
        low.hi[axis] = high.lo[axis] = plane;
        *worst = low;
        parts.push_back(high);
    }
    return parts;
}

// A hull as its corners and measures.
struct Piece {
    std::vector<DVec3> corners;
    double volume = 0.0;
    double area = 0.0;
    // What merges are priced by: the corners themselves when there are few; for a dense hull (a part of a
    // 100 000-triangle statue has thousands of corners) the hull of its corners snapped to a grid of
    // kProxyCells along its largest side, so that pricing every pair stays cheap.
    std::vector<DVec3> proxy;
    double proxy_volume = 0.0;
};

constexpr std::size_t kProxyCorners = 64;
constexpr double kProxyCells = 12.0;

void make_proxy(Piece& piece) {
    piece.proxy = piece.corners;
    piece.proxy_volume = piece.volume;
    if (piece.corners.size() <= kProxyCorners) return;
    DVec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (const DVec3& c : piece.corners) lo = glm::min(lo, c), hi = glm::max(hi, c);
    const DVec3 extent = hi - lo;
    const double step = std::max({extent.x, extent.y, extent.z}) / kProxyCells;
    std::vector<DVec3> snapped;
    for (const DVec3& c : piece.corners) snapped.push_back(lo + glm::round((c - lo) / step) * step);
    keep_each_once(snapped);
    Result<HullMeasure> measure = convex_hull_measure(snapped);
    if (!measure) return; // a thin piece may snap flat: it keeps its own corners
    piece.proxy.clear();
    for (int i : measure->corners) piece.proxy.push_back(snapped[static_cast<std::size_t>(i)]);
    piece.proxy_volume = measure->volume;
}

std::optional<Piece> piece_of(std::span<const DVec3> points) {
    Result<HullMeasure> measure = convex_hull_measure(points);
    if (!measure) return std::nullopt;
    Piece piece{{}, measure->volume, measure->area, {}, 0.0};
    for (int i : measure->corners) piece.corners.push_back(points[static_cast<std::size_t>(i)]);
    make_proxy(piece);
    return piece;
}

std::optional<Piece> merged(const Piece& a, const Piece& b) {
    std::vector<DVec3> points = a.corners;
    points.insert(points.end(), b.corners.begin(), b.corners.end());
    return piece_of(points);
}

// The volume of the hull of both pieces' proxies.
std::optional<double> merged_proxy_volume(const Piece& a, const Piece& b) {
    std::vector<DVec3> points = a.proxy;
    points.insert(points.end(), b.proxy.begin(), b.proxy.end());
    Result<double> volume = convex_hull_volume(points);
    return volume ? std::optional<double>(*volume) : std::nullopt;
}

// Phase two: the pair whose merged hull adds the least volume to the two hulls is merged while there are
// more than `cap` pieces, and any pair whose hulls make a convex whole anyway (added volume within
// `convex_share` of the merged hull's, either way: a table's top cut in two comes back together; hulls that
// overlap do not count as convex, or two halves of a ring would close it).
void merge(std::vector<Piece>& pieces, int cap, double convex_share) {
    const std::size_t n = pieces.size();
    struct Cost {
        double added = std::numeric_limits<double>::max();
        bool convex = false;
    };
    std::vector<std::vector<Cost>> costs(n, std::vector<Cost>(n));
    auto cost = [&](std::size_t i, std::size_t j) {
        const std::optional<double> volume = merged_proxy_volume(pieces[i], pieces[j]);
        if (!volume) return Cost{};
        const double added = *volume - pieces[i].proxy_volume - pieces[j].proxy_volume;
        return Cost{added, std::abs(added) <= convex_share * *volume};
    };
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j) costs[i][j] = cost(i, j);
    while (pieces.size() > 1) {
        std::size_t bi = 0, bj = 1;
        bool found = false;
        const bool forced = static_cast<int>(pieces.size()) > cap;
        for (std::size_t i = 0; i < pieces.size(); ++i)
            for (std::size_t j = i + 1; j < pieces.size(); ++j) {
                const Cost& c = costs[i][j];
                if ((forced || c.convex) && (!found || c.added < costs[bi][bj].added))
                    bi = i, bj = j, found = true;
            }
        if (!found) break;
        std::optional<Piece> m = merged(pieces[bi], pieces[bj]);
        if (!m) break;
        pieces[bi] = std::move(*m);
        pieces.erase(pieces.begin() + static_cast<std::ptrdiff_t>(bj));
        costs.erase(costs.begin() + static_cast<std::ptrdiff_t>(bj));
        for (auto& row : costs) row.erase(row.begin() + static_cast<std::ptrdiff_t>(bj));
        for (std::size_t k = 0; k < pieces.size(); ++k)
            if (k != bi) costs[std::min(k, bi)][std::max(k, bi)] = cost(std::min(k, bi), std::max(k, bi));
    }
}

// Several hulls whose volumes add up to more than one hull of them all (a ring in two pieces whose hulls
// overlap) are worse collision than that one hull, and more of it: one hull instead.
void one_hull_if_smaller(std::vector<Piece>& pieces) {
    if (pieces.size() < 2) return;
    std::vector<DVec3> all;
    double total = 0.0;
    for (const Piece& piece : pieces) {
        all.insert(all.end(), piece.corners.begin(), piece.corners.end());
        total += piece.volume;
    }
    std::optional<Piece> one = piece_of(all);
    if (one && one->volume <= total) pieces = {std::move(*one)};
}

} // namespace

Result<ConvexDecomposition> decompose_convex(std::span<const DVec3> vertices, Triangles triangles,
                                             const DecompositionOptions& options) {
    if (Result<void> input = check_input(vertices, triangles, options); !input) return input.error();
    if (!spans_volume(vertices, triangles))
        return Error("the mesh spans no volume: its corners lie in one plane", Location({}, 0, 0, "vertices"),
                     "give a mesh with volume (a flat model takes a box or no collision)");
    const SolidVoxels voxels(vertices, triangles, options.resolution);
    DVec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    std::vector<std::pair<DVec3, DVec3>> bounds;
    bounds.reserve(triangles.size());
    for (const auto& t : triangles) {
        bounds.emplace_back(glm::min(glm::min(vertices[t[0]], vertices[t[1]]), vertices[t[2]]),
                            glm::max(glm::max(vertices[t[0]], vertices[t[1]]), vertices[t[2]]));
        lo = glm::min(lo, bounds.back().first), hi = glm::max(hi, bounds.back().second);
    }
    const int limit = std::clamp(3 * options.max_hulls, 12, kMaxDecompositionParts);
    const std::vector<Part> parts = split(voxels, vertex_coordinates(vertices, triangles), lo, hi,
                                          options.tolerance * options.resolution, options.max_excess, limit);
    ConvexDecomposition out;
    out.parts = static_cast<int>(parts.size());
    std::vector<Piece> pieces;
    long long solid = 0;
    for (const Part& part : parts) {
        solid += part.count;
        if (std::optional<Piece> piece = piece_of(part_points(voxels, part, vertices, triangles, bounds)))
            pieces.push_back(std::move(*piece));
    }
    out.voxel_volume = static_cast<double>(solid) * std::pow(voxels.cell(), 3);
    if (pieces.empty())
        return Error("the mesh spans no volume: every part's hull is flat", Location({}, 0, 0, "vertices"),
                     "give a mesh with volume (a flat model takes a box or no collision)");
    merge(pieces, options.max_hulls, 1e-6);
    one_hull_if_smaller(pieces);
    for (Piece& piece : pieces) {
        out.hull_volume += piece.volume;
        out.hulls.push_back(std::move(piece.corners));
    }
    return out;
}

} // namespace ks::brush
