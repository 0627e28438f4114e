// The two ray traversal kernels (portable SSE2 / plain C++, and AVX2 chosen at run time) must return the
// same hits, bit for bit, and both must agree with the double-precision reference. Every test here runs
// each kernel the CPU has, so a machine without AVX2 still tests the portable path and one with AVX2 tests
// both; the kernel in use is restored afterwards.
#include "bench/physics/ray_reference.h"
#include "bench/physics/scenes.h"
#include "physics/world.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

using namespace ks;
using namespace ks::physics;

namespace {

struct KernelScope { // restores the kernel in use when the test ends
    RayKernel saved = ray_kernel();
    ~KernelScope() { set_ray_kernel(saved); }
};

std::vector<RayKernel> available_kernels() {
    std::vector<RayKernel> k{RayKernel::Portable};
    if (cpu_has_avx2()) k.push_back(RayKernel::Avx2);
    return k;
}

// Random rays from the rooms plus rays aimed exactly at box corners and edge midpoints, lying in face
// planes and starting on faces: the traversal's slab tests are on their boundary there.
std::vector<geometry::Ray> test_rays(const scenes::RoomsScene& scene, int random_rays, std::uint64_t seed) {
    Rng rng(seed);
    std::vector<geometry::Ray> rays;
    for (int i = 0; i < random_rays; ++i)
        rays.push_back({scenes::random_origin(scene, rng), scenes::random_direction(rng), 100.0f});
    for (std::size_t bi = 0; bi < scene.boxes.size(); bi += 3) {
        const auto& b = scene.boxes[bi];
        const Quat q = b.rotation();
        for (int k = 0; k < 8; ++k) {
            const Vec3 corner =
                b.centre + q * (b.half * Vec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1));
            const Vec3 edge = b.centre + q * (b.half * Vec3(k & 1 ? 1 : -1, 0, k & 4 ? 1 : -1));
            for (const Vec3& target : {corner, edge}) {
                const Vec3 o = target + scenes::random_direction(rng) * rng.uniform(0.5f, 30.0f);
                rays.push_back({o, glm::normalize(target - o), 100.0f});
            }
        }
        for (int axis = 0; axis < 3; ++axis) {
            Vec3 n(0.0f);
            n[axis] = 1.0f;
            const Vec3 face = b.centre + q * (n * b.half[axis]);
            const Vec3 tangent = q * glm::normalize(glm::cross(n, Vec3(0.3f, 0.5f, 0.7f)));
            rays.push_back({face - tangent * 10.0f, tangent, 100.0f}); // in the face plane
            rays.push_back({face, q * n, 100.0f});                     // on the face, leaving
            rays.push_back({face, -(q * n), 100.0f});                  // on the face, entering
        }
    }
    // Axis-parallel directions (zero components: the traversal's inverse direction is 1e30 there).
    for (int i = 0; i < 600; ++i) {
        Vec3 d(0.0f);
        d[i % 3] = (i / 3) % 2 ? 1.0f : -1.0f;
        rays.push_back({scenes::random_origin(scene, rng), d, 100.0f});
    }
    return rays;
}

struct Answer {
    bool hit = false;
    RayHit h;
    bool any = false;
};

std::vector<Answer> cast_all(const World& w, const std::vector<geometry::Ray>& rays) {
    std::vector<Answer> out(rays.size());
    for (std::size_t i = 0; i < rays.size(); ++i) {
        out[i].hit = w.ray_closest(rays[i], out[i].h);
        out[i].any = w.ray_any(rays[i]);
    }
    return out;
}

bool same_bits(float a, float b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

} // namespace

TEST_CASE("ray kernels: forcing AVX2 is refused without the CPU feature; the portable kernel always works") {
    KernelScope scope;
    CHECK(set_ray_kernel(RayKernel::Portable));
    CHECK(ray_kernel() == RayKernel::Portable);
    CHECK(set_ray_kernel(RayKernel::Avx2) == cpu_has_avx2());
    CHECK(ray_kernel() == (cpu_has_avx2() ? RayKernel::Avx2 : RayKernel::Portable));
}

TEST_CASE("ray kernels: portable and AVX2 traversal give bit-identical hits (distance, body, normal)") {
    KernelScope scope;
    const auto scene = scenes::make_rooms(2000, 17);
    World w;
    scenes::add_to_world(scene, w);
    const auto rays = test_rays(scene, 20000, 3);
    std::vector<std::vector<Answer>> answers;
    for (RayKernel k : available_kernels()) {
        REQUIRE(set_ray_kernel(k));
        answers.push_back(cast_all(w, rays));
    }
    MESSAGE("kernels compared: " << answers.size() << " (AVX2 available: " << cpu_has_avx2() << ")");
    int hits = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const Answer& a = answers[0][i];
        hits += a.hit;
        CHECK(a.any == a.hit);
        for (std::size_t k = 1; k < answers.size(); ++k) {
            const Answer& b = answers[k][i];
            CHECK(a.hit == b.hit);
            CHECK(a.any == b.any);
            if (!(a.hit && b.hit)) continue;
            CHECK(same_bits(a.h.distance, b.h.distance));
            CHECK(a.h.body == b.h.body);
            CHECK((same_bits(a.h.normal.x, b.h.normal.x) && same_bits(a.h.normal.y, b.h.normal.y) &&
                   same_bits(a.h.normal.z, b.h.normal.z)));
        }
    }
    CHECK(hits > static_cast<int>(rays.size()) * 9 / 10);
}

TEST_CASE("ray kernels: each kernel matches the double-precision reference, hard rays included") {
    KernelScope scope;
    const auto scene = scenes::make_rooms(2000, 23);
    World w;
    std::vector<BodyId> ids;
    scenes::add_to_world(scene, w, &ids);
    std::vector<reference::RefBox> ref;
    for (const auto& b : scene.boxes)
        ref.push_back({DVec3(b.centre), glm::dquat(b.rotation()), DVec3(b.half)});
    const auto rays = test_rays(scene, 5000, 8);
    for (RayKernel k : available_kernels()) {
        REQUIRE(set_ray_kernel(k));
        int mismatches = 0, boundary = 0;
        for (const geometry::Ray& r : rays) {
            RayHit h;
            const bool hit = w.ray_closest(r, h);
            const auto v = reference::judge(DVec3(r.origin), DVec3(r.direction), r.max_distance,
                                            hit ? int(h.body.index) : -1, h.distance, ref);
            mismatches += v == reference::Verdict::Mismatch;
            boundary += v == reference::Verdict::Boundary;
        }
        INFO("kernel " << (k == RayKernel::Avx2 ? "avx2" : "portable") << ", boundary cases " << boundary);
        CHECK(mismatches == 0);
    }
}

TEST_CASE("ray kernels: filters (layers, ignore, disabled bodies) act the same in both kernels") {
    KernelScope scope;
    const auto scene = scenes::make_rooms(300, 4);
    World w;
    std::vector<BodyId> ids;
    scenes::add_to_world(scene, w, &ids);
    // Disable every third box and give every fifth another layer: packets then mix lanes that pass and
    // lanes that do not.
    for (std::size_t i = 0; i < ids.size(); i += 3) w.set_enabled(ids[i], false);
    const auto rays = test_rays(scene, 3000, 12);
    for (RayKernel k : available_kernels()) {
        REQUIRE(set_ray_kernel(k));
        for (std::size_t i = 0; i < rays.size(); i += 7) {
            const geometry::Ray& r = rays[i];
            RayHit h;
            if (!w.ray_closest(r, h)) continue;
            const std::size_t hit_index = std::find(ids.begin(), ids.end(), h.body) - ids.begin();
            REQUIRE(hit_index < ids.size());
            CHECK(hit_index % 3 != 0); // disabled boxes are never hit
            // Ignoring the body hit: the next hit is at least as far (never the same body).
            RayHit next;
            if (w.ray_closest(r, next, {layer::kAll & ~layer::kTrigger, h.body})) {
                CHECK(next.body != h.body);
                CHECK(next.distance >= h.distance);
            }
            // A layer no box has: nothing.
            RayHit none;
            CHECK_FALSE(w.ray_closest(r, none, {layer::kCharacter}));
            CHECK_FALSE(w.ray_any(r, {layer::kCharacter}));
        }
        // Re-enabled boxes come back (the packet's lanes follow set_enabled).
        for (std::size_t i = 0; i < ids.size(); i += 3) w.set_enabled(ids[i], true);
        int disabled_hits = 0;
        for (std::size_t i = 0; i < rays.size(); i += 7) {
            RayHit h;
            if (w.ray_closest(rays[i], h))
                disabled_hits += (std::find(ids.begin(), ids.end(), h.body) - ids.begin()) % 3 == 0;
        }
        CHECK(disabled_hits > 0);
        for (std::size_t i = 0; i < ids.size(); i += 3) w.set_enabled(ids[i], false);
    }
}
