#include "brush/brush_build.h"

#include "brush/convex_hull.h"

#include <algorithm>
#include <cmath>

namespace ks::brush {
namespace {

Location point_location(std::size_t i) {
    return Location({}, 0, 0, "polygon[" + std::to_string(i) + "]");
}

// The polygon's unit normal (Newell's method, either winding), after checking it is planar and convex.
Result<DVec3> convex_polygon_normal(std::span<const DVec3> polygon) {
    if (polygon.size() < 3)
        return Error("a polygon needs at least 3 points, got " + std::to_string(polygon.size()),
                     Location({}, 0, 0, "polygon"), "give the corners of a convex polygon");
    if (polygon.size() > kMaxFaces - 2)
        return Error("the polygon has more corners than a brush may have faces",
                     Location({}, 0, 0, "polygon"), "give fewer corners");
    DVec3 newell(0.0);
    for (std::size_t k = 0; k < polygon.size(); ++k) {
        if (!is_finite(polygon[k]))
            return Error("the point is not finite", point_location(k), "give three finite numbers");
        const DVec3& a = polygon[k];
        const DVec3& b = polygon[(k + 1) % polygon.size()];
        newell += DVec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    if (!(glm::length(newell) > 0.0))
        return Error("the polygon has no area", Location({}, 0, 0, "polygon"),
                     "give a polygon that is not flat");
    const DVec3 n = glm::normalize(newell);
    for (std::size_t k = 0; k < polygon.size(); ++k) {
        if (std::abs(glm::dot(n, polygon[k] - polygon[0])) > 1e-7)
            return Error("the point is off the polygon's plane", point_location(k),
                         "put every corner in one plane");
        const DVec3& prev = polygon[(k + polygon.size() - 1) % polygon.size()];
        const DVec3& next = polygon[(k + 1) % polygon.size()];
        const DVec3 turn = glm::cross(polygon[k] - prev, next - polygon[k]);
        const double edges = glm::length(polygon[k] - prev) * glm::length(next - polygon[k]);
        if (!(glm::dot(turn, n) > 1e-12 * edges))
            return Error(
                "the polygon turns the wrong way or goes straight at this corner (not strictly convex)",
                point_location(k), "remove the corner or move it out to make the polygon convex");
    }
    return n;
}

} // namespace

Result<Brush> make_box(const DVec3& min, const DVec3& max, const FaceAttributes& attributes) {
    for (int a = 0; a < 3; ++a)
        if (!(min[a] < max[a]))
            return Error("the box's minimum is not below its maximum along axis " + std::string(1, "xyz"[a]),
                         Location({}, 0, 0,
                                  a == 0   ? "min.x"
                                  : a == 1 ? "min.y"
                                           : "min.z"),
                         "give min < max on every axis");
    std::vector<Face> faces;
    for (int a = 0; a < 3; ++a) {
        DVec3 n(0.0);
        n[a] = -1.0;
        faces.push_back({{n, -min[a]}, attributes});
        n[a] = 1.0;
        faces.push_back({{n, max[a]}, attributes});
    }
    return Brush::from_faces(std::move(faces));
}

Result<Brush> make_extrusion(std::span<const DVec3> polygon, const DVec3& direction,
                             const FaceAttributes& attributes) {
    auto normal = convex_polygon_normal(polygon);
    if (!normal) return normal.error();
    if (!is_finite(direction) || !(std::abs(glm::dot(*normal, direction)) > 1e-9 * glm::length(direction)))
        return Error("the direction is not finite or lies in the polygon's plane",
                     Location({}, 0, 0, "direction"), "give a direction leaving the polygon's plane");
    // The polygon's face looks away from the sweep; the swept copy looks along it.
    const DVec3 n = glm::dot(*normal, direction) > 0 ? *normal : -*normal;
    std::vector<Face> faces;
    faces.push_back({{-n, -glm::dot(n, polygon[0])}, attributes});
    faces.push_back({{n, glm::dot(n, polygon[0] + direction)}, attributes});
    DVec3 centre(0.0);
    for (const DVec3& p : polygon) centre += p;
    centre /= double(polygon.size());
    for (std::size_t k = 0; k < polygon.size(); ++k) {
        const DVec3& a = polygon[k];
        const DVec3& b = polygon[(k + 1) % polygon.size()];
        DVec3 side = glm::normalize(glm::cross(b - a, direction));
        if (glm::dot(side, a - centre) < 0) side = -side;
        faces.push_back({{side, glm::dot(side, a)}, attributes});
    }
    return Brush::from_faces(std::move(faces));
}

namespace {

// The points without near-duplicates (closer than kWeldDistance): two derivations of one vertex, e.g. the
// cut vertices of both halves of a split, would give Qhull a sliver facet with a meaningless plane.
std::vector<DVec3> welded_points(std::span<const DVec3> points) {
    std::vector<DVec3> sorted(points.begin(), points.end());
    std::sort(sorted.begin(), sorted.end(), [](const DVec3& a, const DVec3& b) { return a.x < b.x; });
    std::vector<DVec3> kept;
    for (const DVec3& p : sorted) {
        bool duplicate = false;
        for (auto it = kept.rbegin(); it != kept.rend() && p.x - it->x <= kWeldDistance && !duplicate; ++it)
            duplicate = glm::length(p - *it) <= kWeldDistance;
        if (!duplicate) kept.push_back(p);
    }
    return kept;
}

Result<void> check_points(std::span<const DVec3> points) {
    if (points.size() > kMaxHullPoints)
        return Error(std::to_string(points.size()) + " points are beyond the limit of " +
                         std::to_string(kMaxHullPoints),
                     Location({}, 0, 0, "points"), "give fewer points");
    for (std::size_t i = 0; i < points.size(); ++i)
        if (!is_finite(points[i]) || glm::any(glm::greaterThan(glm::abs(points[i]), DVec3(kMaxCoordinate))))
            return Error("the point is not finite or lies beyond +-65536",
                         Location({}, 0, 0, "points[" + std::to_string(i) + "]"), "give finite coordinates");
    return ok();
}

// The hull of `points` measured from a whole-number point near their mean (the brush's anchor): grid points
// minus a whole number are exact, and so are the planes through them.
Result<Hull> anchored_hull(std::span<const DVec3> points, DVec3& anchor) {
    DVec3 mean(0.0);
    for (const DVec3& p : points) mean += p / double(points.size());
    anchor = is_finite(mean) ? glm::round(mean) : DVec3(0.0);
    std::vector<DVec3> local(points.begin(), points.end());
    for (DVec3& p : local) p -= anchor;
    auto hull = convex_hull(local);
    if (!hull) return hull.error();
    return hull;
}

} // namespace

Result<Brush> make_from_points(std::span<const DVec3> points, const FaceAttributes& attributes) {
    if (auto checked = check_points(points); !checked) return checked.error();
    DVec3 anchor;
    auto hull = anchored_hull(welded_points(points), anchor);
    if (!hull) return hull.error();
    std::vector<Face> faces;
    for (const HullFace& f : hull->faces) faces.push_back({f.plane, attributes});
    return Brush::from_anchored_faces(anchor, std::move(faces), RedundantPlanes::drop);
}

Result<Brush> make_hull_of(std::span<const DVec3> points, std::span<const Brush* const> sources,
                           bool require_all_corners) {
    if (auto checked = check_points(points); !checked) return checked.error();
    const std::vector<DVec3> distinct = welded_points(points);
    DVec3 anchor;
    auto hull = anchored_hull(distinct, anchor);
    if (!hull) return hull.error();
    if (require_all_corners && (hull->corners.size() != points.size() || distinct.size() != points.size())) {
        std::size_t missing = 0;
        while (missing < hull->corners.size() && hull->corners[missing] == static_cast<int>(missing))
            ++missing;
        return Error(
            "vertex " + std::to_string(missing) +
                " would no longer be a corner (it would lie inside the brush, on a face or on another "
                "vertex)",
            Location({}, 0, 0, "vertices[" + std::to_string(missing) + "]"),
            "move it less far, or move the vertices it would meet along with it");
    }
    std::vector<Face> faces;
    for (const HullFace& f : hull->faces) {
        const Plane world = f.plane.translated(anchor);
        const Face* best = nullptr;
        double best_score = -1e300;
        for (const Brush* source : sources)
            for (const Face& candidate : source->faces()) {
                // Same plane first (a large bonus), then the most parallel, then the nearest.
                const double dot = glm::dot(candidate.plane.normal, world.normal);
                const double gap = std::abs(candidate.plane.distance - world.distance);
                const bool same = same_plane(candidate.plane, world);
                const double score = (same ? 10.0 : 0.0) + dot - 1e-9 * gap;
                if (score > best_score) best_score = score, best = &candidate;
            }
        faces.push_back({f.plane, best ? best->attributes : FaceAttributes{}});
    }
    return Brush::from_anchored_faces(anchor, std::move(faces), RedundantPlanes::drop);
}

} // namespace ks::brush
