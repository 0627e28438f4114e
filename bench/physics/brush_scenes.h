#pragma once
// Random brushes and the queries against them, shared by the brush tests and `ks_bench physics`: convex
// hulls of random points (half of them near the origin, half near (+-10 000, ...)), rays aimed at them from
// a few units to 30 units away, and upright player capsules placed around them.
#include "brush/brush_build.h"
#include "core/random.h"
#include "geometry/ray.h"

#include <vector>

namespace ks::physics::brush_scenes {

inline DVec3 random_far_centre(Rng& rng, bool far) {
    if (!far) return {rng.uniform(-50, 50), rng.uniform(-50, 50), rng.uniform(-50, 50)};
    auto side = [&] { return (rng.chance(0.5f) ? 1.0 : -1.0) * rng.uniform(9980, 10000); };
    return {side(), side(), side()};
}

// A convex hull of 6..16 random points in a box of half size 0.3..4 around `centre`.
inline brush::Brush random_brush(Rng& rng, const DVec3& centre) {
    for (;;) {
        const DVec3 half(rng.uniform(0.3f, 4), rng.uniform(0.3f, 4), rng.uniform(0.3f, 4));
        std::vector<DVec3> points;
        const int n = 6 + static_cast<int>(rng.below(11));
        for (int i = 0; i < n; ++i)
            points.push_back(centre +
                             DVec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)) * half);
        if (auto b = brush::make_from_points(points)) return std::move(*b);
    }
}

// A ray from 1..30 units outside the brush's bounds toward a random point of them (most hit, some graze,
// some miss), as float like every ray of the game.
inline geometry::Ray ray_at(Rng& rng, const brush::Brush& b) {
    const DVec3 lo = b.bounds_min(), hi = b.bounds_max(), size = hi - lo;
    const DVec3 target =
        lo + DVec3(rng.uniform(-0.1f, 1.1f), rng.uniform(-0.1f, 1.1f), rng.uniform(-0.1f, 1.1f)) * size;
    DVec3 from_dir(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    if (glm::length(from_dir) < 1e-3) from_dir = {0, 1, 0};
    const DVec3 origin = target + glm::normalize(from_dir) * (glm::length(size) + rng.uniform(1, 30));
    geometry::Ray ray;
    ray.origin = Vec3(origin);
    ray.direction = glm::normalize(Vec3(target) - ray.origin);
    ray.max_distance = 100.0f;
    return ray;
}

// An upright player capsule core (radius 1, segment 1 long) placed at random within 3 units of the brush's
// bounds, as float like the game's.
struct CapsulePlacement {
    Vec3 p0, p1;
    float radius = 1.0f;
};
inline CapsulePlacement capsule_near(Rng& rng, const brush::Brush& b) {
    const DVec3 lo = b.bounds_min() - DVec3(3.0), hi = b.bounds_max() + DVec3(3.0);
    const Vec3 c(lo + DVec3(rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0, 1)) * (hi - lo));
    return {c - Vec3(0, 0.5f, 0), c + Vec3(0, 0.5f, 0), 1.0f};
}

} // namespace ks::physics::brush_scenes
