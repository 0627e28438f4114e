#pragma once
// Ray against single shapes, exactly and watertight: boxes by the slab test in the box frame (origin taken
// relative to the box centre, so geometry 10 km away keeps its precision), polyhedra by clipping against
// their face planes (a convex solid's entry point; no edge tests, so no ray slips between two faces),
// capsules and cylinders analytically. A ray starting inside or on a solid hits it at distance 0 with
// the normal opposing the ray; a ray lying in a face plane counts as touching (distance where it enters).
#include "physics/shapes.h"

#include <algorithm>
#include <utility>

namespace ks::physics {

struct Ray {
    Vec3 origin{0.0f};
    Vec3 direction{0.0f, 0.0f, -1.0f}; // unit length
    float max_distance = 1e30f;
};

struct ShapeHit {
    float distance = 0.0f;
    Vec3 normal{0.0f}; // world, unit, facing against the ray
};

// Each returns true and fills `hit` when the ray enters the shape within [0, max_distance].
bool ray_box(const Ray& ray, const Vec3& half, const Transform& xf, ShapeHit& hit);
bool ray_polyhedron(const Ray& ray, const Polyhedron& p, const Transform& xf, ShapeHit& hit);
bool ray_capsule(const Ray& ray, const Vec3& p0, const Vec3& p1, float radius, ShapeHit& hit);
bool ray_cylinder(const Ray& ray, const Vec3& centre, float radius, float half_height, ShapeHit& hit);
bool ray_shape(const Ray& ray, const Shape& shape, const Transform& xf, ShapeHit& hit);

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

// Slab test against an axis-aligned box within [0, max_t]; inlined into BVH traversal.
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

// The exact slab test against an axis-aligned box given by centre and half extents (origin taken relative
// to the centre, so far geometry keeps its precision), with the half-open in-plane rule.
inline bool ray_centred_aabb(const Ray& ray, const Vec3& inv, const Vec3& centre, const Vec3& half,
                             ShapeHit& hit) {
    const Vec3 o = ray.origin - centre;
    const Vec3 t0 = (-half - o) * inv, t1 = (half - o) * inv;
    const Vec3 lo = glm::min(t0, t1), hi = glm::max(t0, t1);
    const float tmin = std::max(lo.x, std::max(lo.y, lo.z));
    const float tmax = std::min(hi.x, std::min(hi.y, hi.z)) * kExitWiden;
    if (!(tmin <= tmax) || !(tmax > 0.0f) || tmin > ray.max_distance) return false;
    if (tmin <= 0.0f) { // starts inside (or on the surface, heading in)
        hit.distance = 0.0f;
        hit.normal = -ray.direction;
        return true;
    }
    const int axis = tmin == lo.x ? 0 : (tmin == lo.y ? 1 : 2);
    hit.distance = tmin;
    hit.normal = Vec3(0.0f);
    hit.normal[axis] = ray.direction[axis] > 0.0f ? -1.0f : 1.0f;
    return true;
}

} // namespace ks::physics
