#pragma once
// Ray against single shapes, exactly and watertight: boxes by the slab test in the box frame (origin taken
// relative to the box centre, so geometry 10 km away keeps its precision), polyhedra by clipping against
// their face planes (a convex solid's entry point; no edge tests, so no ray slips between two faces),
// capsules and cylinders analytically. A ray starting inside or on a solid hits it at distance 0 with
// the normal opposing the ray; a ray lying in a face plane counts as touching (distance where it enters).
#include "geometry/ray.h"
#include "physics/shapes.h"

#include <algorithm>
#include <utility>

namespace ks::physics {

struct ShapeHit {
    float distance = 0.0f;
    Vec3 normal{0.0f}; // world, unit, facing against the ray
};

// Each returns true and fills `hit` when the ray enters the shape within [0, max_distance].
bool ray_box(const geometry::Ray& ray, const Vec3& half, const geometry::Transform& xf, ShapeHit& hit);
bool ray_polyhedron(const geometry::Ray& ray, const Polyhedron& p, const geometry::Transform& xf, ShapeHit& hit);
bool ray_capsule(const geometry::Ray& ray, const Vec3& p0, const Vec3& p1, float radius, ShapeHit& hit);
bool ray_cylinder(const geometry::Ray& ray, const Vec3& centre, float radius, float half_height,
                  ShapeHit& hit);
bool ray_shape(const geometry::Ray& ray, const Shape& shape, const geometry::Transform& xf, ShapeHit& hit);

// The exact slab test against an axis-aligned box given by centre and half extents (origin taken relative
// to the centre, so far geometry keeps its precision), with the half-open in-plane rule.
inline bool ray_centred_aabb(const geometry::Ray& ray, const Vec3& inv, const Vec3& centre, const Vec3& half,
                             ShapeHit& hit) {
    const Vec3 o = ray.origin - centre;
    const Vec3 t0 = (-half - o) * inv, t1 = (half - o) * inv;
    const Vec3 lo = glm::min(t0, t1), hi = glm::max(t0, t1);
    const float tmin = std::max(lo.x, std::max(lo.y, lo.z));
    const float tmax = std::min(hi.x, std::min(hi.y, hi.z)) * geometry::kExitWiden;
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
