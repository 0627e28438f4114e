#pragma once
// The double-precision reference for brush collision: the ray clipped by the brush's own planes (world
// planes, double) and the distance from a segment to the brush (its vertices and ordered polygons), written
// independently of physics' float polyhedron paths, for the brush tests' and the benchmark's error columns.
// Conventions match ray_reference.h: a ray starting inside hits at 0; touching counts.
#include "brush/brush.h"
#include "ray_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ks::physics::reference {

// Distance along the ray (unit `dir`) to where it enters the brush with every plane moved outward by
// `grow` (negative: inward), or -1.
inline double ray_brush(const DVec3& origin, const DVec3& dir, const brush::Brush& b, double max_distance,
                        double grow = 0.0) {
    double tmin = -std::numeric_limits<double>::infinity(), tmax = std::numeric_limits<double>::infinity();
    for (const brush::Face& f : b.faces()) {
        if (!clip_by_plane(f.plane.signed_distance(origin) - grow, glm::dot(f.plane.normal, dir), tmin, tmax))
            return -1.0;
    }
    if (tmin > tmax || tmax <= 0.0 || tmin > max_distance) return -1.0;
    return std::max(tmin, 0.0);
}

// How far `p` lies outside the brush's surface: the largest signed plane distance (0 on the surface,
// negative inside). For a point near a face, its distance to the surface.
inline double outside_by(const DVec3& p, const brush::Brush& b) {
    double worst = -std::numeric_limits<double>::infinity();
    for (const brush::Face& f : b.faces()) worst = std::max(worst, f.plane.signed_distance(p));
    return worst;
}

// Closest points of segments [p0, p1] and [q0, q1] (Ericson, Real-Time Collision Detection 5.1.9).
inline double segment_segment_distance(const DVec3& p0, const DVec3& p1, const DVec3& q0, const DVec3& q1) {
    const DVec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
    const double a = glm::dot(d1, d1), e = glm::dot(d2, d2), f = glm::dot(d2, r);
    double s = 0.0, t = 0.0;
    if (a <= 1e-300 && e <= 1e-300) return glm::length(r);
    if (a <= 1e-300) {
        t = std::clamp(f / e, 0.0, 1.0);
    } else {
        const double c = glm::dot(d1, r);
        if (e <= 1e-300) {
            s = std::clamp(-c / a, 0.0, 1.0);
        } else {
            const double b = glm::dot(d1, d2), denom = a * e - b * b;
            s = denom > 0.0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
            t = (b * s + f) / e;
            if (t < 0.0)
                t = 0.0, s = std::clamp(-c / a, 0.0, 1.0);
            else if (t > 1.0)
                t = 1.0, s = std::clamp((b - c) / a, 0.0, 1.0);
        }
    }
    return glm::length((p0 + d1 * s) - (q0 + d2 * t));
}

// Distance from `p` to face `i`'s polygon when its projection falls inside the polygon, else infinity.
inline double point_face_distance(const DVec3& p, const brush::Brush& b, std::size_t i) {
    const brush::Plane& plane = b.faces()[i].plane;
    const auto& poly = b.polygons()[i];
    for (std::size_t k = 0; k < poly.size(); ++k) {
        const DVec3& a = b.vertices()[poly[k]];
        const DVec3& c = b.vertices()[poly[(k + 1) % poly.size()]];
        // Counter-clockwise seen from outside: the inside lies left of each edge.
        if (glm::dot(glm::cross(c - a, p - a), plane.normal) < 0.0)
            return std::numeric_limits<double>::infinity();
    }
    return std::abs(plane.signed_distance(p));
}

// Distance from the segment [p0, p1] to the brush (0 when they meet).
inline double segment_brush_distance(const DVec3& p0, const DVec3& p1, const brush::Brush& b) {
    double lo = 0.0, hi = 1.0; // the part of the segment inside every half-space
    for (const brush::Face& f : b.faces()) {
        const double s0 = f.plane.signed_distance(p0), s1 = f.plane.signed_distance(p1);
        if (s0 > 0.0 && s1 > 0.0) {
            lo = 1.0, hi = 0.0;
            break;
        }
        if (s0 > 0.0) lo = std::max(lo, s0 / (s0 - s1));
        if (s1 > 0.0) hi = std::min(hi, s0 / (s0 - s1));
    }
    if (lo <= hi) return 0.0;
    // Apart: the closest pair has an endpoint of the segment against a face's inside, or the segment
    // against an edge.
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < b.faces().size(); ++i)
        best = std::min({best, point_face_distance(p0, b, i), point_face_distance(p1, b, i)});
    for (const brush::Edge& e : b.edges())
        best = std::min(best, segment_segment_distance(p0, p1, b.vertices()[e.v0], b.vertices()[e.v1]));
    return best;
}

// The error of a float ray result against the brush, in world units: the distance of the reported entry
// point from the brush's surface (0 for a ray starting inside when its origin is inside), or for a miss how
// deep the ray reaches into the brush (how far it would have to be shrunk to be missed). A result is a
// mismatch beyond `eps` when it is not what the brush grown by eps or shrunk by eps could give: a hit must
// lie between the grown brush's entry and the shrunk one's (so a grazing ray may move along the surface by
// eps / sin(angle), but its point stays within eps of the surface), a miss must miss the shrunk brush.
struct RayJudgement {
    double error = 0.0;
    bool mismatch = false;
};
inline RayJudgement judge_ray(const DVec3& o, const DVec3& d, double max_distance, bool fast_hit,
                              double fast_t, const brush::Brush& b, double eps) {
    const double shrunk = ray_brush(o, d, b, max_distance, -eps);
    if (!fast_hit) {
        RayJudgement j;
        if (ray_brush(o, d, b, max_distance) >= 0.0) {
            // How far inside the surface the ray passes: bisect the inward offset at which it misses.
            j.mismatch = shrunk >= 0.0;
            double lo = 0.0, hi = j.mismatch ? glm::length(b.bounds_max() - b.bounds_min()) : eps;
            for (int i = 0; i < 50; ++i) {
                const double mid = 0.5 * (lo + hi);
                (ray_brush(o, d, b, max_distance, -mid) >= 0.0 ? lo : hi) = mid;
            }
            j.error = hi;
        }
        return j;
    }
    if (fast_t <= 0.0) {
        const double out = outside_by(o, b);
        return {std::max(out, 0.0), out > eps};
    }
    const DVec3 p = o + d * fast_t;
    RayJudgement j{std::abs(outside_by(p, b)), false};
    const double grown = ray_brush(o, d, b, max_distance, eps);
    j.mismatch = grown < 0.0 || fast_t < grown || (shrunk >= 0.0 && fast_t > shrunk) || j.error > eps;
    return j;
}

// The error of a float capsule distance (`fast_distance`: radius minus the contact's penetration; 0 or less
// when the core meets the brush) against the reference distance of its core segment.
inline double capsule_error(double fast_distance, const DVec3& p0, const DVec3& p1, const brush::Brush& b) {
    const double want = segment_brush_distance(p0, p1, b);
    return std::abs(std::max(fast_distance, 0.0) - want);
}

} // namespace ks::physics::reference
