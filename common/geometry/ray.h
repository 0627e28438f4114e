#pragma once
// The ray every query takes (physics casts and shots, editor picking, the camera's screen rays) and the
// robust slab test against an axis-aligned box that BVH traversal and picking build on.
#include "geometry/aabb.h"

#include <algorithm>

namespace ks::geometry {

struct Ray {
    Vec3 origin{0.0f};
    Vec3 direction{0.0f, 0.0f, -1.0f}; // unit length
    float max_distance = 1e30f;

    Vec3 at(float distance) const { return origin + direction * distance; }
};

// Rounding guard for slab tests (Ize, "Robust BVH Ray Traversal"): widening the exit distance by a few
// ulps makes boundary crossings count, so a ray through the shared edge of two boxes is never lost.
inline constexpr float kExitWiden = 1.0f + 4.0f * 1.1920929e-7f;

// An exact zero direction component becomes this tiny positive value: the slab test then needs no inf·0
// (NaN) and classifies a ray lying in a slab plane half-open (inside on the min plane, outside on the max
// plane), so a ray along the face shared by two stacked boxes hits exactly one of them.
inline constexpr float kTinyDirection = 1e-30f;
inline float tiny_fix(float v) {
    return v == 0.0f ? kTinyDirection : v;
}

// 1/direction, with exact zeros replaced as above (finite, never NaN).
inline Vec3 safe_inverse(const Vec3& d) {
    return {1.0f / tiny_fix(d.x), 1.0f / tiny_fix(d.y), 1.0f / tiny_fix(d.z)};
}

// Slab test against an axis-aligned box within [0, max_t]; `inv` is safe_inverse(direction).
// Inlined into BVH traversal.
inline bool ray_aabb(const Vec3& origin, const Vec3& inv, const Vec3& bmin, const Vec3& bmax, float max_t,
                     float& t_enter) {
    const float tx0 = (bmin.x - origin.x) * inv.x, tx1 = (bmax.x - origin.x) * inv.x;
    const float ty0 = (bmin.y - origin.y) * inv.y, ty1 = (bmax.y - origin.y) * inv.y;
    const float tz0 = (bmin.z - origin.z) * inv.z, tz1 = (bmax.z - origin.z) * inv.z;
    const float tmin =
        std::max(std::max(std::min(tx0, tx1), std::min(ty0, ty1)), std::max(std::min(tz0, tz1), 0.0f));
    const float tmax =
        std::min(std::min(std::max(tx0, tx1), std::max(ty0, ty1)), std::min(std::max(tz0, tz1), max_t));
    t_enter = tmin;
    return tmin <= tmax * kExitWiden;
}

inline bool ray_aabb(const Ray& ray, const Aabb& box, float& t_enter) {
    return ray_aabb(ray.origin, safe_inverse(ray.direction), box.min, box.max, ray.max_distance, t_enter);
}

} // namespace ks::geometry
