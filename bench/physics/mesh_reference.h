#pragma once
// The long-double reference for capsule-against-triangle contact, written independently of
// physics/triangle_mesh.cpp: the distance from a point to a triangle by projecting onto its plane and, when
// the projection falls outside, onto each edge; the segment's distance as the minimum over the segment's
// parameter of that (convex) function, found by golden-section search to the limit of long double.
// Used by tests/physics/test_triangle_mesh.cpp and `ks_bench physics_mesh` for their error columns.
#include "core/math.h"

#include <algorithm>
#include <cmath>

namespace ks::physics::reference {

using LReal = long double;
struct LVec3 {
    LReal x = 0, y = 0, z = 0;
};
inline LVec3 lvec(const DVec3& v) {
    return {v.x, v.y, v.z};
}
inline LVec3 operator-(const LVec3& a, const LVec3& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline LVec3 operator+(const LVec3& a, const LVec3& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline LVec3 operator*(const LVec3& a, LReal s) {
    return {a.x * s, a.y * s, a.z * s};
}
inline LReal dot(const LVec3& a, const LVec3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline LVec3 cross(const LVec3& a, const LVec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline LReal length(const LVec3& a) {
    return std::sqrt(dot(a, a));
}

// Distance from p to the segment [a, b].
inline LReal point_segment(const LVec3& p, const LVec3& a, const LVec3& b) {
    const LVec3 ab = b - a;
    const LReal len2 = dot(ab, ab);
    const LReal t = len2 > 0 ? std::clamp(dot(p - a, ab) / len2, LReal(0), LReal(1)) : LReal(0);
    return length(p - (a + ab * t));
}

// Distance from p to the triangle: to its plane when the foot lies inside (all three edge tests agree with
// the normal), else to the nearest edge.
inline LReal point_triangle(const LVec3& p, const LVec3& a, const LVec3& b, const LVec3& c) {
    const LVec3 n = cross(b - a, c - a);
    const LReal n2 = dot(n, n);
    if (n2 > 0) {
        const LVec3 foot = p - n * (dot(p - a, n) / n2);
        if (dot(cross(b - a, foot - a), n) >= 0 && dot(cross(c - b, foot - b), n) >= 0 &&
            dot(cross(a - c, foot - c), n) >= 0)
            return std::abs(dot(p - a, n)) / std::sqrt(n2);
    }
    return std::min({point_segment(p, a, b), point_segment(p, b, c), point_segment(p, c, a)});
}

// Distance from the segment [p0, p1] to the triangle.
inline double segment_triangle(const DVec3& p0d, const DVec3& p1d, const DVec3& ad, const DVec3& bd,
                               const DVec3& cd) {
    const LVec3 p0 = lvec(p0d), d = lvec(p1d) - p0, a = lvec(ad), b = lvec(bd), c = lvec(cd);
    auto f = [&](LReal t) { return point_triangle(p0 + d * t, a, b, c); };
    const LReal g = (std::sqrt(LReal(5)) - 1) / 2;
    LReal lo = 0, hi = 1, x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), f1 = f(x1), f2 = f(x2);
    for (int i = 0; i < 120; ++i) {
        if (f1 <= f2)
            hi = x2, x2 = x1, f2 = f1, x1 = hi - g * (hi - lo), f1 = f(x1);
        else
            lo = x1, x1 = x2, f1 = f2, x2 = lo + g * (hi - lo), f2 = f(x2);
    }
    return static_cast<double>(std::min({f(0), f(1), f1, f2}));
}

// How far a point lies from the segment and from the triangle (witness checks).
inline double off_segment(const DVec3& q, const DVec3& p0, const DVec3& p1) {
    return static_cast<double>(point_segment(lvec(q), lvec(p0), lvec(p1)));
}
inline double off_triangle(const DVec3& q, const DVec3& a, const DVec3& b, const DVec3& c) {
    return static_cast<double>(point_triangle(lvec(q), lvec(a), lvec(b), lvec(c)));
}

} // namespace ks::physics::reference
