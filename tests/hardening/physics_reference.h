#pragma once
// Double-precision references for the physics property tests, written independently of common/physics:
// signed distances (negative inside) to the convex solids a scene has, a ray caster that works for any of
// them, exact segment distances, and a separating-axis search over polyhedra in double.
//
// The ray caster rests on one fact: the signed distance f(t) = sd(o + t·d) to a convex solid is a convex
// function of t. So the ray's minimum is found by ternary search, the ray misses iff that minimum is > 0,
// and the entry point is the first root, found by bisection on [0, t_min] where f decreases. No shape
// specific intersection formula is involved, so it shares no code (and no bug) with the fast path.
#include "core/math.h"
#include "physics/shapes.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace ks::test::physref {

using DQuat = glm::dquat;

inline DQuat to_double(const Quat& q) {
    return glm::normalize(DQuat(q.w, q.x, q.y, q.z));
}

// Signed distance to an oriented box (exact inside and outside).
inline double sd_box(const DVec3& p, const DVec3& centre, const DQuat& rotation, const DVec3& half) {
    const DVec3 q = glm::abs(glm::conjugate(rotation) * (p - centre)) - half;
    const double outside = glm::length(glm::max(q, DVec3(0.0)));
    const double inside = std::min(std::max(q.x, std::max(q.y, q.z)), 0.0);
    return outside + inside;
}

inline double point_segment_distance(const DVec3& p, const DVec3& a, const DVec3& b) {
    const DVec3 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + ab * t));
}

inline double sd_capsule(const DVec3& p, const DVec3& a, const DVec3& b, double radius) {
    return point_segment_distance(p, a, b) - radius;
}

// Upright (y axis) solid cylinder.
inline double sd_cylinder(const DVec3& p, const DVec3& centre, double radius, double half_height) {
    const double radial = std::hypot(p.x - centre.x, p.z - centre.z) - radius;
    const double vertical = std::abs(p.y - centre.y) - half_height;
    const double outside = std::hypot(std::max(radial, 0.0), std::max(vertical, 0.0));
    return outside + std::min(std::max(radial, vertical), 0.0);
}

// A convex polyhedron as planes in double (recomputed from its float vertices with Newell's method).
struct Planes {
    std::vector<DVec3> normals;
    std::vector<double> offsets;
    std::vector<DVec3> vertices; // world space, double
};

inline Planes planes_of(const physics::Polyhedron& poly, const DVec3& position, const DQuat& rotation) {
    Planes out;
    for (const Vec3& v : poly.vertices) out.vertices.push_back(position + rotation * DVec3(v));
    for (const auto& f : poly.faces) {
        auto idx = poly.face_indices(f);
        DVec3 n(0.0), c(0.0);
        for (std::size_t i = 0; i < idx.size(); ++i) {
            const DVec3 a = out.vertices[idx[i]], b = out.vertices[idx[(i + 1) % idx.size()]];
            n += DVec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
            c += a;
        }
        n = glm::normalize(n);
        c /= static_cast<double>(idx.size());
        out.normals.push_back(n);
        out.offsets.push_back(glm::dot(n, c));
    }
    return out;
}

// max over faces of the plane distance: 0 exactly on the surface, the true depth inside, a lower bound of
// the distance outside. Its zero set is the solid and it is convex, which is all the ray caster needs.
inline double sd_planes(const DVec3& p, const Planes& planes) {
    double d = -1e300;
    for (std::size_t i = 0; i < planes.normals.size(); ++i)
        d = std::max(d, glm::dot(planes.normals[i], p) - planes.offsets[i]);
    return d;
}

using Sdf = std::function<double(const DVec3&)>;

// Minimum of a convex function on [lo, hi] by ternary search (to ~1e-12 of the interval).
template <class F>
double argmin_convex(F&& f, double lo, double hi) {
    for (int i = 0; i < 200 && hi - lo > 1e-12 * (1.0 + std::abs(hi)); ++i) {
        const double m1 = lo + (hi - lo) / 3.0, m2 = hi - (hi - lo) / 3.0;
        if (f(m1) <= f(m2))
            hi = m2;
        else
            lo = m1;
    }
    return 0.5 * (lo + hi);
}

struct RayResult {
    bool hit = false;
    double distance = -1.0;
    double min_value = 0.0;   // min of the signed distance along the ray: near 0 means a grazing ray
    double start_value = 0.0; // signed distance at the origin: near 0 means the ray starts on the surface
};

inline RayResult cast(const Sdf& sd, const DVec3& origin, const DVec3& dir, double max_distance) {
    RayResult r;
    auto f = [&](double t) { return sd(origin + dir * t); };
    r.start_value = f(0.0);
    const double t_min = argmin_convex(f, 0.0, max_distance);
    r.min_value = std::min(f(t_min), r.start_value);
    if (r.start_value <= 0.0) {
        r.hit = true;
        r.distance = 0.0;
        return r;
    }
    if (f(t_min) > 0.0) return r;
    double lo = 0.0, hi = t_min; // f(lo) > 0 >= f(hi), f decreasing in between
    for (int i = 0; i < 200 && hi - lo > 1e-13 * (1.0 + hi); ++i) {
        const double mid = 0.5 * (lo + hi);
        (f(mid) > 0.0 ? lo : hi) = mid;
    }
    r.hit = true;
    r.distance = hi;
    return r;
}

// Distance between a segment and a convex solid given by its exact distance function (convex in the
// segment parameter), by ternary search; 0 or negative when the segment enters the solid.
inline double segment_distance(const Sdf& sd, const DVec3& a, const DVec3& b) {
    auto f = [&](double t) { return sd(a + (b - a) * t); };
    return f(argmin_convex(f, 0.0, 1.0));
}

// Separating-axis search in double over face normals and every edge cross product: the largest
// separation (> 0: apart by that much along the best axis; <= 0: overlapping, the minus minimal
// penetration). Face axes and edge axes are both exact for convex polyhedra.
struct Separation {
    double value = 0.0;
    DVec3 axis{0.0};
};

inline void project(const std::vector<DVec3>& vs, const DVec3& axis, double& lo, double& hi) {
    lo = 1e300;
    hi = -1e300;
    for (const DVec3& v : vs) {
        const double d = glm::dot(v, axis);
        lo = std::min(lo, d);
        hi = std::max(hi, d);
    }
}

inline std::vector<DVec3> edge_directions(const physics::Polyhedron& poly, const std::vector<DVec3>& world) {
    std::vector<DVec3> out;
    for (const auto& e : poly.edges) out.push_back(glm::normalize(world[e[1]] - world[e[0]]));
    return out;
}

inline Separation separation(const physics::Polyhedron& pa, const Planes& a, const physics::Polyhedron& pb,
                             const Planes& b) {
    Separation best{-1e300, DVec3(0.0)};
    auto consider = [&](DVec3 axis) {
        const double len = glm::length(axis);
        if (!(len > 1e-9)) return;
        axis /= len;
        double alo, ahi, blo, bhi;
        project(a.vertices, axis, alo, ahi);
        project(b.vertices, axis, blo, bhi);
        const double sep = std::max(blo - ahi, alo - bhi);
        if (sep > best.value) best = {sep, axis};
    };
    for (const DVec3& n : a.normals) consider(n);
    for (const DVec3& n : b.normals) consider(n);
    const auto ea = edge_directions(pa, a.vertices), eb = edge_directions(pb, b.vertices);
    for (const DVec3& u : ea)
        for (const DVec3& v : eb) consider(glm::cross(u, v));
    return best;
}

} // namespace ks::test::physref
