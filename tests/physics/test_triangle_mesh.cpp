// Static triangle meshes (physics/triangle_mesh.h): the capsule-against-triangle distance against the long
// double reference (bench/physics/mesh_reference.h) on random and hard cases (slivers, near-parallel
// segments, a capsule exactly on an edge or a corner, coordinates near 1e5, repeated and zero-area
// triangles); rays and shots against a concave mesh; the character walking up a ramp mesh and stopped by a
// mesh wall.
#include "bench/physics/mesh_reference.h"
#include "physics/triangle_mesh.h"
#include "physics_scene.h"
#include "test_support.h"

#include <array>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

using namespace ks;
using namespace ks::physics;
using namespace ks::physics_test;

namespace {

constexpr double kTolerance = 1e-5;

using Index = std::array<std::uint32_t, 3>;

struct Worst {
    double error = 0.0;
    int mismatches = 0, count = 0;
    void add(double e) {
        ++count;
        error = std::max(error, e);
        if (!(e <= kTolerance)) ++mismatches;
    }
};

// The production distance against the reference: the distance itself, each witness on its own shape, and
// the witnesses as far apart as the distance says.
double distance_error(const DVec3& p0, const DVec3& p1, const DVec3& a, const DVec3& b, const DVec3& c) {
    const SegmentTriangleDistance d = segment_triangle_distance(p0, p1, a, b, c);
    const double ref = reference::segment_triangle(p0, p1, a, b, c);
    return std::max({std::abs(d.distance - ref), reference::off_segment(d.on_segment, p0, p1),
                     reference::off_triangle(d.on_triangle, a, b, c),
                     std::abs(glm::length(d.on_segment - d.on_triangle) - d.distance)});
}

DVec3 random_point(std::mt19937& rng, double half) {
    std::uniform_real_distribution<double> u(-half, half);
    return {u(rng), u(rng), u(rng)};
}

// Inputs as the world has them: floats, taken exactly.
DVec3 as_float(const DVec3& v) {
    return exact_double(Vec3(v));
}

MeshBody make_mesh(const std::vector<DVec3>& vertices, const std::vector<Index>& triangles) {
    auto body = mesh_body(vertices, triangles, "test mesh");
    REQUIRE(body.ok());
    return std::move(*body);
}

BodyId add_mesh(World& w, const std::vector<DVec3>& vertices, const std::vector<Index>& triangles) {
    const MeshBody body = make_mesh(vertices, triangles);
    BodyDesc d;
    d.shape = body.shape;
    d.transform = body.transform;
    auto id = w.add(d, "test mesh");
    REQUIRE(id.ok());
    return *id;
}

// Two triangles per quad (a, b, c, d in order round it).
void add_quad(std::vector<DVec3>& v, std::vector<Index>& t, DVec3 a, DVec3 b, DVec3 c, DVec3 d) {
    const auto base = static_cast<std::uint32_t>(v.size());
    v.insert(v.end(), {a, b, c, d});
    t.push_back({base, base + 1, base + 2});
    t.push_back({base, base + 2, base + 3});
}

} // namespace

TEST_CASE("mesh contact: segment to triangle matches the long double reference on random cases") {
    std::mt19937 rng(27);
    Worst worst;
    for (int i = 0; i < test::iterations(1500, 0.25); ++i) {
        const DVec3 a = as_float(random_point(rng, 10)), b = as_float(random_point(rng, 10)),
                    c = as_float(random_point(rng, 10));
        const DVec3 p0 = as_float(random_point(rng, 12)), p1 = as_float(p0 + random_point(rng, 4));
        worst.add(distance_error(p0, p1, a, b, c));
    }
    INFO("worst error " << worst.error);
    CHECK(worst.mismatches == 0);
}

TEST_CASE("mesh contact: hard cases match the reference (slivers, near-parallel, on edges and corners)") {
    std::mt19937 rng(2701);
    Worst worst;
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < test::iterations(400, 0.25); ++i) {
        const DVec3 a = random_point(rng, 10), u = glm::normalize(random_point(rng, 1));
        DVec3 side = glm::normalize(glm::cross(u, random_point(rng, 1)));
        const double length = 1.0 + 20.0 * unit(rng);
        const DVec3 b = a + u * length;
        // Slivers: the third corner 1e-7..1e-3 off the long edge.
        const double thin = std::pow(10.0, -7.0 + 4.0 * unit(rng));
        const DVec3 c = a + u * (length * unit(rng)) + side * thin;
        const DVec3 p0 = random_point(rng, 12);
        worst.add(distance_error(p0, p0 + random_point(rng, 5), a, b, c));
        // Near-parallel: a segment along the long edge, tilted by 1e-9..1e-3 rad, at a small height.
        const DVec3 n = glm::normalize(glm::cross(b - a, c - a));
        const double tilt = std::pow(10.0, -9.0 + 6.0 * unit(rng)), height = 0.5 * unit(rng);
        const DVec3 q0 = a - u * 2.0 + n * height + side * (thin * 0.5);
        worst.add(distance_error(q0, q0 + (u + n * tilt) * (length + 4.0), a, b, c));
        worst.add(distance_error(q0, q0 + (u + side * tilt) * (length + 4.0), a, b, c));
        // A capsule of radius r exactly on the edge: the segment a radius off it, perpendicular to it.
        const DVec3 big_c = a + u * (length * 0.5) + side * length;
        const DVec3 out = -side; // in the plane, away from the triangle across the edge a-b
        const double r = 0.25 + unit(rng);
        const DVec3 on_edge = a + u * (length * unit(rng)) + out * r;
        worst.add(distance_error(on_edge - n, on_edge + n, a, b, big_c));
        const SegmentTriangleDistance d = segment_triangle_distance(on_edge - n, on_edge + n, a, b, big_c);
        worst.add(std::abs(d.distance - r));
        // ... and on a corner: straight out of it, away from the triangle.
        const DVec3 away = glm::normalize((a - b) + (a - big_c));
        worst.add(std::abs(
            segment_triangle_distance(a + away * r, a + away * (r + 3.0), a, b, big_c).distance - r));
    }
    INFO("worst error " << worst.error << " over " << worst.count);
    CHECK(worst.mismatches == 0);
}

TEST_CASE("mesh contact: near 1e5 from the origin the capsule's contact is as exact as at the origin") {
    std::mt19937 rng(99);
    Worst worst;
    for (int i = 0; i < test::iterations(300, 0.25); ++i) {
        const DVec3 far = DVec3(1e5, -7e4, 9.5e4) + random_point(rng, 1000);
        std::vector<DVec3> v = {far + random_point(rng, 8), far + random_point(rng, 8),
                                far + random_point(rng, 8)};
        const MeshBody body = make_mesh(v, {{0, 1, 2}});
        const Segment s{Vec3(far + random_point(rng, 10)), Vec3(far + random_point(rng, 10))};
        const float r = 0.8f;
        const auto& t = body.shape.mesh->triangles[0];
        // The reference in world coordinates: the float inputs as they are.
        const DVec3 pos = exact_double(body.transform.position);
        const double ref =
            reference::segment_triangle(exact_double(s.p0), exact_double(s.p1), pos + exact_double(t[0]),
                                        pos + exact_double(t[1]), pos + exact_double(t[2]));
        const auto c = collide_capsule_triangle(s, r, *body.shape.mesh, 0, body.transform, 1e6f);
        REQUIRE(c.has_value());
        if (ref > 1e-3)
            worst.add(std::abs((static_cast<double>(r) - ref) - static_cast<double>(c->penetration)));
        const auto whole = collide_capsule_mesh(s, r, *body.shape.mesh, body.transform, 1e6f);
        REQUIRE(whole.has_value());
        CHECK(whole->penetration == c->penetration);
    }
    INFO("worst error " << worst.error);
    CHECK(worst.count > 0);
    CHECK(worst.mismatches == 0);
}

TEST_CASE("mesh build: zero-area triangles are dropped and counted; repeated ones kept; bad input refused") {
    const std::vector<DVec3> v = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {2, 0, 0}, {0, 0, 0}};
    // A good one, a repeated corner, three collinear corners, the good one again.
    const MeshBody body = make_mesh(v, {{0, 1, 2}, {0, 1, 1}, {0, 1, 3}, {4, 0, 1}, {0, 1, 2}});
    CHECK(body.shape.mesh->dropped_degenerate == 3);
    CHECK(body.shape.mesh->triangles.size() == 2);
    const Segment s{Vec3(0.2f, 1.0f, 0.2f), Vec3(0.2f, 3.0f, 0.2f)};
    const auto c = collide_capsule_mesh(s, 1.5f, *body.shape.mesh, body.transform);
    REQUIRE(c.has_value());
    CHECK(c->penetration == doctest::Approx(0.5f).epsilon(1e-6));
    CHECK(c->normal.y == doctest::Approx(1.0f));

    auto none = mesh_body(v, std::vector<Index>{{0, 1, 3}}, "flat.glb");
    REQUIRE_FALSE(none.ok());
    CHECK(test::contains_text(none.error().message,
                              "flat.glb: no triangle with an area (1 degenerate dropped)"));
    auto out_of_range = mesh_body(v, std::vector<Index>{{0, 1, 9}}, "broken.glb");
    REQUIRE_FALSE(out_of_range.ok());
    CHECK(test::contains_text(out_of_range.error().message, "triangle 0 names vertex 9 of 5"));
    const std::vector<DVec3> nan = {{0, 0, 0}, {1, 0, 0}, {0, std::nan(""), 1}};
    CHECK_FALSE(mesh_body(nan, std::vector<Index>{{0, 1, 2}}, "nan.glb").ok());
    // The count is refused before a triangle is read: the storage is left unwritten (untouched pages).
    const std::unique_ptr<Index[]> storage(new Index[kMaxMeshTriangles + 1]);
    auto dense = mesh_body(v, std::span<const Index>(storage.get(), kMaxMeshTriangles + 1), "dense.glb");
    REQUIRE_FALSE(dense.ok());
    CHECK(test::contains_text(dense.error().message, "more than the 1000000 a collision mesh may have"));

    World w;
    BodyDesc d;
    d.shape = body.shape;
    d.motion = Motion::Kinematic;
    CHECK_FALSE(w.add(d, "moving mesh").ok());
}

TEST_CASE("mesh contact: a segment through a triangle is pushed out along the face on its midpoint's side") {
    const MeshBody body = make_mesh({{-5, 0, -5}, {5, 0, -5}, {0, 0, 5}}, {{0, 1, 2}});
    const auto c = collide_capsule_triangle({Vec3(0, -0.3f, 0), Vec3(0, 1.0f, 0)}, 0.5f, *body.shape.mesh, 0,
                                            body.transform);
    REQUIRE(c.has_value());
    CHECK(c->normal.y == doctest::Approx(1.0f));
    CHECK(c->penetration == doctest::Approx(0.8f)); // the radius plus the 0.3 below the plane
    const auto below = collide_capsule_triangle({Vec3(0, -1.0f, 0), Vec3(0, 0.2f, 0)}, 0.5f, *body.shape.mesh,
                                                0, body.transform);
    REQUIRE(below.has_value());
    CHECK(below->normal.y == doctest::Approx(-1.0f));
    CHECK(below->penetration == doctest::Approx(0.7f));
}

namespace {
// A U-shaped channel open upward and at both ends (x from -10 to 10): floor y = 0 from z = -2 to 2, walls
// at z = -2 and z = 2 up to y = 4. Concave: no hull has its inner faces.
void channel(std::vector<DVec3>& v, std::vector<Index>& t, DVec3 o) {
    add_quad(v, t, o + DVec3(-10, 0, -2), o + DVec3(10, 0, -2), o + DVec3(10, 0, 2), o + DVec3(-10, 0, 2));
    add_quad(v, t, o + DVec3(-10, 0, -2), o + DVec3(10, 0, -2), o + DVec3(10, 4, -2), o + DVec3(-10, 4, -2));
    add_quad(v, t, o + DVec3(-10, 0, 2), o + DVec3(10, 0, 2), o + DVec3(10, 4, 2), o + DVec3(-10, 4, 2));
}
} // namespace

TEST_CASE("mesh rays: a shot inside a concave mesh hits its inner face; line of sight over it is clear") {
    for (const DVec3 origin : {DVec3(0.0), DVec3(3e4, 10, -2e4)}) {
        World w;
        std::vector<DVec3> v;
        std::vector<Index> t;
        channel(v, t, origin);
        const BodyId mesh = add_mesh(w, v, t);
        const Vec3 o(origin);
        RayHit hit;
        // From inside the channel toward its far wall: the inner face of the z = 2 wall.
        REQUIRE(w.ray_closest({o + Vec3(3, 2, -1), Vec3(0, 0, 1), 100.0f}, hit));
        CHECK(hit.body == mesh);
        CHECK(hit.distance == doctest::Approx(3.0f).epsilon(1e-5));
        CHECK(hit.normal.z == doctest::Approx(-1.0f));
        // Down onto the floor between the walls.
        REQUIRE(w.ray_closest({o + Vec3(-4, 3, 0.5f), Vec3(0, -1, 0), 100.0f}, hit));
        CHECK(hit.distance == doctest::Approx(3.0f).epsilon(1e-5));
        CHECK(hit.normal.y == doctest::Approx(1.0f));
        // Along the open channel: nothing (a hull would block it); above the walls: clear.
        CHECK_FALSE(w.ray_any({o + Vec3(-20, 2, 0), Vec3(1, 0, 0), 40.0f}));
        CHECK_FALSE(w.ray_any({o + Vec3(0, 5, -10), Vec3(0, 0, 1), 20.0f}));
        // Through the outer side of a wall: its outer face, the normal facing the ray.
        REQUIRE(w.ray_closest({o + Vec3(0, 2, -10), Vec3(0, 0, 1), 20.0f}, hit));
        CHECK(hit.distance == doctest::Approx(8.0f).epsilon(1e-5));
        CHECK(hit.normal.z == doctest::Approx(-1.0f));
        std::vector<RayHit> all;
        CHECK(w.ray_all({o + Vec3(0, 2, -10), Vec3(0, 0, 1), 20.0f}, all) == 1); // one per body
        std::vector<BodyId> touching;
        CHECK(w.overlap_capsule({o + Vec3(0, 1.5f, 1.6f), o + Vec3(0, 2.5f, 1.6f)}, 0.5f, touching) == 1);
    }
}

TEST_CASE("mesh character: up a ramp mesh as up the stair wedge, and stopped by a mesh wall") {
    // The main level's stair ramp (half size (6, 3, 6) at (-4, 3, -72), rising toward -z) as triangles.
    auto ramp = [](World& w) {
        std::vector<DVec3> v;
        std::vector<Index> t;
        add_quad(v, t, {-10, 0, -66}, {2, 0, -66}, {2, 6, -78}, {-10, 6, -78}); // the slope
        add_quad(v, t, {-10, 0, -78}, {2, 0, -78}, {2, 6, -78}, {-10, 6, -78}); // its back
        add_mesh(w, v, t);
        add_box(w, {-4, 3, -90}, {12, 3, 12});
    };
    for (int hz : {60, 240}) {
        World mesh_world(at_rate(hz)), wedge_world(at_rate(hz));
        add_floor(mesh_world), add_floor(wedge_world);
        ramp(mesh_world);
        add_main_stairs(wedge_world);
        const BodyId a = add_player(mesh_world, {-4, 0, -60}), b = add_player(wedge_world, {-4, 0, -60});
        float worst = 0.0f;
        for (int i = 0; i < 4 * hz; ++i) {
            for (World* w : {&mesh_world, &wedge_world}) {
                auto& m = w->character(w == &mesh_world ? a : b).movement;
                m.velocity.x = 0.0f, m.velocity.z = -8.0f;
                w->step(1.0f / hz);
            }
            worst = std::max(worst, std::abs(feet_y(mesh_world, a) - feet_y(wedge_world, b)));
        }
        INFO(hz << " Hz: feet differ by up to " << worst);
        CHECK(feet_y(mesh_world, a) == doctest::Approx(6.0f).epsilon(1e-2));
        CHECK(mesh_world.character(a).grounded);
        CHECK(worst < 1e-3f); // the same heights as on the wedge
    }
    // A wall: a vertical quad at x = 5; the capsule stops a radius and the skin short of it.
    World w(at_rate(120));
    add_floor(w);
    std::vector<DVec3> v;
    std::vector<Index> t;
    add_quad(v, t, {5, 0, -10}, {5, 0, 10}, {5, 6, 10}, {5, 6, -10});
    const BodyId wall = add_mesh(w, v, t);
    const BodyId p = add_player(w, {0, 0, 0});
    bool touched = false;
    w.set_on_collision(p, [&](World&, const Collision& c) { touched = touched || c.other == wall; });
    for (int i = 0; i < 240; ++i) {
        w.character(p).movement.velocity = {20.0f, w.character(p).movement.velocity.y, 3.0f};
        w.step(1.0f / 120.0f);
    }
    CHECK(w.transform(p).position.x == doctest::Approx(5.0f - kPlayerRadius - 0.01f).epsilon(1e-4));
    CHECK(w.transform(p).position.z > 5.0f); // slid along it
    CHECK(w.character(p).grounded);
    CHECK(touched);
}
