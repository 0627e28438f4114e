#pragma once
// Closed triangle meshes of known volume for the convex decomposition's tests and benchmark (an L, a table,
// an arch, a ring, a ball, a sliver), and its two error measures: how far the surface strays outside the
// hulls (should be none) and how much volume the hulls add to the solid.
#include "brush/brush.h"
#include "core/random.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace ks::brush::bench {

struct SolidMesh {
    std::vector<DVec3> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    double volume = 0.0; // exact, for the measures below
};

// A box's twelve triangles, wound outward.
inline void add_box(SolidMesh& m, const DVec3& lo, const DVec3& hi) {
    const auto base = static_cast<std::uint32_t>(m.vertices.size());
    for (int i = 0; i < 8; ++i)
        m.vertices.emplace_back(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
    const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    for (const auto& q : quads) {
        m.triangles.push_back({base + q[0], base + q[1], base + q[2]});
        m.triangles.push_back({base + q[0], base + q[2], base + q[3]});
    }
    const DVec3 size = hi - lo;
    m.volume += size.x * size.y * size.z;
}

// Boxes that do not overlap (they may touch): their union is the solid.
inline SolidMesh boxes(const std::vector<std::pair<DVec3, DVec3>>& list) {
    SolidMesh m;
    for (const auto& [lo, hi] : list) add_box(m, lo, hi);
    return m;
}

inline SolidMesh l_shape() {
    return boxes({{{0, 0, 0}, {4, 1, 1}}, {{0, 1, 0}, {1, 4, 1}}});
}

inline SolidMesh table() {
    std::vector<std::pair<DVec3, DVec3>> parts{{{0, 1.8, 0}, {3, 2, 2}}};
    for (double x : {0.0, 2.8})
        for (double z : {0.0, 1.8}) parts.push_back({{x, 0, z}, {x + 0.2, 1.8, z + 0.2}});
    return boxes(parts);
}

inline SolidMesh arch() {
    return boxes({{{0, 0, 0}, {1, 3, 1}}, {{3, 0, 0}, {4, 3, 1}}, {{0, 3, 0}, {4, 4, 1}}});
}

// A UV sphere (its volume is the polyhedron's, not the ball's).
inline SolidMesh ball(int rings, int segments, double radius) {
    SolidMesh m;
    for (int r = 0; r <= rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const double theta = std::numbers::pi * r / rings, phi = 2 * std::numbers::pi * s / segments;
            m.vertices.push_back(radius * DVec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                                                std::sin(theta) * std::sin(phi)));
        }
    auto at = [&](int r, int s) { return static_cast<std::uint32_t>(r * segments + (s % segments)); };
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            if (r > 0) m.triangles.push_back({at(r, s), at(r, s + 1), at(r + 1, s)});
            if (r + 1 < rings) m.triangles.push_back({at(r, s + 1), at(r + 1, s + 1), at(r + 1, s)});
        }
    return m;
}

// A torus about y: ring radius R, tube radius r.
inline SolidMesh ring(double big, double small, int around, int tube) {
    SolidMesh m;
    for (int i = 0; i < around; ++i)
        for (int j = 0; j < tube; ++j) {
            const double u = 2 * std::numbers::pi * i / around, v = 2 * std::numbers::pi * j / tube;
            const double d = big + small * std::cos(v);
            m.vertices.emplace_back(d * std::cos(u), small * std::sin(v), d * std::sin(u));
        }
    auto at = [&](int i, int j) { return static_cast<std::uint32_t>((i % around) * tube + (j % tube)); };
    for (int i = 0; i < around; ++i)
        for (int j = 0; j < tube; ++j) {
            m.triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j)});
            m.triangles.push_back({at(i + 1, j), at(i, j + 1), at(i + 1, j + 1)});
        }
    return m;
}

// The mesh as OBJ text (what a designer's exported file holds), vertices in full precision.
inline std::string obj_text(const SolidMesh& m) {
    std::ostringstream obj;
    obj.precision(17);
    for (const DVec3& v : m.vertices) obj << "v " << v.x << " " << v.y << " " << v.z << "\n";
    for (const auto& t : m.triangles) obj << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
    return obj.str();
}

// The volume the closed mesh encloses (divergence theorem), in long double.
inline double enclosed_volume(const SolidMesh& m) {
    long double sum = 0;
    for (const auto& t : m.triangles) {
        const DVec3 &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
        const DVec3 n = glm::cross(b, c);
        sum += (long double)a.x * n.x + (long double)a.y * n.y + (long double)a.z * n.z;
    }
    return static_cast<double>(sum / 6);
}

// The mesh turned by `rotation` and moved by `offset` (volume unchanged).
inline SolidMesh moved(SolidMesh m, const glm::dmat3& rotation, const DVec3& offset) {
    for (DVec3& v : m.vertices) v = rotation * v + offset;
    return m;
}

// Each hull as the planes of its faces (outward).
using HullPlanes = std::vector<std::vector<Plane>>;
inline HullPlanes planes_of(const std::vector<Brush>& hulls) {
    HullPlanes out;
    for (const Brush& h : hulls) {
        out.emplace_back();
        for (const Face& f : h.faces()) out.back().push_back(f.plane);
    }
    return out;
}

// The farthest that `samples` random points of the surface lie outside every hull (0 or less: all inside).
inline double surface_outside(const SolidMesh& m, const HullPlanes& hulls, int samples, Rng& rng) {
    double worst = -std::numeric_limits<double>::max();
    for (int i = 0; i < samples; ++i) {
        const auto& t = m.triangles[static_cast<std::size_t>(rng.next_u32() % m.triangles.size())];
        double u = rng.uniform_double(), v = rng.uniform_double();
        if (u + v > 1) u = 1 - u, v = 1 - v;
        const DVec3 p = m.vertices[t[0]] + u * (m.vertices[t[1]] - m.vertices[t[0]]) +
                        v * (m.vertices[t[2]] - m.vertices[t[0]]);
        double nearest = std::numeric_limits<double>::max();
        for (const std::vector<Plane>& h : hulls) {
            double outside = -std::numeric_limits<double>::max();
            for (const Plane& plane : h) outside = std::max(outside, plane.signed_distance(p));
            nearest = std::min(nearest, outside);
        }
        worst = std::max(worst, nearest);
    }
    return worst;
}
inline double surface_outside(const SolidMesh& m, const std::vector<Brush>& hulls, int samples, Rng& rng) {
    return surface_outside(m, planes_of(hulls), samples, rng);
}

} // namespace ks::brush::bench
