// ks_bench physics_brush: brushes in physics (issue 25 item 4). Rays, capsule contacts and capsule sweeps
// against brush shapes (physics/brush_shape.h) vs the same boxes as boxes vs the brushes as triangle meshes,
// in one run: µs per query against the error of each against the double reference (brush_reference.h:
// the brush's own planes in double). Physics has no triangle-mesh shape; the baseline here is a float
// Möller–Trumbore ray test over each face's fan of triangles, in the brush's frame like the polyhedron.
#include "bench_registry.h"
#include "bench_util.h"
#include "brush_reference.h"
#include "brush_scenes.h"
#include "physics/brush_shape.h"
#include "physics/character.h"
#include "physics/ray.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace ks::physics::bench {
namespace {

constexpr double kEps = 1e-5;

struct Target {
    brush::Brush brush;
    BrushBody body;
    Shape box;                   // the same box as a box (box scenes only)
    std::vector<Vec3> triangles; // the brush's faces as fans, local to body.transform (3 per triangle)
    geometry::Aabb bounds;       // world bounds, for the sweeps' obstacles
};

Target make_target(brush::Brush b, const Vec3* box_half) {
    Target t{std::move(b), {}, {}, {}, {}};
    t.body = brush_body(t.brush);
    if (box_half) t.box = Shape::box(*box_half);
    const Polyhedron& p = *t.body.shape.polyhedron;
    for (const auto& f : p.faces) {
        auto idx = p.face_indices(f);
        for (std::size_t k = 1; k + 1 < idx.size(); ++k)
            t.triangles.insert(t.triangles.end(),
                               {p.vertices[idx[0]], p.vertices[idx[k]], p.vertices[idx[k + 1]]});
    }
    t.bounds = t.body.shape.bounds(t.body.transform);
    return t;
}

// Möller–Trumbore over the triangles, nearest entry (rays start outside).
bool ray_triangles(const geometry::Ray& ray, const Target& t, ShapeHit& hit) {
    const Vec3 o = ray.origin - t.body.transform.position, d = ray.direction;
    float best = ray.max_distance;
    bool found = false;
    for (std::size_t i = 0; i < t.triangles.size(); i += 3) {
        const Vec3 &a = t.triangles[i], e1 = t.triangles[i + 1] - a, e2 = t.triangles[i + 2] - a;
        const Vec3 p = glm::cross(d, e2);
        const float det = glm::dot(e1, p);
        if (std::abs(det) < 1e-12f) continue;
        const float inv = 1.0f / det;
        const Vec3 s = o - a;
        const float u = glm::dot(s, p) * inv;
        if (u < 0.0f || u > 1.0f) continue;
        const Vec3 q = glm::cross(s, e1);
        const float v = glm::dot(d, q) * inv;
        if (v < 0.0f || u + v > 1.0f) continue;
        const float dist = glm::dot(e2, q) * inv;
        if (dist >= 0.0f && dist <= best)
            best = dist, found = true, hit.normal = glm::normalize(glm::cross(e1, e2));
    }
    hit.distance = best;
    return found;
}

struct Row {
    std::string query, shape;
    double us = 0.0, worst = 0.0, mean = 0.0;
    long long count = 0, mismatches = 0;
};

void print_row(const Row& r) {
    std::printf("%-16s %-22s %9.4f %12.3e %12.3e %8lld %10lld\n", r.query.c_str(), r.shape.c_str(), r.us,
                r.mean, r.worst, r.count, r.mismatches);
}

// Times `query(i)` over every (target, sample) pair, then judges each result with `error(i)`.
template <class Query, class Judge>
Row measure(const std::string& name, const std::string& shape, std::size_t n, Query&& query, Judge&& judge) {
    Row r{name, shape};
    const double t0 = cpu_seconds();
    for (std::size_t i = 0; i < n; ++i) query(i);
    r.us = (cpu_seconds() - t0) * 1e6 / static_cast<double>(n);
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const auto [error, mismatch] = judge(i);
        r.worst = std::max(r.worst, error);
        sum += error;
        r.mismatches += mismatch ? 1 : 0;
    }
    r.count = static_cast<long long>(n);
    r.mean = sum / static_cast<double>(n);
    return r;
}

struct Sample {
    std::size_t target;
    geometry::Ray ray;
    brush_scenes::CapsulePlacement capsule;
    Vec3 motion;
};

std::vector<Sample> make_samples(Rng& rng, const std::vector<Target>& targets, int per_target) {
    std::vector<Sample> out;
    for (std::size_t k = 0; k < targets.size(); ++k)
        for (int i = 0; i < per_target; ++i) {
            Sample s{k,
                     brush_scenes::ray_at(rng, targets[k].brush),
                     brush_scenes::capsule_near(rng, targets[k].brush),
                     {}};
            // A sweep toward the brush's centre by 1..6 units (walking or falling into it).
            const Vec3 to = Vec3(targets[k].brush.vertex_centre() - exact_double(s.capsule.p0));
            s.motion = glm::length(to) > 1e-3f ? glm::normalize(to) * rng.uniform(1, 6) : Vec3(0, -1, 0);
            out.push_back(s);
        }
    return out;
}

// The error of a sweep, in units, from the reference distance of the capsule's core to the brush along the
// motion (convex in t for convex sets, so ternary search finds its least value): a sweep that stops at t < 1
// should leave the core between radius + skin and radius + skin + kGapTolerance (1e-5) from the brush (error:
// how far outside that band it is); a sweep that runs through (t = 1; also when the motion only slides
// along the surface) should not take the core closer than the radius (error: how far into the solid).
double sweep_error(const Sample& s, const brush::Brush& b, float t, float skin) {
    const DVec3 p0 = exact_double(s.capsule.p0), p1 = exact_double(s.capsule.p1), m = exact_double(s.motion);
    auto dist = [&](double at) { return reference::segment_brush_distance(p0 + m * at, p1 + m * at, b); };
    const double r = s.capsule.radius;
    if (t < 1.0f) {
        const double d = dist(t), lo = r + skin, hi = lo + 1e-5;
        return d < lo ? lo - d : (d > hi ? d - hi : 0.0);
    }
    double lo = 0.0, hi = 1.0;
    for (int i = 0; i < 80; ++i) {
        const double a = lo + (hi - lo) / 3, c = hi - (hi - lo) / 3;
        if (dist(a) <= dist(c))
            hi = c;
        else
            lo = a;
    }
    return std::max(0.0, r - dist(0.5 * (lo + hi)));
}

std::vector<Row> run_set(const std::string& label, const std::vector<Target>& targets,
                         const std::vector<Sample>& samples, bool boxes) {
    std::vector<Row> rows;
    const std::size_t n = samples.size();
    std::vector<ShapeHit> hits(n);
    std::vector<char> hit(n);
    auto judge_rays = [&](std::size_t i) {
        const Sample& s = samples[i];
        const auto j = reference::judge_ray(exact_double(s.ray.origin), exact_double(s.ray.direction),
                                            s.ray.max_distance, hit[i] != 0, hits[i].distance,
                                            targets[s.target].brush, kEps);
        return std::pair{j.error, j.mismatch};
    };
    rows.push_back(measure(
        "ray", label + " brush", n,
        [&](std::size_t i) {
            const Target& t = targets[samples[i].target];
            hit[i] = ray_shape(samples[i].ray, t.body.shape, t.body.transform, hits[i]);
        },
        judge_rays));
    if (boxes)
        rows.push_back(measure(
            "ray", label + " box", n,
            [&](std::size_t i) {
                const Target& t = targets[samples[i].target];
                hit[i] = ray_shape(samples[i].ray, t.box, t.body.transform, hits[i]);
            },
            judge_rays));
    rows.push_back(measure(
        "ray", label + " triangles", n,
        [&](std::size_t i) { hit[i] = ray_triangles(samples[i].ray, targets[samples[i].target], hits[i]); },
        judge_rays));

    std::vector<float> distance(n);
    auto judge_capsules = [&](std::size_t i) {
        const Sample& s = samples[i];
        const double e = reference::capsule_error(distance[i], exact_double(s.capsule.p0),
                                                  exact_double(s.capsule.p1), targets[s.target].brush);
        return std::pair{e, e > kEps};
    };
    auto contact = [&](const Shape& shape, std::size_t i) {
        const Sample& s = samples[i];
        const auto c = collide_capsule_shape({s.capsule.p0, s.capsule.p1}, s.capsule.radius, shape,
                                             targets[s.target].body.transform, 100.0f);
        distance[i] = c ? s.capsule.radius - c->penetration : 1e9f;
    };
    rows.push_back(measure(
        "capsule contact", label + " brush", n,
        [&](std::size_t i) { contact(targets[samples[i].target].body.shape, i); }, judge_capsules));
    if (boxes)
        rows.push_back(measure(
            "capsule contact", label + " box", n,
            [&](std::size_t i) { contact(targets[samples[i].target].box, i); }, judge_capsules));

    const float skin = 0.01f;
    // Sweeps start clear of the brush (the controller resolves overlaps before it sweeps).
    std::vector<std::size_t> clear;
    for (std::size_t i = 0; i < n; ++i) {
        const Sample& s = samples[i];
        if (reference::segment_brush_distance(exact_double(s.capsule.p0), exact_double(s.capsule.p1),
                                              targets[s.target].brush) > s.capsule.radius + skin + 1e-3)
            clear.push_back(i);
    }
    std::vector<float> toi(n);
    auto judge_sweeps = [&](std::size_t k) {
        const std::size_t i = clear[k];
        const double e = sweep_error(samples[i], targets[samples[i].target].brush, toi[i], skin);
        return std::pair{e, e > kEps};
    };
    auto sweep = [&](const Shape& shape, std::size_t k) {
        const Sample& s = samples[clear[k]];
        const Target& t = targets[s.target];
        Obstacle o{&shape, t.body.transform, 0, is_yaw_only(t.body.transform.rotation), t.bounds};
        Vec3 normal;
        toi[clear[k]] =
            sweep_capsule({s.capsule.p0, s.capsule.p1}, s.capsule.radius, s.motion, o, skin, normal);
    };
    rows.push_back(measure(
        "capsule sweep", label + " brush", clear.size(),
        [&](std::size_t k) { sweep(targets[samples[clear[k]].target].body.shape, k); }, judge_sweeps));
    if (boxes)
        rows.push_back(measure(
            "capsule sweep", label + " box", clear.size(),
            [&](std::size_t k) { sweep(targets[samples[clear[k]].target].box, k); }, judge_sweeps));
    return rows;
}

int brush_collision_command(int argc, const char* const* argv) {
    bool quick = false;
    for (int i = 1; i < argc; ++i) quick |= std::string(argv[i]) == "--quick";
    const int count = quick ? 100 : 400, per = quick ? 20 : 50;
    Rng rng(25);
    std::vector<std::string> csv;
    std::printf("brush collision: per place %d random hull brushes and %d boxes, %d queries each; load %s\n",
                count, count, per, load_average().c_str());
    std::printf("%-16s %-22s %9s %12s %12s %8s %10s\n", "query", "shape", "us/query", "mean error",
                "worst error", "queries", ">1e-5");
    for (const bool far : {false, true}) {
        const std::string place = far ? " far" : " near";
        std::vector<Target> hulls, boxes;
        for (int k = 0; k < count; ++k)
            hulls.push_back(make_target(
                brush_scenes::random_brush(rng, brush_scenes::random_far_centre(rng, far)), nullptr));
        for (int k = 0; k < count; ++k) {
            const Vec3 centre(brush_scenes::random_far_centre(rng, far));
            const Vec3 half(rng.uniform(0.2f, 5), rng.uniform(0.2f, 5), rng.uniform(0.2f, 5));
            auto b = brush::make_box(exact_double(centre) - exact_double(half),
                                     exact_double(centre) + exact_double(half));
            boxes.push_back(make_target(std::move(*b), &half));
        }
        const auto hull_samples = make_samples(rng, hulls, per), box_samples = make_samples(rng, boxes, per);
        for (const auto& [label, targets, samples, as_boxes] :
             {std::tuple{"hull" + place, &hulls, &hull_samples, false},
              std::tuple{"box" + place, &boxes, &box_samples, true}})
            for (const Row& r : run_set(label, *targets, *samples, as_boxes)) {
                print_row(r);
                csv.push_back(r.query + "," + r.shape + "," + fmt("%.5f", r.us) + "," + fmt("%.3e", r.mean) +
                              "," + fmt("%.3e", r.worst) + "," + std::to_string(r.count) + "," +
                              std::to_string(r.mismatches));
            }
    }
    if (!quick) {
        const auto path = write_csv(
            "physics_brush", "query,shape,us_per_query,mean_error,worst_error,queries,beyond_1e-5", csv);
        std::printf("csv: %s\n", path.string().c_str());
    }
    return 0;
}

const ks::bench::Registrar registrar(
    {"physics_brush", "rays, capsule contacts and sweeps: brushes vs boxes vs triangles, us vs error",
     brush_collision_command});

} // namespace
} // namespace ks::physics::bench
