#pragma once
// The axis-aligned box every module shares: physics broadphase and BVH bounds, render culling and mesh
// bounds, the editor's box selection and validation grids.
#include "core/math.h"

namespace ks::geometry {

struct Aabb {
    Vec3 min{0.0f};
    Vec3 max{0.0f};

    // Inverted (min > max) so that growing it by anything gives exactly that thing. Finite, so that its
    // centre stays a number.
    static Aabb empty() { return {Vec3(3.4e38f), Vec3(-3.4e38f)}; }

    bool valid() const { return min.x <= max.x && min.y <= max.y && min.z <= max.z; }
    // Closed intervals: boxes that only touch overlap.
    bool overlaps(const Aabb& o) const {
        return min.x <= o.max.x && o.min.x <= max.x && min.y <= o.max.y && o.min.y <= max.y &&
               min.z <= o.max.z && o.min.z <= max.z;
    }
    bool contains(const Vec3& p) const {
        return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y && p.z >= min.z && p.z <= max.z;
    }
    Vec3 center() const { return (min + max) * 0.5f; }
    Vec3 extent() const { return (max - min) * 0.5f; } // half size
    float surface_area() const {
        const Vec3 d = max - min;
        return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
    }
    Aabb expanded(float by) const { return {min - Vec3(by), max + Vec3(by)}; }
    void grow(const Vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void grow(const Aabb& b) {
        min = glm::min(min, b.min);
        max = glm::max(max, b.max);
    }
};

inline Aabb merge(const Aabb& a, const Aabb& b) {
    return {glm::min(a.min, b.min), glm::max(a.max, b.max)};
}

// The box around `box` moved by the affine `m` (exact for the transformed box's corners).
Aabb transform_aabb(const Aabb& box, const Mat4& m);

} // namespace ks::geometry
