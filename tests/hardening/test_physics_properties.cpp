// Randomized property tests of the physics module through its public API (issue 8, item 3). Every case
// is drawn from a fixed-seed Rng, so a failure reproduces exactly; the failing case's inputs are printed.
//   1. finite in, finite out: no query returns NaN for any finite input; NaN/inf input gets a clear answer
//   2. no tunnelling below the documented speed limit (docs/performance.md: 400 u/s, 15-240 Hz)
//   3. SAT agrees with a double-precision separating-axis search and with independent witnesses
//   4. capsule contacts agree with exact double segment distances
//   5. ray casts agree with a double-precision reference (single shapes, and a whole level's BVH)
// Disagreements inside a thin band around the boundary (a ray grazing an edge, shapes touching to within
// 1e-4) are decided by float rounding of the inputs; they are counted and bounded, never ignored outright.
#include "bench/physics/ray_reference.h"
#include "bench/physics/scenes.h"
#include "hardening/physics_reference.h"
#include "physics/collide.h"
#include "physics/ray.h"
#include "physics/world.h"

#include "core/random.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace ks::physics {
namespace {

namespace ref = ks::test::physref;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

bool finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
// A normalised vector is unit to ~1e-7; 1e-3 is the bar. Capsule contact normals once missed it far from
// the origin (fixed: the regression cases at the end of this file keep their inputs); g_loose_normals counts
// the cases beyond the bar, and every one of them fails the test.
int g_loose_normals = 0;
bool unit(const Vec3& v, float tolerance = 1e-3f) {
    return finite(v) && std::abs(glm::length(v) - 1.0f) < tolerance;
}
bool contact_unit(const Vec3& v) {
    if (unit(v)) return true;
    ++g_loose_normals;
    return false;
}
std::string str(const Vec3& v) {
    std::ostringstream s;
    s.precision(9);
    s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return s.str();
}

Vec3 random_unit(Rng& rng) {
    for (;;) {
        const Vec3 v(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
        const float l = glm::length(v);
        if (l > 0.1f && l <= 1.0f) return v / l;
    }
}

Quat random_rotation(Rng& rng) {
    Vec4 q;
    do {
        q = Vec4(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    } while (glm::length(q) < 0.1f || glm::length(q) > 1.0f);
    q = glm::normalize(q);
    return Quat(q.w, q.x, q.y, q.z);
}

// Rotations a level really has (a quarter of them), else any rotation.
Quat scene_rotation(Rng& rng) {
    const float r = rng.uniform();
    if (r < 0.15f) return Quat(1, 0, 0, 0);
    if (r < 0.3f) return glm::angleAxis(rng.uniform(0.0f, 2.0f * kPi), Vec3(0, 1, 0));
    return random_rotation(rng);
}

Vec3 random_half(Rng& rng, float lo = 0.05f, float hi = 5.0f) {
    return {rng.uniform(lo, hi), rng.uniform(lo, hi), rng.uniform(lo, hi)};
}

// A random convex hull of 6-24 points (an ellipsoid's surface, some on a flat cut), or a box/wedge.
Polyhedron random_polyhedron(Rng& rng, const char*& kind) {
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

// ---------------------------------------------------------------------------------------------------------
// 1. Finite in, finite out.

void check_hit(bool hit, const ShapeHit& h, const geometry::Ray& ray, const char* what, int i) {
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
Vec3 awkward_direction(Rng& rng) {
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

TEST_CASE("physics properties: every query is finite for random finite input") {
    Rng rng(0x5eed0001);
    int hits = 0, contacts = 0;
    for (int i = 0; i < 4000; ++i) {
        const char* kind = "";
        const Polyhedron poly = random_polyhedron(rng, kind);
        const float scale = rng.chance(0.1f) ? 1e4f : 100.0f; // a level spans hundreds; far out too
        const geometry::Transform xf{
            {rng.uniform(-scale, scale), rng.uniform(-scale, scale), rng.uniform(-scale, scale)},
            scene_rotation(rng)};
        const Vec3 half = random_half(rng);
        // Rays from near the shape (often inside or on it) and from far away, aimed at it or anywhere.
        geometry::Ray ray;
        ray.origin = xf.position + random_unit(rng) * rng.uniform(0.0f, rng.chance(0.5f) ? 3.0f : 60.0f);
        ray.direction =
            rng.chance(0.5f)
                ? awkward_direction(rng)
                : glm::normalize(xf.position + random_unit(rng) * 2.0f - ray.origin + Vec3(1e-3f, 0, 0));
        ray.max_distance = rng.chance(0.1f) ? 1e30f : rng.uniform(0.0f, 200.0f);
        ShapeHit h;
        const bool b = ray_box(ray, half, xf, h);
        check_hit(b, h, ray, "ray_box", i);
        const bool p = ray_polyhedron(ray, poly, xf, h);
        check_hit(p, h, ray, kind, i);
        const Vec3 up(0, rng.uniform(0.0f, 2.0f), 0); // a zero-length core is a sphere
        const bool c = ray_capsule(ray, xf.position - up, xf.position + up, half.x, h);
        check_hit(c, h, ray, "ray_capsule", i);
        const bool y = ray_cylinder(ray, xf.position, half.x, half.y, h);
        check_hit(y, h, ray, "ray_cylinder", i);
        hits += b + p + c + y;

        // Narrowphase against a second shape nearby.
        const char* kind_b = "";
        const Polyhedron other = random_polyhedron(rng, kind_b);
        const geometry::Transform xb{xf.position + random_unit(rng) * rng.uniform(0.0f, 6.0f), random_rotation(rng)};
        if (auto k = collide_convex(poly, xf, other, xb)) {
            INFO("collide_convex " << kind << "/" << kind_b << " case " << i);
            REQUIRE(unit(k->normal));
            REQUIRE(std::isfinite(k->penetration));
            REQUIRE(k->penetration >= 0.0f);
            REQUIRE(finite(k->point));
            ++contacts;
        }
        const Segment s{xb.position, xb.position + Vec3(0, rng.uniform(0.0f, 3.0f), 0)};
        const float r = rng.uniform(0.05f, 2.0f);
        const SegmentDistance sd = segment_polyhedron_distance(s, poly, xf);
        REQUIRE(std::isfinite(sd.distance));
        REQUIRE(sd.distance >= 0.0f);
        REQUIRE((finite(sd.on_segment) && finite(sd.on_shape)));
        const Shape shapes[] = {Shape::box(half), Shape::capsule(half.x, half.y),
                                Shape::cylinder(half.x, half.z), Shape::wedge(half)};
        for (const Shape& shape : shapes) {
            const float margin = rng.chance(0.5f) ? 0.0f : 0.1f;
            geometry::Transform sx = xf;
            if (shape.kind == ShapeKind::Capsule || shape.kind == ShapeKind::Cylinder)
                sx.rotation = Quat(1, 0, 0, 0);
            if (auto k = collide_capsule_shape(s, r, shape, sx, margin)) {
                INFO("collide_capsule_shape kind "
                     << static_cast<int>(shape.kind) << " case " << i << ": core " << str(s.p0) << "-"
                     << str(s.p1) << " radius " << r << ", shape at " << str(sx.position)
                     << " rotation (w, x, y, z) " << sx.rotation.w << ", "
                     << str(Vec3(sx.rotation.x, sx.rotation.y, sx.rotation.z)) << " half " << str(half)
                     << ", normal " << str(k->normal) << " depth " << k->penetration);
                REQUIRE(contact_unit(k->normal));
                REQUIRE(std::isfinite(k->penetration));
                REQUIRE(k->penetration >= -margin - 1e-4f);
                REQUIRE(finite(k->point));
                ++contacts;
            }
        }
        // Closest points of segments, degenerate ones (points, parallel, collinear) included.
        Vec3 q0 = s.p0 + random_unit(rng), q1 = rng.chance(0.3f) ? q0 : q0 + random_unit(rng) * 2.0f;
        if (rng.chance(0.2f)) q1 = q0 + (s.p1 - s.p0); // parallel
        float ps = -1, pt = -1;
        closest_segment_segment(s.p0, s.p1, q0, q1, ps, pt);
        REQUIRE((ps >= 0.0f && ps <= 1.0f && pt >= 0.0f && pt <= 1.0f));
    }
    MESSAGE(hits << " ray hits and " << contacts << " contacts checked finite; " << g_loose_normals
                 << " contact normals off unit length by more than 1e-3");
    g_loose_normals = 0;
    CHECK(hits > 4000);
    CHECK(contacts > 2000);
}

TEST_CASE("physics properties: NaN and infinite input get a clear answer, never NaN out") {
    const Vec3 nans[] = {Vec3(kNaN, 0, 0), Vec3(0, kInf, 0), Vec3(0, 0, -kInf), Vec3(kNaN)};
    const geometry::Transform xf{{0, 0, -5}, Quat(1, 0, 0, 0)};
    const Polyhedron box = make_box_polyhedron(Vec3(1));
    for (const Vec3& bad : nans) {
        INFO("bad value " << str(bad));
        for (int which = 0; which < 3; ++which) {
            geometry::Ray ray{{0, 0, 0}, {0, 0, -1}, 100.0f};
            if (which == 0) ray.origin = bad;
            if (which == 1) ray.direction = bad;
            if (which == 2) ray.max_distance = bad.x + bad.y + bad.z;
            ShapeHit h;
            // Either no hit or a finite one: a NaN distance would poison the caller's nearest-hit logic.
            auto clear = [&](const char* name, bool hit) {
                INFO(std::string(name)
                     << " with the bad value in "
                     << std::string(which == 0   ? "origin"
                                    : which == 1 ? "direction"
                                                 : "max_distance")
                     << ": hit " << hit << " at " << h.distance << " normal " << str(h.normal));
                CHECK((!hit || (std::isfinite(h.distance) && finite(h.normal))));
            };
            clear("ray_box", ray_box(ray, Vec3(1), xf, h));
            clear("ray_polyhedron", ray_polyhedron(ray, box, xf, h));
            clear("ray_capsule", ray_capsule(ray, {0, 0, -5}, {0, 1, -5}, 1.0f, h));
            clear("ray_cylinder", ray_cylinder(ray, {0, 0, -5}, 1.0f, 1.0f, h));
        }
        // Shapes and bodies with NaN or infinite numbers are refused with an error naming them.
        CHECK_FALSE(Shape::box(bad).validate("crate").ok());
        World world;
        BodyDesc desc;
        desc.shape = Shape::box(Vec3(1));
        desc.transform.position = bad;
        auto added = world.add(desc, "entities[7] (crate)");
        REQUIRE_FALSE(added.ok());
        CHECK(added.error().message.find("entities[7]") != std::string::npos);
    }

    // A world with a floor, a wall and a character fed NaN and infinite velocities, steps and queries.
    World world;
    BodyDesc floor;
    floor.shape = Shape::box({50, 0.5f, 50});
    floor.transform.position = {0, -0.5f, 0};
    REQUIRE(world.add(floor, "floor").ok());
    BodyDesc wall;
    wall.shape = Shape::box({0.25f, 5, 10});
    wall.transform.position = {5, 5, 0};
    REQUIRE(world.add(wall, "wall").ok());
    BodyDesc player;
    player.shape = Shape::capsule(1.0f, 0.5f);
    player.motion = Motion::Character;
    player.transform.position = {0, 1.6f, 0};
    auto me = world.add(player, "player");
    REQUIRE(me.ok());
    for (const Vec3& bad : nans) {
        world.character(*me).movement.velocity = bad;
        world.character(*me).movement.acceleration = bad;
        world.step(1.0f / 120.0f);
        world.step(kNaN);
        world.step(-1.0f);
        world.advance(kNaN);
        world.advance(kInf);
        world.advance(1.0 / 60.0);
        const Vec3 at = world.transform(*me).position;
        INFO("after velocity " << str(bad) << " the character is at " << str(at));
        REQUIRE(finite(at));
        CHECK(at.y > 0.0f); // still standing on the floor
        world.character(*me).movement.acceleration = Vec3(0.0f);
        RayHit hit;
        CHECK_FALSE(world.ray_closest({bad, {1, 0, 0}, 100.0f}, hit));
        CHECK_FALSE(world.ray_closest({{0, 1, 0}, bad, 100.0f}, hit));
        CHECK_FALSE(world.ray_any({bad, {1, 0, 0}, 100.0f}));
        std::vector<RayHit> hits;
        CHECK(world.ray_all({{0, 1, 0}, bad, 100.0f}, hits) == 0);
        std::vector<BodyId> overlaps;
        world.overlap_capsule({bad, bad}, 1.0f, overlaps); // any answer but a crash; no NaN to check
    }
    // The character still works afterwards.
    world.character(*me).movement.velocity = {10, 0, 0};
    for (int i = 0; i < 120; ++i) world.step(1.0f / 120.0f);
    const Vec3 at = world.transform(*me).position;
    CHECK(at.x > 2.0f);
    CHECK(at.x < 5.0f - 0.25f - 1.0f + 1e-3f); // stopped by the wall
}

// ---------------------------------------------------------------------------------------------------------
// 2. Tunnelling. docs/performance.md: the swept controller lets nothing through a 5 cm wall at any speed up
// to 400 u/s and any frame rate from 15 to 240 Hz. Here: random thin walls (5 cm - 1 m, any yaw), capsules
// of radius 0.25-1, approach angles up to 60°, speeds up to 400 u/s, step rates 15-240 Hz. The capsule's
// centre must never pass the wall's near face minus its radius (beyond a slack of the skin plus rounding).

TEST_CASE("physics properties: no tunnelling through thin walls up to 400 u/s at 15-240 Hz") {
    Rng rng(0x5eed0002);
    int trials = 0, blocked = 0;
    double worst_depth = -1e9;
    for (int i = 0; i < 600; ++i) {
        const float fps = std::array{15.0f, 30.0f, 60.0f, 120.0f, 240.0f}[rng.below(5)];
        const float dt = 1.0f / fps;
        const float speed = rng.chance(0.3f) ? 400.0f : rng.uniform(1.0f, 400.0f);
        const float radius = rng.uniform(0.25f, 1.0f);
        const float half_thickness = rng.uniform(0.025f, 0.5f);
        const float yaw = rng.uniform(0.0f, 2.0f * kPi);
        const Quat rot = glm::angleAxis(yaw, Vec3(0, 1, 0));
        const Vec3 normal = rot * Vec3(-1, 0, 0); // the side the character comes from
        const Vec3 along = rot * Vec3(0, 0, 1);
        const Vec3 wall_at(rng.uniform(-300, 300), 0, rng.uniform(-300, 300));

        World world(WorldSettings{dt, 240});
        BodyDesc wall;
        wall.shape = Shape::box({half_thickness, 5, 2000}); // too long to slide off its end
        wall.transform = {wall_at, rot};
        REQUIRE(world.add(wall, "wall").ok());
        const float gap = rng.uniform(0.05f, 5.0f);
        const float angle = rng.uniform(-1.047f, 1.047f);
        const Vec3 dir = -normal * std::cos(angle) + along * std::sin(angle);
        BodyDesc body;
        body.shape = Shape::capsule(radius, 0.5f);
        body.motion = Motion::Character;
        body.transform.position = wall_at + normal * (half_thickness + radius + gap);
        body.movement.gravity = 0.0f;
        body.movement.max_speed = 1e4f;
        auto me = world.add(body, "mover");
        REQUIRE(me.ok());
        // Long enough to reach the wall and push on it for a few steps.
        const float travel = gap + 3.0f;
        const int steps = static_cast<int>(std::ceil(travel / (speed * std::cos(angle)) / dt)) + 4;
        double deepest = -1e9;
        for (int k = 0; k < steps; ++k) {
            world.character(*me).movement.velocity = dir * speed;
            world.step(dt);
            const Vec3 p = world.transform(*me).position;
            REQUIRE(finite(p));
            // How far the capsule's surface is past the wall's near face (> 0: inside or through).
            deepest = std::max(deepest,
                               static_cast<double>(half_thickness + radius - glm::dot(p - wall_at, normal)));
        }
        ++trials;
        worst_depth = std::max(worst_depth, deepest);
        const Vec3 end = world.transform(*me).position;
        blocked += glm::dot(end - wall_at, normal) > 0.0f;
        INFO("case " << i << ": " << fps << " Hz, " << speed << " u/s, radius " << radius << ", wall "
                     << 2 * half_thickness << " thick, angle " << angle << ", ends " << deepest
                     << " past the face");
        REQUIRE(deepest < 1e-3);
    }
    MESSAGE(trials << " trials, " << blocked << " ended on the near side; deepest penetration "
                   << worst_depth);
    CHECK(blocked == trials);
}

// ---------------------------------------------------------------------------------------------------------
// 3. SAT against references.

TEST_CASE("physics properties: SAT agrees with a double-precision axis search and with witnesses") {
    Rng rng(0x5eed0003);
    constexpr double kBand = 1e-4; // |separation| below this is a touching case either answer may give
    int pairs = 0, overlapping = 0, banded = 0, vertex_witnesses = 0, sampled_separations = 0;
    double worst_depth_error = 0;
    for (int i = 0; i < 5000; ++i) {
        const char *ka = "", *kb = "";
        const Polyhedron a = random_polyhedron(rng, ka), b = random_polyhedron(rng, kb);
        const geometry::Transform xa{{rng.uniform(-50, 50), rng.uniform(-5, 5), rng.uniform(-50, 50)},
                           scene_rotation(rng)};
        // Place b so that about half the pairs overlap: along a random direction, at a distance around
        // the sum of the bounding radii' typical support.
        const float ra = glm::length(a.bounds.max - a.bounds.min) * 0.5f;
        const float rb = glm::length(b.bounds.max - b.bounds.min) * 0.5f;
        const geometry::Transform xb{xa.position + random_unit(rng) * rng.uniform(0.0f, 0.9f * (ra + rb)),
                           scene_rotation(rng)};
        const auto fast = collide_convex(a, xa, b, xb);
        const ref::Planes pa = ref::planes_of(a, DVec3(xa.position), ref::to_double(xa.rotation));
        const ref::Planes pb = ref::planes_of(b, DVec3(xb.position), ref::to_double(xb.rotation));
        const ref::Separation sep = ref::separation(a, pa, b, pb);
        ++pairs;
        INFO("case " << i << ": " << ka << " at " << str(xa.position) << " vs " << kb << " at "
                     << str(xb.position) << ", reference separation " << sep.value);
        if (std::abs(sep.value) < kBand) {
            ++banded;
            continue;
        }
        REQUIRE(fast.has_value() == (sep.value < 0.0));
        if (!fast) continue;
        ++overlapping;
        // Depth: the minimal penetration over all axes (the fast path works in float at coordinates up to
        // 50, so a few 1e-5 of rounding).
        const double err = std::abs(fast->penetration - (-sep.value));
        worst_depth_error = std::max(worst_depth_error, err);
        CHECK(err < 1e-3 * (1.0 + std::abs(sep.value)));
        // The normal separates along its axis by the reported depth: moving A out by normal·(depth + 1e-3)
        // separates the pair in the reference.
        const geometry::Transform moved{xa.position + fast->normal * (fast->penetration + 2e-3f), xa.rotation};
        const ref::Planes moved_a = ref::planes_of(a, DVec3(moved.position), ref::to_double(moved.rotation));
        CHECK(ref::separation(a, moved_a, b, pb).value > 0.0);
    }
    // Independent witnesses on fresh pairs: a vertex of one deep inside the other means overlap; an axis
    // (random, not from either shape) that separates them by more than the band means no contact.
    for (int i = 0; i < 3000; ++i) {
        const char *ka = "", *kb = "";
        const Polyhedron a = random_polyhedron(rng, ka), b = random_polyhedron(rng, kb);
        const geometry::Transform xa{{0, 0, 0}, random_rotation(rng)};
        const float ra = glm::length(a.bounds.max - a.bounds.min) * 0.5f;
        const float rb = glm::length(b.bounds.max - b.bounds.min) * 0.5f;
        const geometry::Transform xb{random_unit(rng) * rng.uniform(0.0f, ra + rb), random_rotation(rng)};
        const auto fast = collide_convex(a, xa, b, xb);
        const ref::Planes pa = ref::planes_of(a, DVec3(xa.position), ref::to_double(xa.rotation));
        const ref::Planes pb = ref::planes_of(b, DVec3(xb.position), ref::to_double(xb.rotation));
        INFO("witness case " << i << ": " << ka << " vs " << kb << " at " << str(xb.position));
        bool inside = false;
        for (const DVec3& v : pa.vertices) inside |= ref::sd_planes(v, pb) < -1e-3;
        for (const DVec3& v : pb.vertices) inside |= ref::sd_planes(v, pa) < -1e-3;
        if (inside) {
            ++vertex_witnesses;
            REQUIRE(fast.has_value());
        }
        for (int k = 0; k < 32; ++k) {
            const DVec3 axis(random_unit(rng));
            double alo, ahi, blo, bhi;
            ref::project(pa.vertices, axis, alo, ahi);
            ref::project(pb.vertices, axis, blo, bhi);
            if (std::max(blo - ahi, alo - bhi) > 1e-3) {
                ++sampled_separations;
                REQUIRE_FALSE(fast.has_value());
                break;
            }
        }
    }
    MESSAGE(pairs << " pairs (" << overlapping << " overlapping, " << banded << " within " << kBand
                  << " of touching), worst depth error " << worst_depth_error
                  << "; witnesses: " << vertex_witnesses << " vertex-inside, " << sampled_separations
                  << " random-axis separations");
    CHECK(overlapping > 1000);
    CHECK(banded < pairs / 100);
    CHECK(vertex_witnesses > 500);
    CHECK(sampled_separations > 500);
}

// ---------------------------------------------------------------------------------------------------------
// 4. Capsules against exact distances.

TEST_CASE("physics properties: capsule contacts agree with exact double-precision distances") {
    Rng rng(0x5eed0004);
    constexpr double kBand = 1e-4;
    int cases = 0, contacts = 0, banded = 0;
    double worst = 0;
    for (int i = 0; i < 6000; ++i) {
        const Vec3 centre(rng.uniform(-100, 100), rng.uniform(-5, 5), rng.uniform(-100, 100));
        const float r = rng.uniform(0.1f, 1.5f);
        const Segment s{centre, centre + Vec3(0, rng.uniform(0.0f, 2.0f), 0)};
        const DVec3 a(s.p0), b(s.p1);
        const int which = static_cast<int>(rng.below(5));
        std::optional<Contact> fast;
        ref::Sdf sd;
        const char* what = "";
        const Vec3 at = centre + random_unit(rng) * rng.uniform(0.0f, 5.0f);
        if (which <= 1) { // box: yaw-only fast path, and any rotation through the polyhedron path
            const Vec3 half = random_half(rng, 0.05f, 3.0f);
            const Quat q =
                which == 0 ? glm::angleAxis(rng.uniform(0.0f, 6.3f), Vec3(0, 1, 0)) : random_rotation(rng);
            const geometry::Transform xf{at, q};
            what = which == 0 ? "collide_capsule_box (yaw)" : "collide_capsule_polyhedron (box)";
            fast = which == 0 ? collide_capsule_box(s, r, half, xf)
                              : collide_capsule_polyhedron(s, r, make_box_polyhedron(half), xf);
            const ref::DQuat dq = ref::to_double(q);
            sd = [=](const DVec3& p) { return ref::sd_box(p, DVec3(at), dq, DVec3(half)); };
        } else if (which == 2) {
            const Segment o{at, at + Vec3(0, rng.uniform(0.0f, 2.0f), 0)};
            const float ro = rng.uniform(0.1f, 1.5f);
            what = "collide_capsule_capsule";
            fast = collide_capsule_capsule(s, r, o, ro);
            sd = [=](const DVec3& p) { return ref::sd_capsule(p, DVec3(o.p0), DVec3(o.p1), ro); };
        } else if (which == 3) {
            const float cr = rng.uniform(0.1f, 2.0f), ch = rng.uniform(0.1f, 2.0f);
            what = "collide_capsule_cylinder";
            fast = collide_capsule_cylinder(s, r, at, cr, ch);
            sd = [=](const DVec3& p) { return ref::sd_cylinder(p, DVec3(at), cr, ch); };
        } else {
            const Vec3 half = random_half(rng, 0.1f, 3.0f);
            const Quat q = glm::angleAxis(rng.uniform(0.0f, 6.3f), Vec3(0, 1, 0));
            what = "collide_capsule_shape (wedge)";
            const Shape wedge = Shape::wedge(half);
            fast = collide_capsule_shape(s, r, wedge, {at, q});
            const ref::Planes planes = ref::planes_of(*wedge.polyhedron, DVec3(at), ref::to_double(q));
            // sd_planes is exact only inside; outside, the exact distance to the solid is what counts, so
            // compare only the verdict (inside the band it is not decided) and depths of core-touching cases.
            sd = [=](const DVec3& p) { return ref::sd_planes(p, planes); };
        }
        ++cases;
        const double d = ref::segment_distance(sd, a, b); // <= 0 when the core enters the solid
        INFO(std::string(what) << " case " << i << ": core " << str(s.p0) << "-" << str(s.p1) << " radius "
                               << r << ", reference core distance " << d);
        if (which == 4 && d > 0.0) { // a lower bound only: verdict when clearly apart, or clearly touching
            if (d > r + kBand) CHECK_FALSE(fast.has_value());
            continue;
        }
        if (std::abs(d - r) < kBand) {
            ++banded;
            continue;
        }
        REQUIRE(fast.has_value() == (d < r));
        if (!fast) continue;
        ++contacts;
        INFO("normal " << str(fast->normal) << " depth " << fast->penetration);
        REQUIRE(contact_unit(fast->normal));
        if (d > 1e-3) { // the core is outside: depth is exactly r - distance
            const double err = std::abs(fast->penetration - (r - d));
            worst = std::max(worst, err);
            CHECK(err < 2e-4 * (1.0 + r));
        } else {
            CHECK(fast->penetration >= r - 1e-3);
        }
    }
    MESSAGE(cases << " capsule cases, " << contacts << " contacts, " << banded << " within " << kBand
                  << " of touching, worst depth error " << worst << "; " << g_loose_normals
                  << " normals off unit length by more than 1e-3");
    g_loose_normals = 0;
    CHECK(contacts > 1500);
    CHECK(banded < cases / 100);
}

// ---------------------------------------------------------------------------------------------------------
// 5. Rays against the double reference.

TEST_CASE("physics properties: single-shape ray casts agree with a double-precision reference") {
    Rng rng(0x5eed0005);
    constexpr double kBand = 1e-4;
    int rays = 0, hits = 0, banded = 0;
    double worst = 0;
    for (int i = 0; i < 8000; ++i) {
        const int which = static_cast<int>(rng.below(5));
        const float scale = rng.chance(0.2f) ? 2000.0f : 50.0f;
        const Vec3 at(rng.uniform(-scale, scale), rng.uniform(-10, 10), rng.uniform(-scale, scale));
        const Vec3 half = random_half(rng, 0.05f, 4.0f);
        const Quat q =
            which == 0 ? scene_rotation(rng) : glm::angleAxis(rng.uniform(0.0f, 6.3f), Vec3(0, 1, 0));
        Shape shape;
        ref::Sdf sd;
        const ref::DQuat dq = ref::to_double(q);
        switch (which) {
        case 0:
            shape = Shape::box(half);
            sd = [=](const DVec3& p) { return ref::sd_box(p, DVec3(at), dq, DVec3(half)); };
            break;
        case 1: {
            shape = Shape::wedge(half);
            const ref::Planes planes = ref::planes_of(*shape.polyhedron, DVec3(at), dq);
            sd = [=](const DVec3& p) { return ref::sd_planes(p, planes); };
            break;
        }
        case 2: {
            const char* kind = "";
            shape = Shape::hull(random_polyhedron(rng, kind));
            const ref::Planes planes = ref::planes_of(*shape.polyhedron, DVec3(at), dq);
            sd = [=](const DVec3& p) { return ref::sd_planes(p, planes); };
            break;
        }
        case 3: {
            shape = Shape::capsule(half.x, half.y);
            const DVec3 up(0, half.y, 0);
            sd = [=](const DVec3& p) { return ref::sd_capsule(p, DVec3(at) - up, DVec3(at) + up, half.x); };
            break;
        }
        default:
            shape = Shape::cylinder(half.x, half.y);
            sd = [=](const DVec3& p) { return ref::sd_cylinder(p, DVec3(at), half.x, half.y); };
        }
        geometry::Ray ray;
        ray.origin = at + random_unit(rng) * rng.uniform(0.0f, rng.chance(0.2f) ? 3.0f : 40.0f);
        const Vec3 aim = at + random_unit(rng) * rng.uniform(0.0f, 5.0f);
        ray.direction =
            rng.chance(0.2f) ? awkward_direction(rng) : glm::normalize(aim - ray.origin + Vec3(0, 1e-4f, 0));
        ray.max_distance = rng.uniform(1.0f, 100.0f);
        ShapeHit h;
        const bool fast = ray_shape(ray, shape, {at, q}, h);
        const ref::RayResult want = ref::cast(sd, DVec3(ray.origin), DVec3(ray.direction), ray.max_distance);
        ++rays;
        INFO("shape " << which << " case " << i << ": at " << str(at) << " origin " << str(ray.origin)
                      << " dir " << str(ray.direction) << " max " << ray.max_distance << "; reference hit "
                      << want.hit << " at " << want.distance << " (min sd " << want.min_value << ", start sd "
                      << want.start_value << "), fast " << fast << " at " << h.distance);
        // Grazing rays, rays starting on the surface and hits right at max_distance are decided by
        // rounding: either answer is right.
        const bool grazing = std::abs(want.min_value) < kBand * (1.0 + scale * 1e-3) ||
                             std::abs(want.start_value) < kBand ||
                             (want.hit && std::abs(want.distance - ray.max_distance) < kBand * 10);
        if (fast != want.hit) {
            REQUIRE(grazing);
            ++banded;
            continue;
        }
        if (!fast) continue;
        ++hits;
        check_hit(fast, h, ray, "ray_shape", i);
        if (grazing) continue; // the entry point of a grazing ray is ill-conditioned
        const double err = std::abs(h.distance - want.distance);
        worst = std::max(worst, err);
        // Float relative precision at coordinates up to 2000, plus the entry's sensitivity to the angle.
        CHECK(err < 1e-3 + 1e-6 * glm::length(ray.origin));
    }
    MESSAGE(rays << " rays, " << hits << " hits, " << banded
                 << " boundary disagreements, worst distance error " << worst);
    CHECK(hits > 2000);
    CHECK(banded < rays / 200);
}

TEST_CASE("physics properties: world ray casts agree with brute force over a 2000-box level") {
    const scenes::RoomsScene scene = scenes::make_rooms(2000, 7);
    World world;
    std::vector<reference::RefBox> boxes;
    std::vector<BodyId> ids;
    for (const scenes::SceneBox& b : scene.boxes) {
        BodyDesc d;
        d.shape = Shape::box(b.half);
        d.transform = {b.centre, b.rotation()};
        auto id = world.add(d, "box");
        REQUIRE(id.ok());
        ids.push_back(*id);
        const Quat q = b.rotation();
        boxes.push_back({DVec3(b.centre), reference::DQuat(q.w, q.x, q.y, q.z), DVec3(b.half)});
    }
    Rng rng(0x5eed0006);
    int rays = 0, hits = 0, boundary = 0;
    for (int i = 0; i < 3000; ++i) {
        const scenes::Room& room = scene.rooms[rng.below(static_cast<std::uint32_t>(scene.rooms.size()))];
        geometry::Ray ray;
        ray.origin = {rng.uniform(room.min.x, room.max.x), rng.uniform(0.1f, 15.0f),
                      rng.uniform(room.min.z, room.max.z)};
        ray.direction = rng.chance(0.25f) ? awkward_direction(rng) : random_unit(rng);
        ray.max_distance = rng.chance(0.5f) ? 500.0f : rng.uniform(1.0f, 60.0f);
        RayHit hit;
        const bool got = world.ray_closest(ray, hit);
        int index = -1;
        if (got) {
            REQUIRE(finite(hit.point));
            REQUIRE(unit(hit.normal));
            for (std::size_t k = 0; k < ids.size(); ++k)
                if (ids[k] == hit.body) index = static_cast<int>(k);
            REQUIRE(index >= 0);
            ++hits;
        }
        const auto verdict = reference::judge(DVec3(ray.origin), DVec3(ray.direction), ray.max_distance,
                                              index, got ? hit.distance : -1.0, boxes);
        INFO("ray " << i << " origin " << str(ray.origin) << " dir " << str(ray.direction) << " max "
                    << ray.max_distance << ": fast hit box " << index << " at " << hit.distance);
        REQUIRE(verdict != reference::Verdict::Mismatch);
        boundary += verdict == reference::Verdict::Boundary;
        // ray_any agrees with ray_closest.
        REQUIRE(world.ray_any(ray) == got);
        ++rays;
    }
    MESSAGE(rays << " rays over " << boxes.size() << " boxes, " << hits << " hits, " << boundary
                 << " boundary cases (within 1e-4 of an edge)");
    CHECK(hits > rays / 2);
    CHECK(boundary < rays / 100);
}

// ---------------------------------------------------------------------------------------------------------
// Bugs the tests above found (both fixed), kept with their exact inputs as regression cases.

// common/physics/collide.cpp, from_distance(): the normal is (on_core - on_shape) / distance, where the two
// points are in world space (a polyhedron's are transformed there first) but `distance` was measured
// separately (in the shape's frame, or analytically for cylinders). Far from the origin the world-space
// difference has lost digits (float ulp is 5e-4 at 4000 and 1e-3 at 9000), so for a capsule core within a
// few tenths of the shape the "unit" normal is off by up to 12 %: random tests at 4000-9000 units find
// lengths 0.978, 1.0033, 1.117 (and 0.998 at 90 units with the core 3e-4 from a box). The character
// controller slides along these normals. Fixed: from_distance() now normalises a direction computed in the
// shape's frame (or analytically) by its own length.
TEST_CASE("regression: capsule contact normals are unit length far from the origin") {
    struct Case {
        const char* what;
        Segment core;
        float radius;
        Shape shape;
        geometry::Transform xf;
    };
    const Case cases[] = {
        {"cylinder at 9000 (random case 110)",
         {{6399.75635f, 9426.39062f, -8266.51855f}, {6399.75635f, 9427.81738f, -8266.51855f}},
         1.56919f,
         Shape::cylinder(0.69577682f, 4.40683222f),
         {{6399.29102f, 9423.65625f, -8265.89746f}, Quat(1, 0, 0, 0)}},
        {"cylinder at 9000 (random case 112)",
         {{-8558.91797f, -4386.16846f, 8802.70605f}, {-8558.91797f, -4384.67188f, 8802.70605f}},
         1.19873f,
         Shape::cylinder(0.472080231f, 2.13043857f),
         {{-8558.85938f, -4385.75146f, 8803.18359f}, Quat(1, 0, 0, 0)}},
        {"wedge at 4000 (random case 2095)",
         {{4101.1792f, 1897.94141f, -3684.61841f}, {4101.1792f, 1899.04846f, -3684.61841f}},
         1.39944f,
         Shape::wedge({3.00523663f, 1.5319277f, 2.20550776f}),
         {{4101.1582f, 1897.93262f, -3684.59717f},
          glm::normalize(Quat(-0.539067f, 0.0f, 0.842262805f, 0.0f))}},
    };
    for (const Case& c : cases) {
        const auto contact = collide_capsule_shape(c.core, c.radius, c.shape, c.xf);
        REQUIRE(contact.has_value());
        INFO(std::string(c.what) << ": normal " << str(contact->normal) << ", length "
                                 << glm::length(contact->normal));
        CHECK(unit(contact->normal));
    }
}

// common/physics/ray.cpp, ray_box(): a ray whose direction held a NaN or an infinity passed the slab test
// and was reported as starting inside (hit at distance 0) with the normal -direction, i.e. NaN or infinite.
// World's queries refuse such rays, so the game was not affected; a direct caller of ray_box was. Fixed:
// ray_box checks the direction first, like ray_polyhedron, ray_capsule and ray_cylinder in effect do.
TEST_CASE("regression: ray_box with a non-finite direction reports no hit") {
    for (const Vec3& bad : {Vec3(kNaN, 0, 0), Vec3(0, kInf, 0), Vec3(0, 0, -kInf), Vec3(kNaN)}) {
        const geometry::Ray ray{{0, 0, 0}, bad, 100.0f};
        ShapeHit h;
        const bool hit = ray_box(ray, Vec3(1), {{0, 0, -5}, Quat(1, 0, 0, 0)}, h);
        INFO("direction " << str(bad) << ": hit " << hit << " at " << h.distance << " normal "
                          << str(h.normal));
        CHECK_FALSE(hit);
    }
}

} // namespace
} // namespace ks::physics
