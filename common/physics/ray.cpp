#include "physics/ray.h"

#include "physics/triangle_mesh.h"

#include <algorithm>
#include <cmath>

namespace ks::physics {
bool ray_box(const geometry::Ray& ray, const Vec3& half, const geometry::Transform& xf, ShapeHit& hit) {
    // In the box frame, relative to its centre: the subtraction is exact for nearby points, so a box 10 km
    // from the origin is intersected as precisely as one at the origin.
    // A NaN or infinite direction would slip through the slab test below (NaN compares false) and report
    // a hit with a NaN normal; one sum tells (inf - inf and NaN + x are NaN, inf + x is inf).
    if (!std::isfinite(ray.direction.x + ray.direction.y + ray.direction.z)) return false;
    const Vec3 o = xf.to_local(ray.origin);
    const Vec3 d = xf.dir_to_local(ray.direction);
    float tmin = -3.4e38f, tmax = 3.4e38f;
    int axis = -1;
    for (int i = 0; i < 3; ++i) {
        const float inv = 1.0f / geometry::tiny_fix(d[i]);
        float t0 = (-half[i] - o[i]) * inv, t1 = (half[i] - o[i]) * inv;
        if (t0 > t1) std::swap(t0, t1);
        if (t0 > tmin) tmin = t0, axis = i;
        tmax = std::min(tmax, t1);
    }
    tmax *= geometry::kExitWiden;
    if (!(tmin <= tmax) || !(tmax > 0.0f) || tmin > ray.max_distance) return false;
    if (tmin <= 0.0f) { // starts inside (or on the surface, heading in)
        hit.distance = 0.0f;
        hit.normal = -ray.direction;
        return true;
    }
    Vec3 n(0.0f);
    n[axis] = d[axis] > 0.0f ? -1.0f : 1.0f;
    hit.distance = tmin;
    hit.normal = xf.dir_to_world(n);
    return true;
}

bool ray_polyhedron(const geometry::Ray& ray, const Polyhedron& p, const geometry::Transform& xf,
                    ShapeHit& hit) {
    const Vec3 o = xf.to_local(ray.origin);
    const Vec3 d = xf.dir_to_local(ray.direction);
    float tmin = -3.4e38f, tmax = 3.4e38f;
    int entry = -1;
    for (std::size_t i = 0; i < p.faces.size(); ++i) {
        const auto& f = p.faces[i];
        const float dist = glm::dot(f.normal, o) - f.offset, dn = glm::dot(f.normal, d);
        if (dn == 0.0f) {
            if (dist > 0.0f) return false; // parallel and outside this face's half-space
            continue;
        }
        const float t = -dist / dn;
        if (dn < 0.0f) {
            if (t > tmin) tmin = t, entry = static_cast<int>(i);
        } else {
            tmax = std::min(tmax, t);
        }
        if (tmin > tmax * geometry::kExitWiden + 1e-30f) return false;
    }
    if (!(tmax > 0.0f) || tmin > ray.max_distance || entry < 0) return false;
    if (tmin <= 0.0f) {
        hit.distance = 0.0f;
        hit.normal = -ray.direction;
        return true;
    }
    hit.distance = tmin;
    hit.normal = xf.dir_to_world(p.faces[entry].normal);
    return true;
}

bool ray_capsule(const geometry::Ray& ray, const Vec3& p0, const Vec3& p1, float r, ShapeHit& hit) {
    // Relative to p0 for precision far from the origin.
    const Vec3 ba = p1 - p0, oa = ray.origin - p0, rd = ray.direction;
    const float baba = glm::dot(ba, ba), bard = glm::dot(ba, rd), baoa = glm::dot(ba, oa);
    // Inside test first: distance from the origin to the segment.
    const float h0 = baba > 0.0f ? std::clamp(baoa / baba, 0.0f, 1.0f) : 0.0f;
    if (glm::length(oa - ba * h0) <= r) {
        hit.distance = 0.0f;
        hit.normal = -rd;
        return true;
    }
    float t = -1.0f;
    Vec3 centre;
    const float a = baba - bard * bard, b = baba * glm::dot(oa, rd) - baoa * bard,
                c = baba * glm::dot(oa, oa) - baoa * baoa - r * r * baba;
    if (a > 1e-12f * baba) { // the cylindrical body
        const float disc = b * b - a * c;
        if (disc >= 0.0f) {
            const float tc = (-b - std::sqrt(disc)) / a;
            const float y = baoa + tc * bard;
            if (y > 0.0f && y < baba && tc >= 0.0f) t = tc, centre = p0 + ba * (y / baba);
        }
    }
    if (t < 0.0f) { // the end spheres
        for (const Vec3& e : {p0, p1}) {
            const Vec3 oc = ray.origin - e;
            const float bb = glm::dot(oc, rd), cc = glm::dot(oc, oc) - r * r, disc = bb * bb - cc;
            if (disc < 0.0f) continue;
            const float ts = -bb - std::sqrt(disc);
            if (ts >= 0.0f && (t < 0.0f || ts < t)) t = ts, centre = e;
        }
    }
    if (t < 0.0f || t > ray.max_distance) return false;
    hit.distance = t;
    hit.normal = glm::normalize(ray.origin + rd * t - centre);
    return true;
}

bool ray_cylinder(const geometry::Ray& ray, const Vec3& c, float radius, float half_height, ShapeHit& hit) {
    const Vec3 o = ray.origin - c, d = ray.direction;
    const float r2 = radius * radius;
    if (std::abs(o.y) <= half_height && o.x * o.x + o.z * o.z <= r2) {
        hit.distance = 0.0f;
        hit.normal = -d;
        return true;
    }
    float best = -1.0f;
    Vec3 n(0.0f);
    const float a = d.x * d.x + d.z * d.z;
    if (a > 0.0f) {
        const float b = o.x * d.x + o.z * d.z, cc = o.x * o.x + o.z * o.z - r2, disc = b * b - a * cc;
        if (disc >= 0.0f) {
            const float t = (-b - std::sqrt(disc)) / a;
            const float y = o.y + d.y * t;
            if (t >= 0.0f && std::abs(y) <= half_height) {
                best = t;
                n = glm::normalize(Vec3(o.x + d.x * t, 0.0f, o.z + d.z * t));
            }
        }
    }
    if (d.y != 0.0f) {
        for (float side : {1.0f, -1.0f}) {
            const float t = (side * half_height - o.y) / d.y;
            if (t < 0.0f || (best >= 0.0f && t >= best) || d.y * side > 0.0f) continue;
            const float x = o.x + d.x * t, z = o.z + d.z * t;
            if (x * x + z * z <= r2) best = t, n = {0.0f, side, 0.0f};
        }
    }
    if (best < 0.0f || best > ray.max_distance) return false;
    hit.distance = best;
    hit.normal = n;
    return true;
}

bool ray_shape(const geometry::Ray& ray, const Shape& shape, const geometry::Transform& xf, ShapeHit& hit) {
    switch (shape.kind) {
    case ShapeKind::Box:
        return ray_box(ray, shape.half_extents, xf, hit);
    case ShapeKind::Wedge:
    case ShapeKind::Hull:
        return ray_polyhedron(ray, *shape.polyhedron, xf, hit);
    case ShapeKind::Capsule: {
        const Vec3 up(0.0f, shape.half_height, 0.0f);
        return ray_capsule(ray, xf.position - up, xf.position + up, shape.radius, hit);
    }
    case ShapeKind::Cylinder:
        return ray_cylinder(ray, xf.position, shape.radius, shape.half_height, hit);
    case ShapeKind::Mesh:
        return ray_mesh(ray, *shape.mesh, xf, hit);
    }
    return false;
}

} // namespace ks::physics
