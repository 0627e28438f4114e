#include "brush/convex_hull.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

namespace ks::brush {
namespace {

// The plane through a face's points: the first point, the one farthest from it, and the one farthest from
// the line through both (the widest triangle found in linear time), facing along Qhull's outward normal.
std::optional<Plane> hull_face_plane(std::span<const DVec3> points, const std::vector<int>& on_face,
                                     const DVec3& outward) {
    const DVec3 a = points[on_face[0]];
    DVec3 b = a;
    for (int i : on_face)
        if (glm::length(points[i] - a) > glm::length(b - a)) b = points[i];
    const DVec3 ab = b - a;
    DVec3 c = a;
    double widest = -1.0;
    for (int i : on_face) {
        const double w = glm::length(glm::cross(ab, points[i] - a));
        if (w > widest) widest = w, c = points[i];
    }
    auto plane = plane_from_points(a, b, c);
    if (plane && glm::dot(plane->normal, outward) < 0) *plane = plane->flipped();
    return plane;
}

// Runs Qhull; its messages go to a memory stream so that a failure becomes an Error.
struct QhullRun {
    qhT qh_storage{};
    qhT* qh = &qh_storage;
    char* messages = nullptr;
    std::size_t message_size = 0;
    FILE* err = nullptr;
    int exit_code = 0;

    explicit QhullRun(std::vector<coordT>& coords) {
        err = open_memstream(&messages, &message_size);
        qh_zero(qh, err);
        // Pre-merge facets whose centrums lie within 1e-9 of their neighbours' planes: points that are one
        // face to brush precision (kOnPlaneEpsilon is 1e-8) make one face, not slivers of meaningless planes.
        char options[] = "qhull C-1e-9";
        exit_code = qh_new_qhull(qh, 3, static_cast<int>(coords.size() / 3), coords.data(), False, options,
                                 nullptr, err);
    }
    ~QhullRun() {
        int curlong = 0, totlong = 0;
        qh_freeqhull(qh, !qh_ALL);
        qh_memfreeshort(qh, &curlong, &totlong);
        if (err) std::fclose(err);
        std::free(messages);
    }
    QhullRun(const QhullRun&) = delete;
    QhullRun& operator=(const QhullRun&) = delete;
};

// The points as Qhull's coordinates, or the refusal convex_hull documents.
Result<std::vector<coordT>> hull_input(std::span<const DVec3> points) {
    if (points.size() < 4)
        return Error("a convex hull needs at least 4 points, got " + std::to_string(points.size()),
                     Location({}, 0, 0, "points"), "give points that span a volume");
    if (points.size() > kMaxHullPoints)
        return Error(std::to_string(points.size()) + " points are beyond the limit of " +
                         std::to_string(kMaxHullPoints),
                     Location({}, 0, 0, "points"), "give fewer points");
    std::vector<coordT> coords;
    coords.reserve(points.size() * 3);
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!is_finite(points[i]) || glm::any(glm::greaterThan(glm::abs(points[i]), DVec3(kMaxCoordinate))))
            return Error("the point is not finite or lies beyond +-65536",
                         Location({}, 0, 0, "points[" + std::to_string(i) + "]"), "give finite coordinates");
        coords.insert(coords.end(), {points[i].x, points[i].y, points[i].z});
    }
    return coords;
}

// Qhull's failure as an Error.
Error qhull_failure(QhullRun& run) {
    std::fflush(run.err);
    const std::string text = run.messages ? std::string(run.messages, run.message_size) : std::string();
    const bool flat = text.find("QH6154") != std::string::npos || text.find("flat") != std::string::npos ||
                      text.find("QH6214") != std::string::npos;
    return Error(flat ? "the points span no volume (they are coplanar, collinear or equal)"
                      : "Qhull failed: " + text.substr(0, text.find('\n')),
                 Location({}, 0, 0, "points"), "give at least 4 points that are not in one plane");
}

} // namespace

Result<HullMeasure> convex_hull_measure(std::span<const DVec3> points) {
    Result<std::vector<coordT>> coords = hull_input(points);
    if (!coords) return coords.error();
    QhullRun run(*coords);
    if (run.exit_code != 0) return qhull_failure(run);
    qhT* qh = run.qh;
    qh_getarea(qh, qh->facet_list);
    HullMeasure measure{static_cast<double>(qh->totvol), static_cast<double>(qh->totarea), {}};
    vertexT* vertex;
    FORALLvertices measure.corners.push_back(qh_pointid(qh, vertex->point));
    std::sort(measure.corners.begin(), measure.corners.end());
    return measure;
}

Result<double> convex_hull_volume(std::span<const DVec3> points) {
    Result<HullMeasure> measure = convex_hull_measure(points);
    if (!measure) return measure.error();
    return measure->volume;
}

Result<Hull> convex_hull(std::span<const DVec3> points) {
    Result<std::vector<coordT>> coords = hull_input(points);
    if (!coords) return coords.error();
    QhullRun run(*coords);
    if (run.exit_code != 0) return qhull_failure(run);
    qhT* qh = run.qh;
    Hull hull;
    std::vector<char> is_corner(points.size(), 0);
    facetT* facet;
    vertexT *vertex, **vertexp;
    FORALLfacets {
        HullFace face;
        FOREACHvertex_(facet->vertices) {
            const int id = qh_pointid(qh, vertex->point);
            face.points.push_back(id);
            is_corner[static_cast<std::size_t>(id)] = 1;
        }
        const DVec3 outward(facet->normal[0], facet->normal[1], facet->normal[2]);
        auto plane = hull_face_plane(points, face.points, outward);
        if (!plane) continue; // a sliver facet Qhull kept: its neighbours carry the surface
        face.plane = *plane;
        hull.faces.push_back(std::move(face));
    }
    for (std::size_t i = 0; i < points.size(); ++i)
        if (is_corner[i]) hull.corners.push_back(static_cast<int>(i));
    return hull;
}

} // namespace ks::brush
