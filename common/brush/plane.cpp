#include "brush/plane.h"

#include <algorithm>
#include <cmath>

namespace ks::brush {

bool is_finite(const DVec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::optional<Plane> plane_from_points(const DVec3& a, const DVec3& b, const DVec3& c) {
    // The cross product of the two edges meeting at the vertex opposite the longest edge: the shortest
    // operands, so the least cancellation.
    const DVec3 ab = b - a, bc = c - b, ca = a - c;
    const double lab = glm::dot(ab, ab), lbc = glm::dot(bc, bc), lca = glm::dot(ca, ca);
    DVec3 n;
    if (lab >= lbc && lab >= lca)
        n = glm::cross(bc, ca); // ab is the longest: the edges at c
    else if (lbc >= lca)
        n = glm::cross(ca, ab);
    else
        n = glm::cross(ab, bc);
    const double len = glm::length(n);
    if (!(len > 0.0) || !std::isfinite(len)) return std::nullopt;
    // Collinear within rounding: the area is tiny against the edges' lengths.
    if (len <= 1e-14 * std::max({lab, lbc, lca})) return std::nullopt;
    n /= len;
    // The distance is averaged over the three points so none of them is favoured.
    const double d = (glm::dot(n, a) + glm::dot(n, b) + glm::dot(n, c)) / 3.0;
    return Plane{n, d};
}

std::optional<DVec3> intersect_planes(const Plane& a, const Plane& b, const Plane& c, double min_det) {
    const DVec3 bc = glm::cross(b.normal, c.normal);
    const double det = glm::dot(a.normal, bc);
    if (!(std::abs(det) >= min_det)) return std::nullopt;
    const DVec3 ca = glm::cross(c.normal, a.normal), ab = glm::cross(a.normal, b.normal);
    return (a.distance * bc + b.distance * ca + c.distance * ab) / det;
}

} // namespace ks::brush
