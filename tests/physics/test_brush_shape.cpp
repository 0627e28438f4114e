// Brushes as collision shapes (physics/brush_shape.h): the shape itself, a box brush against the same box,
// rays and player capsules against random brushes near the origin and at +-10 000 judged by the double
// reference (bench/physics/brush_reference.h), and the hard cases: a 1e-4 sliver, a face 1e-6 rad from flat,
// and rays through the shared edges and vertices of two brushes.
#include "bench/physics/brush_reference.h"
#include "bench/physics/brush_scenes.h"
#include "brush/brush_clip.h"
#include "physics/collide.h"
#include "physics/ray.h"
#include "physics_scene.h"

#include <algorithm>
#include <cmath>
#include <vector>

using namespace ks;
using namespace ks::physics;
using namespace ks::physics_test;

namespace {

constexpr double kTolerance = 1e-5;

// The capsule's distance to the shape as the character controller sees it (radius minus penetration).
double capsule_distance(const Segment& s, float r, const BrushBody& body) {
    const auto c = collide_capsule_shape(s, r, body.shape, body.transform, 100.0f);
    REQUIRE(c.has_value());
    return static_cast<double>(r) - static_cast<double>(c->penetration);
}

struct Tally {
    int rays = 0, ray_mismatches = 0, capsules = 0, capsule_mismatches = 0;
    double worst_ray = 0.0, worst_capsule = 0.0;
};

void judge_rays_and_capsules(Rng& rng, const brush::Brush& b, int count, Tally& tally) {
    const BrushBody body = brush_body(b);
    for (int i = 0; i < count; ++i) {
        const geometry::Ray ray = brush_scenes::ray_at(rng, b);
        ShapeHit hit;
        const bool fast = ray_shape(ray, body.shape, body.transform, hit);
        const auto j = reference::judge_ray(exact_double(ray.origin), exact_double(ray.direction),
                                            ray.max_distance, fast, hit.distance, b, kTolerance);
        ++tally.rays;
        tally.worst_ray = std::max(tally.worst_ray, j.error);
        if (j.mismatch) {
            ++tally.ray_mismatches;
            INFO("ray mismatch at " << ray.origin.x << ", " << ray.origin.y << ", " << ray.origin.z
                                    << " error " << j.error);
            CHECK_FALSE(j.mismatch);
        }
        const auto cap = brush_scenes::capsule_near(rng, b);
        const double e = reference::capsule_error(capsule_distance({cap.p0, cap.p1}, cap.radius, body),
                                                  exact_double(cap.p0), exact_double(cap.p1), b);
        ++tally.capsules;
        tally.worst_capsule = std::max(tally.worst_capsule, e);
        if (e > kTolerance) ++tally.capsule_mismatches;
    }
}

} // namespace

TEST_CASE("a brush shape: the brush's vertices, polygons and planes, placed at its float centre") {
    const brush::Brush b = box_brush({9990.5f, -10000, 9995}, {10, 0.25f, 5});
    const BrushBody body = brush_body(b);
    CHECK(body.transform.position == Vec3(9990.5f, -10000, 9995));
    CHECK(body.transform.rotation == Quat(1, 0, 0, 0));
    CHECK(body.shape.kind == ShapeKind::Hull);
    CHECK(body.shape.half_extents == Vec3(10, 0.25f, 5));
    CHECK(body.shape.validate("brush").ok());
    const Polyhedron& p = *body.shape.polyhedron;
    CHECK(p.vertices.size() == 8);
    CHECK(p.faces.size() == 6);
    CHECK(p.edges.size() == 12);
    CHECK(p.edge_directions.size() == 3);
    for (const auto& f : p.faces) {
        CHECK(f.count == 4);
        for (auto v : p.face_indices(f)) CHECK(glm::dot(f.normal, p.vertices[v]) == f.offset); // exact
    }
    // Counter-clockwise seen from outside, like every polyhedron of physics.
    for (const auto& f : p.faces) {
        auto idx = p.face_indices(f);
        const Vec3 n =
            glm::cross(p.vertices[idx[1]] - p.vertices[idx[0]], p.vertices[idx[2]] - p.vertices[idx[0]]);
        CHECK(glm::dot(n, f.normal) > 0.0f);
    }
}

TEST_CASE("a box brush behaves as the same box: ray hits and capsule contacts within 1e-5") {
    Rng rng(25);
    double worst_ray = 0.0, worst_turned = 0.0, worst_contact = 0.0;
    int hits = 0, contacts = 0;
    for (int k = 0; k < 200; ++k) {
        const bool far = k % 2 == 1;
        const Vec3 centre = Vec3(brush_scenes::random_far_centre(rng, far));
        const Vec3 half(rng.uniform(0.2f, 5), rng.uniform(0.2f, 5), rng.uniform(0.2f, 5));
        const float yaw_angle = k % 4 < 2 ? 0.0f : rng.uniform(-kPi, kPi);
        const geometry::Transform box_xf{centre, yaw(yaw_angle)};
        const Shape box = Shape::box(half);
        std::vector<DVec3> corners;
        for (int i = 0; i < 8; ++i)
            corners.push_back(DVec3(centre) + DVec3(box_xf.rotation * Vec3((i & 1) ? half.x : -half.x,
                                                                           (i & 2) ? half.y : -half.y,
                                                                           (i & 4) ? half.z : -half.z)));
        auto b = brush::make_from_points(corners);
        REQUIRE(b.ok());
        const BrushBody body = brush_body(*b);
        for (int i = 0; i < 40; ++i) {
            const geometry::Ray ray = brush_scenes::ray_at(rng, *b);
            ShapeHit a, c;
            const bool on_box = ray_shape(ray, box, box_xf, a),
                       on_brush = ray_shape(ray, body.shape, body.transform, c);
            if (on_box != on_brush) { // only a ray grazing an edge may differ: within 1e-5 of the box
                const auto j = reference::judge_ray(exact_double(ray.origin), exact_double(ray.direction),
                                                    ray.max_distance, on_brush, c.distance, *b, kTolerance);
                CHECK_FALSE(j.mismatch);
                continue;
            }
            if (!on_box) continue;
            ++hits;
            // The two entry points, measured across the face they lie on (along a grazing ray the entry moves
            // by the surface's error over the sine of the angle).
            const double e = std::abs((static_cast<double>(a.distance) - c.distance) *
                                      glm::dot(exact_double(ray.direction), exact_double(a.normal)));
            // Turned boxes: the box path turns the ray into the box frame in float, an error of its own (up
            // to 1.4e-5 against the double box, seen at yaw near 180°); the brush stays within 1e-5 of it.
            if (yaw_angle == 0.0f) {
                worst_ray = std::max(worst_ray, e);
                CHECK(e <= kTolerance);
            } else {
                worst_turned = std::max(worst_turned, e);
                CHECK(e <= 2.0 * kTolerance);
                CHECK_FALSE(reference::judge_ray(exact_double(ray.origin), exact_double(ray.direction),
                                                 ray.max_distance, true, c.distance, *b, kTolerance)
                                .mismatch);
            }
            if (a.distance > 0.0f) CHECK(glm::length(a.normal - c.normal) <= 1e-5f);
        }
        for (int i = 0; i < 40; ++i) {
            const auto cap = brush_scenes::capsule_near(rng, *b);
            const Segment s{cap.p0, cap.p1};
            const auto a = collide_capsule_shape(s, cap.radius, box, box_xf, 1.0f);
            const auto c = collide_capsule_shape(s, cap.radius, body.shape, body.transform, 1.0f);
            REQUIRE(a.has_value() == c.has_value());
            if (!a) continue;
            ++contacts;
            const double e = std::abs(static_cast<double>(a->penetration) - c->penetration);
            worst_contact = std::max(worst_contact, e);
            CHECK(e <= kTolerance);
            if (a->penetration < cap.radius - 1e-3f) CHECK(glm::length(a->normal - c->normal) <= 1e-4f);
        }
    }
    MESSAGE("box brush vs box: " << hits << " hits, worst entry difference across the face " << worst_ray
                                 << " (turned boxes " << worst_turned << ")"
                                 << "; " << contacts << " contacts, worst penetration difference "
                                 << worst_contact);
    CHECK(hits > 3000);
    CHECK(contacts > 1000);
}

TEST_CASE("random brushes near the origin and at +-10 000: 0 results beyond 1e-5 of the double reference") {
    Rng rng(2025);
    Tally tally;
    for (int k = 0; k < 400; ++k) {
        const brush::Brush b =
            brush_scenes::random_brush(rng, brush_scenes::random_far_centre(rng, k % 2 == 1));
        judge_rays_and_capsules(rng, b, 25, tally);
    }
    MESSAGE(tally.rays << " rays: worst " << tally.worst_ray << ", " << tally.ray_mismatches
                       << " beyond 1e-5; " << tally.capsules << " capsules: worst " << tally.worst_capsule
                       << ", " << tally.capsule_mismatches << " beyond 1e-5");
    CHECK(tally.rays == 10000);
    CHECK(tally.ray_mismatches == 0);
    CHECK(tally.capsule_mismatches == 0);
}

TEST_CASE("hard cases: a 1e-4 sliver and a roof 1e-6 rad from flat, at the origin and at +-10 000") {
    for (const DVec3 at : {DVec3(0.0), DVec3(9990, -10000, 9995), DVec3(-10000, 10000, -10000)}) {
        CAPTURE(at.x);
        auto sliver = brush::make_box(at + DVec3(-5, 0, -5), at + DVec3(5, 1e-4, 5));
        REQUIRE(sliver.ok());
        // A box whose top is two planes meeting in a ridge along z, each 1e-6 rad from flat.
        const double tilt = 1e-6;
        std::vector<brush::Face> faces;
        auto plane = [&](DVec3 n, DVec3 through) {
            n = glm::normalize(n);
            faces.push_back({{n, glm::dot(n, through)}, {}});
        };
        plane({-1, 0, 0}, at + DVec3(-4, 0, 0));
        plane({1, 0, 0}, at + DVec3(4, 0, 0));
        plane({0, -1, 0}, at + DVec3(0, -1, 0));
        plane({0, 0, -1}, at + DVec3(0, 0, -3));
        plane({0, 0, 1}, at + DVec3(0, 0, 3));
        plane({std::sin(tilt), std::cos(tilt), 0}, at + DVec3(0, 1, 0));
        plane({-std::sin(tilt), std::cos(tilt), 0}, at + DVec3(0, 1, 0));
        auto roof = brush::Brush::from_faces(faces);
        REQUIRE(roof.ok());
        CHECK(roof->vertices().size() == 10);
        Rng rng(5);
        Tally tally;
        for (const brush::Brush* b : std::initializer_list<const brush::Brush*>{&*sliver, &*roof}) {
            judge_rays_and_capsules(rng, *b, 1000, tally);
            // Straight down onto the top: the entry is where the planes say, to 1e-5.
            const BrushBody body = brush_body(*b);
            for (int i = 0; i < 200; ++i) {
                const DVec3 target =
                    b->bounds_min() + DVec3(rng.uniform(0.01f, 0.99f), 1.0, rng.uniform(0.01f, 0.99f)) *
                                          (b->bounds_max() - b->bounds_min());
                geometry::Ray ray{Vec3(target + DVec3(0, 10, 0)), {0, -1, 0}, 100.0f};
                ShapeHit hit;
                REQUIRE(ray_shape(ray, body.shape, body.transform, hit));
                const double want =
                    reference::ray_brush(exact_double(ray.origin), exact_double(ray.direction), *b, 100.0);
                CHECK(std::abs(hit.distance - want) <= kTolerance);
                CHECK(hit.normal.y > 0.99999f);
            }
        }
        MESSAGE("sliver and roof at " << at.x << ": worst ray " << tally.worst_ray << ", worst capsule "
                                      << tally.worst_capsule);
        CHECK(tally.ray_mismatches == 0);
        CHECK(tally.capsule_mismatches == 0);
    }
}

TEST_CASE("rays through the shared edges and vertices of two brushes: always a hit, at the right place") {
    for (const Vec3 at : {Vec3(0), Vec3(9990, -10000, 9995)}) {
        CAPTURE(at.x);
        // A box split by a slanted plane into two brushes sharing the cut face (its edges and corners lie on
        // the box's faces), and a third box brush beside them sharing the +x face.
        const brush::Brush whole = box_brush(at, {2, 1, 1.5f});
        const brush::Plane cut{glm::normalize(DVec3(1, 0.3, 0.2)),
                               glm::dot(glm::normalize(DVec3(1, 0.3, 0.2)), DVec3(at))};
        auto halves = brush::split(whole, cut);
        REQUIRE(halves.ok());
        REQUIRE(halves->back.has_value());
        REQUIRE(halves->front.has_value());
        const brush::Brush beside = box_brush(at + Vec3(3, 0, 0), {1, 1, 1.5f});
        World w;
        add_brush(w, *halves->back);
        add_brush(w, *halves->front);
        add_brush(w, beside);
        // Every point where two of them meet on the outside: the cut face's vertices and points along its
        // edges, and points along the seam of the +x face.
        std::vector<DVec3> targets;
        const brush::Brush& a = *halves->back;
        const int cut_face = a.find_face(cut);
        REQUIRE(cut_face >= 0);
        const auto& poly = a.polygons()[cut_face];
        for (std::size_t k = 0; k < poly.size(); ++k) {
            const DVec3 p = a.vertices()[poly[k]], q = a.vertices()[poly[(k + 1) % poly.size()]];
            for (int s = 0; s < 8; ++s) targets.push_back(p + (q - p) * (s / 8.0));
        }
        for (int s = 1; s < 8; ++s) targets.push_back(DVec3(at) + DVec3(2, 1, -1.5 + 3.0 * s / 8.0));
        // Rays come from outside every face of the union (the box [-2, 4] x [-1, 1] x [-1.5, 1.5] about `at`)
        // that the target lies on, so in exact arithmetic each enters the union at the target; targets inside
        // the union (on the shared +x face) are left out.
        const DVec3 union_min = DVec3(at) + DVec3(-2, -1, -1.5), union_max = DVec3(at) + DVec3(4, 1, 1.5);
        Rng rng(9);
        int rays = 0, misses = 0, shared_hits = 0;
        double worst = 0.0;
        for (const DVec3& target : targets) {
            std::vector<DVec3> normals;
            for (int axis = 0; axis < 3; ++axis) {
                DVec3 n(0.0);
                if (std::abs(target[axis] - union_min[axis]) < 1e-9) n[axis] = -1.0;
                if (std::abs(target[axis] - union_max[axis]) < 1e-9) n[axis] = 1.0;
                if (n != DVec3(0.0)) normals.push_back(n);
            }
            if (normals.empty()) continue;
            for (int i = 0; i < 40; ++i) {
                DVec3 from;
                do from = glm::normalize(DVec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)));
                while (std::any_of(normals.begin(), normals.end(),
                                   [&](const DVec3& n) { return glm::dot(n, from) < 0.05; }));
                geometry::Ray ray;
                ray.origin = Vec3(target + from * 12.0);
                ray.direction = glm::normalize(Vec3(target) - ray.origin);
                ray.max_distance = 40.0f;
                RayHit hit;
                ++rays;
                if (!w.ray_closest(ray, hit)) {
                    ++misses;
                    continue;
                }
                // The reference: the nearest entry over the three brushes.
                double want = 1e30;
                const brush::Brush* parts[] = {&*halves->back, &*halves->front, &beside};
                for (const brush::Brush* b : parts) {
                    const double t =
                        reference::ray_brush(exact_double(ray.origin), exact_double(ray.direction), *b, 40.0);
                    if (t >= 0.0) want = std::min(want, t);
                }
                CHECK(want < 1e30);
                worst = std::max(worst, std::abs(hit.distance - want));
                std::vector<RayHit> all;
                REQUIRE(w.ray_all(ray, all) >= 1);
                CHECK(all.front().distance == hit.distance);
                // Both brushes of a seam are closed solids: a ray entering at their shared edge touches both.
                if (all.size() > 1 && all[1].distance - all[0].distance <= 1e-5f) ++shared_hits;
            }
        }
        MESSAGE(rays << " rays at shared edges and vertices: " << misses << " missed, worst distance error "
                     << worst << ", " << shared_hits << " touching both brushes of the seam at once");
        CHECK(rays > 1000);
        CHECK(misses == 0);
        CHECK(worst <= 1e-4);
    }
}
