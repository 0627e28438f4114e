#pragma once
// Shared by the physics property tests (tests/hardening/test_physics_properties.cpp and
// test_physics_properties_references.cpp): random shapes, rotations and ray directions drawn from a
// fixed-seed Rng, the checks every ray hit and contact normal must pass, and printing of the failing inputs.
#include "physics/collide.h"
#include "physics/ray.h"

#include "core/random.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace ks::physics::property_test {

inline bool finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
// A normalised vector is unit to ~1e-7; 1e-3 is the bar. Capsule contact normals once missed it far from
// the origin (fixed: the regression cases at the end of test_physics_properties.cpp keep their inputs);
// g_loose_normals counts the cases beyond the bar, and every one of them fails the test.
inline int g_loose_normals = 0;
inline bool unit(const Vec3& v, float tolerance = 1e-3f) {
    return finite(v) && std::abs(glm::length(v) - 1.0f) < tolerance;
}
inline bool contact_unit(const Vec3& v) {
    if (unit(v)) return true;
    ++g_loose_normals;
    return false;
}
inline std::string str(const Vec3& v) {
    std::ostringstream s;
    s.precision(9);
    s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return s.str();
}

inline Vec3 random_unit(Rng& rng) {
    for (;;) {
        const Vec3 v(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
        const float l = glm::length(v);
        if (l > 0.1f && l <= 1.0f) return v / l;
    }
}

inline Quat random_rotation(Rng& rng) {
    Vec4 q;
    do {
        q = Vec4(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    } while (glm::length(q) < 0.1f || glm::length(q) > 1.0f);
    q = glm::normalize(q);
    return Quat(q.w, q.x, q.y, q.z);
}

// Rotations a level really has (a quarter of them), else any rotation.
inline Quat scene_rotation(Rng& rng) {
    const float r = rng.uniform();
    if (r < 0.15f) return Quat(1, 0, 0, 0);
    if (r < 0.3f) return glm::angleAxis(rng.uniform(0.0f, 2.0f * kPi), Vec3(0, 1, 0));
    return random_rotation(rng);
}

inline Vec3 random_half(Rng& rng, float lo = 0.05f, float hi = 5.0f) {
    return {rng.uniform(lo, hi), rng.uniform(lo, hi), rng.uniform(lo, hi)};
}

// A random convex hull of 6-24 points (an ellipsoid's surface, some on a flat cut), or a box/wedge.
inline Polyhedron random_polyhedron(Rng& rng, const char*& kind) {
    const float pick = rng.uniform();
    if (pick < 0.35f) {
        kind = "box";
        return make_box_polyhedron(random_half(rng, 0.05f, 4.0f));
    }
    if (pick < 0.55f) {
        kind = "wedge";
        return make_wedge_polyhedron(random_half(rng, 0.1f, 4.0f));
    }
    kind = "hull";
    for (;;) {
        const Vec3 scale = random_half(rng, 0.2f, 3.0f);
        const int n = 6 + static_cast<int>(rng.below(19));
        std::vector<Vec3> points;
        for (int i = 0; i < n; ++i) {
            Vec3 p = random_unit(rng) * scale;
            if (rng.chance(0.2f)) p.y = std::min(p.y, 0.2f * scale.y); // a flat cut: coplanar points
            points.push_back(p);
        }
        auto hull = build_convex_hull(points, "random hull");
        if (hull) return std::move(*hull);
    }
}

// What every ray hit must be: finite, within the ray's reach, a unit normal facing the ray.
inline void check_hit(bool hit, const ShapeHit& h, const geometry::Ray& ray, const char* what, int i) {
    if (!hit) return;
    INFO(what << " case " << i << " origin " << str(ray.origin) << " dir " << str(ray.direction));
    REQUIRE(std::isfinite(h.distance));
    REQUIRE(h.distance >= 0.0f);
    REQUIRE(h.distance <= ray.max_distance);
    REQUIRE(unit(h.normal));
    REQUIRE(glm::dot(h.normal, ray.direction) <= 1e-3f);
}

// Ray directions a game produces, and the awkward ones: axis-aligned (exact zeros), nearly axis-aligned
// (1e-20 components), and random.
inline Vec3 awkward_direction(Rng& rng) {
    switch (rng.below(4)) {
    case 0: {
        Vec3 d(0.0f);
        d[rng.below(3)] = rng.chance(0.5f) ? 1.0f : -1.0f;
        return d;
    }
    case 1: {
        Vec3 d(rng.uniform(-1e-20f, 1e-20f), rng.uniform(-1e-20f, 1e-20f), rng.uniform(-1e-20f, 1e-20f));
        d[rng.below(3)] = 1.0f;
        return glm::normalize(d);
    }
    case 2: {
        Vec3 d = random_unit(rng);
        d[rng.below(3)] = 0.0f;
        return glm::length(d) > 0.1f ? glm::normalize(d) : Vec3(1, 0, 0);
    }
    default:
        return random_unit(rng);
    }
}

} // namespace ks::physics::property_test
