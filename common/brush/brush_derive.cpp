#include "brush/brush_derive.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <string>

namespace ks::brush {
namespace {

constexpr double kBaseHalfSize = 262144.0; // 2^18: every valid brush fits inside each base square
constexpr int kBaseEdge = -1;              // a winding edge still on the base square
constexpr double kMinPolishDeterminant = 1e-6;

struct WindingPoint {
    DVec3 p;
    int edge_plane; // the plane the edge from this point to the next lies on
};
using Winding = std::vector<WindingPoint>;

Winding base_winding(const Plane& plane) {
    const DVec3 n = plane.normal;
    const DVec3 a = std::abs(n.x) < std::abs(n.y)
                        ? (std::abs(n.x) < std::abs(n.z) ? DVec3(1, 0, 0) : DVec3(0, 0, 1))
                        : (std::abs(n.y) < std::abs(n.z) ? DVec3(0, 1, 0) : DVec3(0, 0, 1));
    const DVec3 u = glm::normalize(glm::cross(a, n)) * kBaseHalfSize;
    const DVec3 v = glm::cross(n, u); // u x v points along n: the corners below run counter-clockwise
    const DVec3 c = n * plane.distance;
    return {{c - u - v, kBaseEdge}, {c + u - v, kBaseEdge}, {c + u + v, kBaseEdge}, {c - u + v, kBaseEdge}};
}

enum Side { back, on, front };

Side side_of(double d) {
    return d > kOnPlaneEpsilon ? front : (d < -kOnPlaneEpsilon ? back : on);
}

// Keeps the part of `w` behind `plane` (index `j`); points within kOnPlaneEpsilon of it are kept as they
// are, so a plane through existing corners adds no new points.
void clip_winding(Winding& w, const Plane& plane, int j, Winding& out) {
    out.clear();
    const std::size_t n = w.size();
    std::vector<double> dist(n);
    bool any_front = false;
    for (std::size_t k = 0; k < n; ++k) {
        dist[k] = plane.signed_distance(w[k].p);
        any_front |= side_of(dist[k]) == front;
    }
    if (!any_front) return;
    for (std::size_t k = 0; k < n; ++k) {
        const WindingPoint& a = w[k];
        const WindingPoint& b = w[(k + 1) % n];
        const Side sa = side_of(dist[k]), sb = side_of(dist[(k + 1) % n]);
        if (sa != front) out.push_back({a.p, sa == on && sb == front ? j : a.edge_plane});
        if ((sa == back && sb == front) || (sa == front && sb == back)) {
            const double t = dist[k] / (dist[k] - dist[(k + 1) % n]);
            const DVec3 x = a.p + (b.p - a.p) * t;
            out.push_back({x, sa == back ? j : a.edge_plane});
        }
    }
    w.swap(out);
}

struct RawCorner {
    DVec3 p;
    int face, before, after; // the face's plane and the planes of the edges ending and starting here
};

// Groups corners closer than kWeldDistance: sorted along x, then a sweep; returns each corner's group.
std::vector<int> weld(const std::vector<RawCorner>& corners, double distance, int& groups) {
    std::vector<int> order(corners.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return corners[a].p.x < corners[b].p.x; });
    std::vector<int> group(corners.size(), -1);
    groups = 0;
    for (std::size_t i = 0; i < order.size(); ++i) {
        const int a = order[i];
        if (group[a] >= 0) continue;
        group[a] = groups;
        for (std::size_t k = i + 1; k < order.size(); ++k) {
            const int b = order[k];
            if (corners[b].p.x - corners[a].p.x > distance) break;
            if (group[b] < 0 && glm::length(corners[b].p - corners[a].p) <= distance) group[b] = groups;
        }
        ++groups;
    }
    return group;
}

// The point on the best-conditioned three of `candidates` (the pair with the largest cross product, then
// the third with the largest determinant), or nullopt when no three are independent.
std::optional<DVec3> best_intersection(const std::vector<Plane>& planes, std::vector<int> candidates) {
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    double best = -1.0;
    int a = -1, b = -1;
    for (std::size_t i = 0; i < candidates.size(); ++i)
        for (std::size_t k = i + 1; k < candidates.size(); ++k) {
            const double s =
                glm::length(glm::cross(planes[candidates[i]].normal, planes[candidates[k]].normal));
            if (s > best) best = s, a = candidates[i], b = candidates[k];
        }
    if (a < 0) return std::nullopt;
    const DVec3 ab = glm::cross(planes[a].normal, planes[b].normal);
    double best_det = -1.0;
    int c = -1;
    for (int k : candidates) {
        const double det = std::abs(glm::dot(ab, planes[k].normal));
        if (k != a && k != b && det > best_det) best_det = det, c = k;
    }
    if (c < 0) return std::nullopt;
    return intersect_planes(planes[a], planes[b], planes[c]);
}

// A corner recomputed from its three planes, taken in index order: the faces sharing a vertex of three
// planes compute it bit for bit alike, so welding it is exact. Where the three are so near parallel that
// their intersection is less precise than the clipped point (|det| below kMinPolishDeterminant: the
// intersection's rounding grows as 1/|det|), the clipped point is kept.
DVec3 polish_corner(const std::vector<Plane>& planes, const DVec3& clipped, int face, int before, int after) {
    int t[3] = {face, before, after};
    std::sort(t, t + 3);
    if (t[0] == t[1] || t[1] == t[2]) return clipped;
    const auto x = intersect_planes(planes[t[0]], planes[t[1]], planes[t[2]], kMinPolishDeterminant);
    return x ? *x : clipped;
}

double polygon_area(const std::vector<DVec3>& vertices, const std::vector<int>& polygon) {
    DVec3 sum(0.0);
    const DVec3 origin = vertices[polygon[0]];
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
        sum += glm::cross(vertices[polygon[k]] - origin, vertices[polygon[k + 1]] - origin);
    return 0.5 * glm::length(sum);
}

// Each directed edge once, and its reverse once: a closed, consistently oriented surface.
Result<void> check_closed(const std::vector<std::vector<int>>& polygons) {
    std::map<std::pair<int, int>, int> directed;
    for (std::size_t f = 0; f < polygons.size(); ++f)
        for (std::size_t k = 0; k < polygons[f].size(); ++k) {
            const auto e = std::pair{polygons[f][k], polygons[f][(k + 1) % polygons[f].size()]};
            if (++directed[e] > 1)
                return Error("faces meet in a degenerate way (an edge used twice)",
                             Location({}, 0, 0, "faces[" + std::to_string(f) + "]"),
                             "move planes apart so that no edge is shorter than 1e-8 units");
        }
    for (const auto& [e, count] : directed)
        if (!directed.count({e.second, e.first}))
            return Error("the faces do not close (an edge has one face only)", Location({}, 0, 0, "faces"),
                         "make sure the planes enclose a volume; no edge may be shorter than 1e-8 units");
    return ok();
}

// Welds the corners closer than `weld_distance`, places each vertex, and builds the polygons; refused when
// they do not close.
Result<DerivedGeometry> assemble(const std::vector<Plane>& planes, const std::vector<RawCorner>& corners,
                                 const std::vector<std::vector<int>>& face_corners, double weld_distance) {
    int groups = 0;
    const std::vector<int> group = weld(corners, weld_distance, groups);
    std::vector<std::vector<int>> group_planes(groups);
    std::vector<DVec3> group_sum(groups, DVec3(0.0));
    std::vector<int> group_count(groups, 0);
    for (std::size_t c = 0; c < corners.size(); ++c) {
        auto& gp = group_planes[group[c]];
        gp.insert(gp.end(), {corners[c].face, corners[c].before, corners[c].after});
        group_sum[group[c]] += corners[c].p;
        ++group_count[group[c]];
    }
    DerivedGeometry out;
    out.vertices.resize(groups);
    for (int g = 0; g < groups; ++g) {
        const auto polished = best_intersection(planes, group_planes[g]);
        out.vertices[g] = polished ? *polished : group_sum[g] / double(group_count[g]);
    }
    // Polygons over welded vertices, without repeats; a polygon of no area contributes no face.
    out.polygons.resize(planes.size());
    for (std::size_t i = 0; i < planes.size(); ++i) {
        std::vector<int>& poly = out.polygons[i];
        for (int c : face_corners[i])
            if (poly.empty() || poly.back() != group[c]) poly.push_back(group[c]);
        while (poly.size() > 1 && poly.front() == poly.back()) poly.pop_back();
        if (poly.size() < 3 || polygon_area(out.vertices, poly) <= 1e-14) poly.clear();
    }
    // Keep only the vertices some face uses, in first-use order.
    std::vector<int> remap(groups, -1);
    std::vector<DVec3> used;
    for (auto& poly : out.polygons)
        for (int& v : poly) {
            if (remap[v] < 0) remap[v] = static_cast<int>(used.size()), used.push_back(out.vertices[v]);
            v = remap[v];
        }
    out.vertices = std::move(used);
    if (auto closed = check_closed(out.polygons); !closed) return closed.error();
    return out;
}

} // namespace

Result<DerivedGeometry> derive_geometry(const std::vector<Plane>& planes) {
    const int n = static_cast<int>(planes.size());
    std::vector<RawCorner> corners;
    std::vector<std::vector<int>> face_corners(planes.size());
    Winding w, scratch;
    for (int i = 0; i < n; ++i) {
        w = base_winding(planes[i]);
        for (int j = 0; j < n && w.size() >= 3; ++j)
            if (j != i) clip_winding(w, planes[j], j, scratch);
        if (w.size() < 3) continue;
        for (std::size_t k = 0; k < w.size(); ++k)
            if (w[k].edge_plane == kBaseEdge)
                return Error("the brush is unbounded or reaches beyond +-" +
                                 std::to_string(int(kMaxCoordinate)) + " units: this face does not close",
                             Location({}, 0, 0, "faces[" + std::to_string(i) + "]"),
                             "add planes that close the brush, or keep it within the world");
        for (std::size_t k = 0; k < w.size(); ++k) {
            const int before = w[(k + w.size() - 1) % w.size()].edge_plane;
            face_corners[i].push_back(static_cast<int>(corners.size()));
            corners.push_back(
                {polish_corner(planes, w[k].p, i, before, w[k].edge_plane), i, before, w[k].edge_plane});
        }
    }
    // Where planes meet in a near-degenerate way (four nearly through one point, one of them nearly parallel
    // to another) the corners of one vertex can spread past the weld distance and leave the faces open:
    // welding again a little wider closes them, collapsing a feature below 1e-6 units.
    Result<DerivedGeometry> out = assemble(planes, corners, face_corners, kWeldDistance);
    for (double wider : {10 * kWeldDistance, 100 * kWeldDistance})
        if (!out) out = assemble(planes, corners, face_corners, wider);
    return out;
}

} // namespace ks::brush
