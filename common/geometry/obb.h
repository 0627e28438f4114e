#pragma once
// The oriented box (the editor's entity bounds), the exact separating-axis overlap test between two of them
// with penetration depth, and the ray's entry into one (picking).
#include "geometry/aabb.h"
#include "geometry/ray.h"

namespace ks::geometry {

struct Obb {
    Vec3 center{0.0f};
    Mat3 axes{1.0f}; // columns: the box's local x, y, z in world space (orthonormal)
    Vec3 half{0.0f};
    Aabb aabb() const;
    bool contains(const Vec3& p, float margin = 0.0f) const;
    Vec3 to_local(const Vec3& p) const; // coordinates along the box axes, relative to the centre
};

struct Overlap {
    bool overlapping = false;
    float depth = 0.0f; // smallest penetration over the separating axes (0 when apart or touching)
    Vec3 axis{0.0f};    // unit axis of that smallest penetration, pointing from b toward a
};
// Separating-axis test of two oriented boxes (15 axes; near-parallel edge pairs are skipped, their face
// axes already decide), in doubles. Boxes that only touch (depth <= tolerance) do not overlap; non-finite
// input never overlaps.
Overlap obb_overlap(const Obb& a, const Obb& b, float tolerance = 1e-3f);

// One separating axis of a SAT: the projections of A and B on it as intervals. `depth` is the smaller of the
// two pushes that separate them (< 0: separated by that gap, 0: touching); `push_a_positive` says A leaves
// by moving along +axis. Both SATs measure every axis with it: obb_overlap here (doubles) and the physics
// convex-convex test (physics/collide.cpp, floats).
template <class T>
struct AxisOverlap {
    T depth;
    bool push_a_positive;
};
template <class T>
AxisOverlap<T> interval_overlap(T a_lo, T a_hi, T b_lo, T b_hi) {
    const T push_positive = b_hi - a_lo, push_negative = a_hi - b_lo;
    return {std::min(push_positive, push_negative), push_positive < push_negative};
}

// Slab test of a ray against an oriented box: the entry distance (0 when the origin is inside), or a
// negative number for a miss (also beyond ray.max_distance).
float ray_obb(const Ray& ray, const Obb& box);

} // namespace ks::geometry
