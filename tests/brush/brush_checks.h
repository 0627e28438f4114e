#pragma once
// An independent audit of a brush for the tests: recomputes from its derived vertices and polygons, without
// the module's derivation, whether it is a closed convex polyhedron on its own planes.
#include "brush/brush.h"
#include "core/random.h"

#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <string>

namespace ks::brush_test {
using namespace ks::brush;

// Empty when the brush is valid; else what is wrong.
inline std::string audit(const Brush& b, double tolerance = 1e-7) {
    const auto& v = b.vertices();
    const auto& polys = b.polygons();
    if (b.faces().size() < 4 || polys.size() != b.faces().size()) return "fewer than 4 faces";
    if (v.size() < 4) return "fewer than 4 vertices";
    std::map<std::pair<int, int>, int> directed;
    for (std::size_t f = 0; f < polys.size(); ++f) {
        if (polys[f].size() < 3) return "face " + std::to_string(f) + " has fewer than 3 vertices";
        for (std::size_t k = 0; k < polys[f].size(); ++k) {
            const int a = polys[f][k], c = polys[f][(k + 1) % polys[f].size()];
            if (std::abs(b.faces()[f].plane.signed_distance(v[a])) > tolerance)
                return "vertex off its face's plane by " +
                       std::to_string(b.faces()[f].plane.signed_distance(v[a]));
            ++directed[{a, c}];
        }
    }
    for (const auto& [e, n] : directed)
        if (n != 1 || directed.count({e.second, e.first}) != 1) return "not a closed oriented surface";
    const long long euler = static_cast<long long>(v.size()) - static_cast<long long>(directed.size() / 2) +
                            static_cast<long long>(polys.size());
    if (euler != 2) return "Euler characteristic " + std::to_string(euler);
    for (const DVec3& p : v)
        for (const Face& f : b.faces())
            if (f.plane.signed_distance(p) > tolerance)
                return "a vertex is outside a face plane (not convex)";
    for (const DVec3& p : v)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return "non-finite vertex";
    if (!(polyhedron_volume(v, polys) > 0)) return "no volume";
    return {};
}

// A random unit vector (rejection sampling in the unit ball, away from its centre).
inline DVec3 random_unit(Rng& rng) {
    for (;;) {
        const DVec3 v(rng.uniform_double() * 2 - 1, rng.uniform_double() * 2 - 1,
                      rng.uniform_double() * 2 - 1);
        const double l = glm::length(v);
        if (l > 0.1 && l <= 1.0) return v / l;
    }
}

inline double grid_distance(const Brush& b, double grid) {
    double worst = 0;
    for (const DVec3& p : b.vertices())
        for (int a = 0; a < 3; ++a) worst = std::max(worst, std::abs(p[a] - std::round(p[a] / grid) * grid));
    return worst;
}

inline bool has_vertex(const Brush& b, const DVec3& p, double tolerance = 1e-9) {
    for (const DVec3& v : b.vertices())
        if (glm::length(v - p) <= tolerance) return true;
    return false;
}

} // namespace ks::brush_test
