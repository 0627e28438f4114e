#pragma once
// The double-precision reference for ray casts: brute force over every shape, with its own slab and plane
// clipping code in double (independent of the float fast path), for the benchmark's error columns and the
// tests. Conventions match the fast path: a ray starting inside hits at 0; a ray lying exactly in a slab
// plane is inside on the min plane and outside on the max plane (half-open), so stacked boxes share a face
// without double hits.
#include "core/math.h"
#include "physics/shapes.h"

#include <cmath>
#include <limits>
#include <span>

namespace ks::physics::reference {

using DQuat = glm::dquat;

struct RefBox {
    DVec3 centre;
    DQuat rotation;
    DVec3 half;
};

// Distance to the box or -1.
inline double ray_box(const DVec3& origin, const DVec3& dir, const RefBox& b, double max_distance) {
    const DQuat inv = glm::conjugate(b.rotation);
    const DVec3 o = inv * (origin - b.centre), d = inv * dir;
    double tmin = -std::numeric_limits<double>::infinity(), tmax = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
        if (d[i] == 0.0) {
            if (!(o[i] >= -b.half[i] && o[i] < b.half[i])) return -1.0;
            continue;
        }
        double t0 = (-b.half[i] - o[i]) / d[i], t1 = (b.half[i] - o[i]) / d[i];
        if (t0 > t1) std::swap(t0, t1);
        tmin = std::max(tmin, t0);
        tmax = std::min(tmax, t1);
    }
    if (tmin > tmax || tmax <= 0.0 || tmin > max_distance) return -1.0;
    return std::max(tmin, 0.0);
}

// Clips the ray's parameter range [tmin, tmax] by one face plane of a convex solid, given the origin's signed
// distance to it and the plane normal's dot product with the direction. False when the ray runs parallel to
// the plane outside it (it misses the solid).
inline bool clip_by_plane(double distance, double normal_dot_dir, double& tmin, double& tmax) {
    if (normal_dot_dir == 0.0) return distance <= 0.0;
    const double t = -distance / normal_dot_dir;
    if (normal_dot_dir < 0.0)
        tmin = std::max(tmin, t);
    else
        tmax = std::min(tmax, t);
    return true;
}

// Convex polyhedron given by its float vertices and faces; planes recomputed here in double.
inline double ray_polyhedron(const DVec3& origin, const DVec3& dir, const Polyhedron& p, const DVec3& centre,
                             const DQuat& rotation, double max_distance) {
    const DQuat inv = glm::conjugate(rotation);
    const DVec3 o = inv * (origin - centre), d = inv * dir;
    double tmin = -std::numeric_limits<double>::infinity(), tmax = std::numeric_limits<double>::infinity();
    for (const auto& f : p.faces) {
        auto idx = p.face_indices(f);
        DVec3 n(0.0), c(0.0);
        for (std::size_t i = 0; i < idx.size(); ++i) {
            const DVec3 a(p.vertices[idx[i]]), b(p.vertices[idx[(i + 1) % idx.size()]]);
            n += DVec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
            c += a;
        }
        n = glm::normalize(n);
        c /= static_cast<double>(idx.size());
        if (!clip_by_plane(glm::dot(n, o - c), glm::dot(n, d), tmin, tmax)) return -1.0;
    }
    if (tmin > tmax || tmax <= 0.0 || tmin > max_distance) return -1.0;
    return std::max(tmin, 0.0);
}

// Distance from a point to the box (0 inside), in double.
inline double point_box_distance(const DVec3& p, const RefBox& b) {
    const DVec3 l = glm::abs(glm::conjugate(b.rotation) * (p - b.centre)) - b.half;
    return glm::length(glm::max(l, DVec3(0.0)));
}

// A disagreement between the float fast path and this reference is a "boundary" case when it disappears
// if the box grows or shrinks by `eps` (the ray passes within eps of an edge or a vertex: which side it is
// on is decided by float rounding of the inputs) and a real mismatch otherwise.
enum class Verdict { Match, Boundary, Mismatch };

inline RefBox grown(const RefBox& b, double by) {
    return {b.centre, b.rotation, glm::max(b.half + DVec3(by), DVec3(0.0))};
}

struct RefHit {
    double distance = -1.0;
    int index = -1;
};

inline RefHit closest(const DVec3& origin, const DVec3& dir, std::span<const RefBox> boxes,
                      double max_distance) {
    RefHit best;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const double t = ray_box(origin, dir, boxes[i], max_distance);
        if (t >= 0.0 && (best.index < 0 || t < best.distance)) best = {t, static_cast<int>(i)};
    }
    return best;
}

// Judges a fast-path closest hit (`fast_index` < 0: no hit) against the reference brute force.
inline Verdict judge(const DVec3& o, const DVec3& d, double max_distance, int fast_index,
                     double fast_distance, std::span<const RefBox> boxes, double eps = 1e-4) {
    const RefHit want = closest(o, d, boxes, max_distance);
    if (fast_index < 0 && want.index < 0) return Verdict::Match;
    if (fast_index >= 0 && want.index >= 0 && std::abs(fast_distance - want.distance) <= 1e-3)
        return Verdict::Match;
    // The fast path hit something the reference does not see there: fine if the hit point lies within eps of
    // that box, and nothing in the reference is clearly nearer.
    if (fast_index >= 0) {
        const DVec3 p = o + d * fast_distance;
        if (point_box_distance(p, boxes[fast_index]) > eps) return Verdict::Mismatch;
        // A nearer box in the reference counts against us only if the ray still enters it, clearly nearer,
        // when it shrinks by eps (a grazing ray moves its entry by eps / sin(angle)).
        if (want.index >= 0 && want.distance < fast_distance - 1e-3) {
            const double t = ray_box(o, d, grown(boxes[want.index], -eps), max_distance);
            if (t >= 0.0 && t < fast_distance - 1e-3) return Verdict::Mismatch;
        }
        return Verdict::Boundary;
    }
    // The fast path missed what the reference hits: fine only if the ray misses that box shrunk by eps.
    return ray_box(o, d, grown(boxes[want.index], -eps), max_distance) >= 0.0 ? Verdict::Mismatch
                                                                              : Verdict::Boundary;
}

} // namespace ks::physics::reference
