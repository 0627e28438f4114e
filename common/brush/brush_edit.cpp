#include "brush/brush_edit.h"

#include "brush/brush_build.h"
#include "brush/convex_hull.h"
#include "brush/texture_mapping.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace ks::brush {
namespace {

// Rule (2): each old edge's endpoints still share a face of the hull.
Result<void> check_edges_kept(const Brush& brush, const Hull& hull) {
    std::vector<std::set<int>> faces_of(brush.vertices().size());
    for (std::size_t f = 0; f < hull.faces.size(); ++f)
        for (int p : hull.faces[f].points) faces_of[static_cast<std::size_t>(p)].insert(static_cast<int>(f));
    for (std::size_t e = 0; e < brush.edges().size(); ++e) {
        const Edge& edge = brush.edges()[e];
        const auto& a = faces_of[static_cast<std::size_t>(edge.v0)];
        const auto& b = faces_of[static_cast<std::size_t>(edge.v1)];
        if (std::none_of(a.begin(), a.end(), [&](int f) { return b.count(f) > 0; }))
            return Error("the move would turn the brush over: edge " + std::to_string(e) + " (vertices " +
                             std::to_string(edge.v0) + " and " + std::to_string(edge.v1) +
                             ") would cross the inside",
                         Location({}, 0, 0, "edges[" + std::to_string(e) + "]"),
                         "move the vertices a shorter way, in steps that keep the brush's shape");
    }
    return ok();
}

// Faces whose every vertex moved rigidly by `delta` keep their world mapping.
void lock_moved_faces(const Brush& before, const std::vector<bool>& moved, const DVec3& delta, Brush& after,
                      std::vector<Face>& faces) {
    for (std::size_t f = 0; f < before.faces().size(); ++f) {
        const auto& poly = before.polygons()[f];
        if (!std::all_of(poly.begin(), poly.end(), [&](int v) { return moved[static_cast<std::size_t>(v)]; }))
            continue;
        const int match = after.find_face(before.faces()[f].plane.translated(delta));
        if (match >= 0)
            faces[static_cast<std::size_t>(match)].attributes =
                locked_attributes(before.faces()[f], glm::dmat3(1.0), delta);
    }
}

} // namespace

Result<Brush> move_vertices(const Brush& brush, std::span<const int> vertex_indices, const DVec3& delta) {
    if (!is_finite(delta))
        return Error("the move is not finite", Location({}, 0, 0, "delta"), "give finite numbers");
    std::vector<bool> moved(brush.vertices().size(), false);
    for (int v : vertex_indices) {
        if (v < 0 || static_cast<std::size_t>(v) >= moved.size())
            return Error("there is no vertex " + std::to_string(v), Location({}, 0, 0, "vertices"),
                         "give indices below " + std::to_string(moved.size()));
        moved[static_cast<std::size_t>(v)] = true;
    }
    std::vector<DVec3> points = brush.vertices();
    for (std::size_t i = 0; i < points.size(); ++i)
        if (moved[i]) points[i] += delta;
    auto hull = convex_hull(points);
    if (!hull) return hull.error();
    if (hull->corners.size() != points.size()) {
        std::size_t lost = 0;
        while (lost < hull->corners.size() && hull->corners[lost] == static_cast<int>(lost)) ++lost;
        return Error("vertex " + std::to_string(lost) +
                         " would no longer be a corner (it would lie inside the brush, on a face or on "
                         "another vertex)",
                     Location({}, 0, 0, "vertices[" + std::to_string(lost) + "]"),
                     "move it less far, or move the vertices it would meet along with it");
    }
    if (auto kept = check_edges_kept(brush, *hull); !kept) return kept.error();
    const Brush* sources[] = {&brush};
    auto result = make_hull_of(points, sources, true);
    if (!result) return result.error();
    if (result->vertices().size() != points.size())
        return Error("the moved brush is degenerate (vertices closer than 1e-8 units)",
                     Location({}, 0, 0, "delta"), "move the vertices less far");
    for (std::size_t f = 0; f < brush.faces().size(); ++f) {
        const auto& poly = brush.polygons()[f];
        const bool still =
            std::none_of(poly.begin(), poly.end(), [&](int v) { return moved[static_cast<std::size_t>(v)]; });
        if (still && result->find_face(brush.faces()[f].plane) < 0)
            return Error("the move would push vertices through face " + std::to_string(f) +
                             ", turning the brush over",
                         Location({}, 0, 0, "faces[" + std::to_string(f) + "]"),
                         "move the vertices the other way, or less far");
    }
    std::vector<Face> faces = result->anchored_faces();
    lock_moved_faces(brush, moved, delta, *result, faces);
    return Brush::from_anchored_faces(result->anchor(), std::move(faces));
}

Result<Brush> move_edge(const Brush& brush, int edge_index, const DVec3& delta) {
    if (edge_index < 0 || static_cast<std::size_t>(edge_index) >= brush.edges().size())
        return Error("there is no edge " + std::to_string(edge_index), Location({}, 0, 0, "edges"),
                     "give an index below " + std::to_string(brush.edges().size()));
    const Edge& e = brush.edges()[static_cast<std::size_t>(edge_index)];
    const int ends[] = {e.v0, e.v1};
    return move_vertices(brush, ends, delta);
}

Result<Brush> move_face(const Brush& brush, int face_index, const DVec3& delta) {
    if (face_index < 0 || static_cast<std::size_t>(face_index) >= brush.faces().size())
        return Error("there is no face " + std::to_string(face_index), Location({}, 0, 0, "faces"),
                     "give an index below " + std::to_string(brush.faces().size()));
    return move_vertices(brush, brush.polygons()[static_cast<std::size_t>(face_index)], delta);
}

Result<Brush> add_vertex(const Brush& brush, const DVec3& point) {
    if (!is_finite(point))
        return Error("the new vertex is not finite", Location({}, 0, 0, "point"), "give finite numbers");
    const bool outside = std::any_of(brush.faces().begin(), brush.faces().end(), [&](const Face& f) {
        return f.plane.signed_distance(point) > kOnPlaneEpsilon;
    });
    if (!outside)
        return Error("the new vertex would lie inside the brush or on its surface",
                     Location({}, 0, 0, "point"), "drag it out of the brush");
    std::vector<DVec3> points = brush.vertices();
    points.push_back(point);
    const Brush* sources[] = {&brush};
    auto result = make_hull_of(points, sources, true);
    if (!result)
        return Error("the new vertex would swallow others (" + result.error().message + ")",
                     Location({}, 0, 0, "point"), "drag it less far out");
    return result;
}

Result<Brush> remove_vertices(const Brush& brush, std::span<const int> vertex_indices) {
    std::vector<bool> removed(brush.vertices().size(), false);
    for (int v : vertex_indices) {
        if (v < 0 || static_cast<std::size_t>(v) >= removed.size())
            return Error("there is no vertex " + std::to_string(v), Location({}, 0, 0, "vertices"),
                         "give indices below " + std::to_string(removed.size()));
        removed[static_cast<std::size_t>(v)] = true;
    }
    std::vector<DVec3> points;
    for (std::size_t i = 0; i < removed.size(); ++i)
        if (!removed[i]) points.push_back(brush.vertices()[i]);
    const Brush* sources[] = {&brush};
    auto result = make_hull_of(points, sources);
    if (!result)
        return Error("without those vertices the brush has no volume (" + result.error().message + ")",
                     Location({}, 0, 0, "vertices"), "keep at least four vertices that are not on one plane");
    return result;
}

Result<Brush> snap_to_grid(const Brush& brush, double grid) {
    if (!(grid > 0.0) || !std::isfinite(grid))
        return Error("the grid must be a positive number", Location({}, 0, 0, "grid"), "give a grid above 0");
    std::vector<DVec3> points;
    for (const DVec3& v : brush.vertices()) {
        const DVec3 p = glm::round(v / grid) * grid;
        if (std::find(points.begin(), points.end(), p) == points.end()) points.push_back(p);
    }
    const Brush* sources[] = {&brush};
    auto snapped = make_hull_of(points, sources);
    if (!snapped)
        return Error("snapped to a grid of " + std::to_string(grid) + " the brush has no volume (" +
                         snapped.error().message + ")",
                     Location({}, 0, 0, "grid"), "use a finer grid or make the brush larger");
    return snapped;
}

} // namespace ks::brush
