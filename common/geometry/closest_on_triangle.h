#pragma once
// The point of a triangle nearest a point (Ericson, Real-Time Collision Detection 5.1.5, by Voronoi regions),
// with where it lies on the triangle: point = a + (b - a) along_ab + (c - a) along_ac. A template so that
// physics runs it in double (its contacts) and model simplification in float, one algorithm for both; the
// point is computed by the same expressions in every region as physics always did, so its results are
// unchanged to the bit.
#include <glm/glm.hpp>

namespace ks::geometry {

template <class V>
struct TriangleClosest {
    V point;
    typename V::value_type along_ab, along_ac;
};

template <class V>
TriangleClosest<V> closest_on_triangle(const V& p, const V& a, const V& b, const V& c) {
    using T = typename V::value_type;
    const V ab = b - a, ac = c - a, ap = p - a;
    const T d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= T(0) && d2 <= T(0)) return {a, T(0), T(0)};
    const V bp = p - b;
    const T d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= T(0) && d4 <= d3) return {b, T(1), T(0)};
    const T vc = d1 * d4 - d3 * d2;
    if (vc <= T(0) && d1 >= T(0) && d3 <= T(0)) {
        const T s = d1 / (d1 - d3);
        return {a + ab * s, s, T(0)};
    }
    const V cp = p - c;
    const T d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= T(0) && d5 <= d6) return {c, T(0), T(1)};
    const T vb = d5 * d2 - d1 * d6;
    if (vb <= T(0) && d2 >= T(0) && d6 <= T(0)) {
        const T t = d2 / (d2 - d6);
        return {a + ac * t, T(0), t};
    }
    const T va = d3 * d6 - d5 * d4;
    if (va <= T(0) && (d4 - d3) >= T(0) && (d5 - d6) >= T(0)) {
        const T r = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return {b + (c - b) * r, T(1) - r, r};
    }
    const T denom = T(1) / (va + vb + vc);
    return {a + ab * (vb * denom) + ac * (vc * denom), vb * denom, vc * denom};
}

} // namespace ks::geometry
