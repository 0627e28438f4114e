#include "geometry/obb.h"

#include <cmath>
#include <limits>

namespace ks::geometry {

Aabb Obb::aabb() const {
    Vec3 extent(0.0f);
    for (int i = 0; i < 3; ++i) extent += glm::abs(axes[i]) * half[i];
    return {center - extent, center + extent};
}

Vec3 Obb::to_local(const Vec3& p) const {
    const Vec3 d = p - center;
    return {glm::dot(d, axes[0]), glm::dot(d, axes[1]), glm::dot(d, axes[2])};
}

bool Obb::contains(const Vec3& p, float margin) const {
    const Vec3 l = to_local(p);
    for (int i = 0; i < 3; ++i)
        if (std::abs(l[i]) > half[i] + margin) return false;
    return true;
}

Overlap obb_overlap(const Obb& a, const Obb& b, float tolerance) {
    // Doubles: level coordinates reach 1e4 while overlaps of 1e-3 must still be told from touching.
    const glm::dvec3 t = glm::dvec3(b.center) - glm::dvec3(a.center);
    glm::dvec3 axes_a[3], axes_b[3];
    for (int i = 0; i < 3; ++i) {
        axes_a[i] = glm::normalize(glm::dvec3(a.axes[i]));
        axes_b[i] = glm::normalize(glm::dvec3(b.axes[i]));
    }
    const glm::dvec3 ha(a.half), hb(b.half);
    double check = t.x + t.y + t.z + ha.x + ha.y + ha.z + hb.x + hb.y + hb.z;
    for (int i = 0; i < 3; ++i) check += glm::dot(axes_a[i] + axes_b[i], glm::dvec3(1.0));
    if (!std::isfinite(check)) return {};

    double best = std::numeric_limits<double>::infinity();
    glm::dvec3 best_axis(0.0);
    auto test = [&](const glm::dvec3& axis) {
        double ra = 0, rb = 0;
        for (int i = 0; i < 3; ++i) {
            ra += ha[i] * std::abs(glm::dot(axes_a[i], axis));
            rb += hb[i] * std::abs(glm::dot(axes_b[i], axis));
        }
        const double dist = glm::dot(t, axis);
        const AxisOverlap<double> o = interval_overlap(-ra, ra, dist - rb, dist + rb);
        if (o.depth < best) {
            best = o.depth;
            best_axis = o.push_a_positive ? axis : -axis; // from b toward a
        }
        return o.depth > tolerance;
    };
    for (int i = 0; i < 3; ++i)
        if (!test(axes_a[i]) || !test(axes_b[i])) return {};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const glm::dvec3 c = glm::cross(axes_a[i], axes_b[j]);
            const double len = glm::length(c);
            if (len < 1e-6) continue; // parallel edges: a face axis already covers this direction
            if (!test(c / len)) return {};
        }
    return {true, static_cast<float>(best), Vec3(best_axis)};
}

float ray_obb(const Ray& ray, const Obb& box) {
    if (!is_finite(ray.origin) || !is_finite(ray.direction)) return -1.0f;
    const Vec3 o = box.to_local(ray.origin);
    const Vec3 d = glm::transpose(box.axes) * ray.direction;
    float t0 = 0.0f, t1 = ray.max_distance;
    for (int i = 0; i < 3; ++i) {
        if (std::abs(d[i]) < 1e-8f) { // parallel to this slab: inside it or a miss
            if (std::abs(o[i]) > box.half[i]) return -1.0f;
            continue;
        }
        float near = (-box.half[i] - o[i]) / d[i], far = (box.half[i] - o[i]) / d[i];
        if (near > far) std::swap(near, far);
        t0 = std::max(t0, near);
        t1 = std::min(t1, far);
        if (t0 > t1) return -1.0f;
    }
    return t0;
}

} // namespace ks::geometry
