#pragma once
// Ray against single shapes, exactly and watertight: boxes by the slab test in the box frame (origin taken
// relative to the box centre, so geometry 10 km away keeps its precision), polyhedra by clipping against
// their face planes (a convex solid's entry point; no edge tests, so no ray slips between two faces),
// capsules and cylinders analytically. A ray starting inside or on a solid hits it at distance 0 with
// the normal opposing the ray; a ray lying in a face plane counts as touching (distance where it enters).
#include "physics/shapes.h"

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
bool ray_aabb(const Ray& ray, const Vec3& inv_dir, const Aabb& box, float max_t, float& t_enter);
bool ray_polyhedron(const Ray& ray, const Polyhedron& p, const Transform& xf, ShapeHit& hit);
bool ray_capsule(const Ray& ray, const Vec3& p0, const Vec3& p1, float radius, ShapeHit& hit);
bool ray_cylinder(const Ray& ray, const Vec3& centre, float radius, float half_height, ShapeHit& hit);
bool ray_shape(const Ray& ray, const Shape& shape, const Transform& xf, ShapeHit& hit);

// 1/direction with exact zeros kept as +-inf (the slab test treats NaN from 0·inf as "inside the slab").
Vec3 safe_inverse(const Vec3& d);

} // namespace ks::physics
