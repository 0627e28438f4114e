// Brush bodies in the world's static BVH: closest-hit rays over 300 brushes (near the origin and at
// +-10 000) against the double reference's nearest brush, any-hit and all-hit rays agreeing with it, and
// capsule overlaps against the reference distance.
#include "bench/physics/brush_reference.h"
#include "bench/physics/brush_scenes.h"
#include "physics_scene.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace ks;
using namespace ks::physics;
using namespace ks::physics_test;

TEST_CASE("a world of brushes: BVH ray queries and capsule overlaps agree with the double reference") {
    for (const bool far : {false, true}) {
        CAPTURE(far);
        Rng rng(far ? 77 : 76);
        World w;
        std::vector<brush::Brush> brushes;
        std::vector<BodyId> ids;
        const DVec3 base = far ? DVec3(9950, -9950, 9950) : DVec3(0.0);
        for (int k = 0; k < 300; ++k) {
            const DVec3 centre =
                base + DVec3(rng.uniform(-40, 40), rng.uniform(-40, 40), rng.uniform(-40, 40));
            brushes.push_back(brush_scenes::random_brush(rng, centre));
            ids.push_back(add_brush(w, brushes.back()));
        }
        int rays = 0, hits = 0, mismatches = 0, capsule_mismatches = 0;
        double worst = 0.0;
        for (int i = 0; i < 3000; ++i) {
            const brush::Brush& aimed = brushes[rng.below(static_cast<std::uint32_t>(brushes.size()))];
            geometry::Ray ray = brush_scenes::ray_at(rng, aimed);
            // Within 60 units a float distance is spaced by at most 3.8e-6; further out its own rounding
            // nears the 1e-5 asked of the shape (7.6e-6 spacing at 64-128 units).
            ray.max_distance = 60.0f;
            const DVec3 o = exact_double(ray.origin), d = exact_double(ray.direction);
            ++rays;
            RayHit hit;
            const bool fast = w.ray_closest(ray, hit);
            CHECK(fast == w.ray_any(ray));
            // The reference's nearest brush, shrunk by 1e-5 (what the ray must reach) and grown (what it
            // may).
            double nearest_shrunk = 1e30, nearest = 1e30;
            for (const brush::Brush& b : brushes) {
                const double t = reference::ray_brush(o, d, b, ray.max_distance, -1e-5);
                if (t >= 0.0) nearest_shrunk = std::min(nearest_shrunk, t);
                const double t0 = reference::ray_brush(o, d, b, ray.max_distance);
                if (t0 >= 0.0) nearest = std::min(nearest, t0);
            }
            if (!fast) {
                if (nearest_shrunk < 1e30) ++mismatches;
                continue;
            }
            ++hits;
            std::size_t index = 0;
            while (ids[index] != hit.body) ++index;
            const auto j =
                reference::judge_ray(o, d, ray.max_distance, true, hit.distance, brushes[index], 1e-5);
            worst = std::max(worst, j.error);
            if (j.mismatch || hit.distance > nearest_shrunk + 1e-5) ++mismatches;
            if (nearest < 1e30) CHECK(std::abs(hit.distance - nearest) < 1e-3);
            std::vector<RayHit> all;
            REQUIRE(w.ray_all(ray, all) >= 1);
            CHECK(all.front().body == hit.body);
            CHECK(all.front().distance == hit.distance);
        }
        for (int i = 0; i < 1000; ++i) {
            const brush::Brush& near_one = brushes[rng.below(static_cast<std::uint32_t>(brushes.size()))];
            const auto cap = brush_scenes::capsule_near(rng, near_one);
            std::vector<BodyId> found;
            w.overlap_capsule({cap.p0, cap.p1}, cap.radius, found);
            for (std::size_t k = 0; k < brushes.size(); ++k) {
                const double dist =
                    reference::segment_brush_distance(exact_double(cap.p0), exact_double(cap.p1), brushes[k]);
                const bool listed = std::find(found.begin(), found.end(), ids[k]) != found.end();
                // Within 1e-5 of touching either answer is right.
                if (std::abs(dist - cap.radius) > 1e-5 && listed != (dist < cap.radius)) ++capsule_mismatches;
            }
        }
        MESSAGE("place " << std::string(far ? "far" : "near") << ": " << rays << " rays over 300 brushes, "
                         << hits << " hits, worst " << worst << ", " << mismatches
                         << " mismatches; capsule overlaps: " << capsule_mismatches << " mismatches");
        CHECK(hits > 1500);
        CHECK(mismatches == 0);
        CHECK(capsule_mismatches == 0);
    }
}
