// ks_bench rays: closest-hit and any-hit rays per second against scene size (100 -> 100k boxes) for the BVH
// and a brute-force baseline in the same run, the error against a double-precision brute-force reference
// (1M random rays plus the hard-case set), and `--level FILE` for any level file.
#include "bench_registry.h"
#include "bench_util.h"
#include "core/cli.h"
#include "core/paths.h"
#include "level/level_io.h"
#include "ray_reference.h"
#include "scenes.h"

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <fstream>

namespace ks::physics::bench {
namespace {

using reference::RefBox;

const char* kernel_name(RayKernel k) {
    return k == RayKernel::Avx2 ? "avx2" : "portable";
}

struct RaySet {
    std::vector<geometry::Ray> rays;
};

RaySet make_rays(const scenes::RoomsScene& s, int n, std::uint64_t seed) {
    Rng rng(seed);
    RaySet set;
    set.rays.reserve(n);
    for (int i = 0; i < n; ++i)
        set.rays.push_back({scenes::random_origin(s, rng), scenes::random_direction(rng), 100.0f});
    return set;
}

// Brute force in float: every box, every ray (what a scene without an acceleration structure does).
struct BruteForce {
    std::vector<Vec3> half;
    std::vector<geometry::Transform> xf;
    bool closest(const geometry::Ray& r, float& best) const {
        best = r.max_distance;
        bool any = false;
        ShapeHit h;
        for (std::size_t i = 0; i < half.size(); ++i)
            if (ray_box({r.origin, r.direction, best}, half[i], xf[i], h)) best = h.distance, any = true;
        return any;
    }
    bool any_hit(const geometry::Ray& r) const {
        ShapeHit h;
        for (std::size_t i = 0; i < half.size(); ++i)
            if (ray_box(r, half[i], xf[i], h)) return true;
        return false;
    }
};

struct Timing {
    double closest_rps = 0, any_rps = 0; // per second of this thread's CPU time
    double closest_wall_rps = 0;
    double checksum = 0;
    int hits = 0;
};

Timing time_world(const World& w, const RaySet& set, double min_seconds) {
    Timing t;
    RayHit hit;
    std::size_t done = 0;
    double start = cpu_seconds(), wall = now_seconds(), elapsed = 0;
    do {
        for (const geometry::Ray& r : set.rays)
            if (w.ray_closest(r, hit)) t.checksum += hit.distance, ++t.hits;
        done += set.rays.size();
        elapsed = cpu_seconds() - start;
    } while (elapsed < min_seconds);
    t.closest_rps = done / elapsed;
    t.closest_wall_rps = done / (now_seconds() - wall);
    done = 0;
    start = cpu_seconds();
    int any = 0;
    do {
        for (const geometry::Ray& r : set.rays) any += w.ray_any(r);
        done += set.rays.size();
        elapsed = cpu_seconds() - start;
    } while (elapsed < min_seconds);
    t.any_rps = done / elapsed;
    t.hits += any * 0; // keep `any` alive
    if (any < 0) std::printf("%d", any);
    return t;
}

Timing time_brute(const BruteForce& b, const RaySet& set, std::size_t max_rays) {
    Timing t;
    const std::size_t n = std::min(max_rays, set.rays.size());
    double start = cpu_seconds();
    for (std::size_t i = 0; i < n; ++i) {
        float d;
        if (b.closest(set.rays[i], d)) t.checksum += d, ++t.hits;
    }
    t.closest_rps = n / (cpu_seconds() - start);
    start = cpu_seconds();
    int any = 0;
    for (std::size_t i = 0; i < n; ++i) any += b.any_hit(set.rays[i]);
    t.any_rps = n / (cpu_seconds() - start);
    if (any < 0) std::printf("%d", any);
    return t;
}

struct Accuracy {
    long long rays = 0, hits = 0, mismatches = 0, boundary = 0;
    double max_abs_error = 0; // over rays where both hit the same surface
};

// Compares the world's closest hit with the double brute force (see reference::judge).
void compare(const World& w, std::span<const RefBox> ref, const geometry::Ray& r, Accuracy& acc) {
    RayHit h;
    const bool hit = w.ray_closest(r, h);
    ++acc.rays;
    acc.hits += hit;
    const auto v = reference::judge(DVec3(r.origin), DVec3(r.direction), r.max_distance,
                                    hit ? int(h.body.index) : -1, h.distance, ref);
    if (v == reference::Verdict::Mismatch) ++acc.mismatches;
    if (v == reference::Verdict::Boundary) ++acc.boundary;
    if (hit && v == reference::Verdict::Match) {
        const auto want = reference::closest(DVec3(r.origin), DVec3(r.direction), ref, r.max_distance);
        acc.max_abs_error = std::max(acc.max_abs_error, std::abs(h.distance - want.distance));
    }
}

// Rays aimed exactly at vertices and edge midpoints of boxes, lying in face planes, starting on faces and
// grazing faces at 1e-6 rad.
std::vector<geometry::Ray> hard_cases(const scenes::RoomsScene& s, std::uint64_t seed, int per_box_limit) {
    Rng rng(seed);
    std::vector<geometry::Ray> rays;
    const int boxes = std::min<int>(per_box_limit, static_cast<int>(s.boxes.size()));
    for (int bi = 0; bi < boxes; ++bi) {
        const auto& b = s.boxes[rng.below(static_cast<std::uint32_t>(s.boxes.size()))];
        const Quat q = b.rotation();
        for (int k = 0; k < 8; ++k) {
            const Vec3 corner =
                b.centre + q * (b.half * Vec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1));
            const Vec3 edge_mid = b.centre + q * (b.half * Vec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, 0));
            for (const Vec3& target : {corner, edge_mid}) {
                const Vec3 o = target + scenes::random_direction(rng) * rng.uniform(1.0f, 20.0f);
                rays.push_back({o, glm::normalize(target - o), 100.0f});
            }
        }
        for (int axis = 0; axis < 3; ++axis) {
            Vec3 n(0.0f);
            n[axis] = 1.0f;
            const Vec3 face_point = b.centre + q * (n * b.half[axis]);
            Vec3 tangent = q * glm::normalize(glm::cross(n, Vec3(0.3f, 0.5f, 0.7f)));
            rays.push_back({face_point - tangent * 10.0f, tangent, 100.0f}); // in the face plane
            rays.push_back({face_point, q * n, 100.0f});                     // on the face, leaving
            rays.push_back({face_point, -(q * n), 100.0f});                  // on the face, entering
            const Vec3 graze = glm::normalize(tangent * std::cos(1e-6f) - (q * n) * std::sin(1e-6f));
            rays.push_back(
                {face_point + (q * n) * 1e-4f - graze * 5.0f, graze, 100.0f}); // grazing at 1e-6 rad
        }
    }
    return rays;
}

std::vector<RefBox> to_ref(const scenes::RoomsScene& s) {
    std::vector<RefBox> ref;
    for (const auto& b : s.boxes) ref.push_back({DVec3(b.centre), glm::dquat(b.rotation()), DVec3(b.half)});
    return ref;
}

int run_default(bool quick) {
    const std::vector<int> sizes = quick ? std::vector<int>{100, 2000, 10000}
                                         : std::vector<int>{100, 300, 1000, 2000, 5000, 10000, 30000, 100000};
    const int rays_per_scene = quick ? 50000 : 200000;
    std::printf(
        "Rays from random points in the rooms, random directions, max distance 100; one thread.\n"
        "Rates are per second of this thread's CPU time (the machine is shared); the last column is the\n"
        "wall-clock closest-hit rate. ns/ray/log2(n) staying flat means cost grows like log(n).\n");
    const RayKernel kernel = ray_kernel();
    std::printf("Kernel: %s (the portable kernel's closest-hit rate in the same run is the last column).\n"
                "Load average at the start: %s\n",
                kernel_name(kernel), load_average().c_str());
    std::printf("%8s %5s %13s %13s %12s %12s %8s %8s %10s %12s %13s\n", "shapes", "depth", "bvh closest/s",
                "bvh any/s", "brute cl./s", "brute any/s", "speedup", "ns/ray", "ns/log2(n)", "wall clos./s",
                "portable cl/s");
    std::vector<std::string> rows;
    for (int n : sizes) {
        const auto scene = scenes::make_rooms(n, 1);
        World w;
        scenes::add_to_world(scene, w);
        const auto set = make_rays(scene, rays_per_scene, 7);
        BruteForce brute;
        for (const auto& b : scene.boxes)
            brute.half.push_back(b.half), brute.xf.push_back({b.centre, b.rotation()});
        const Timing tb = time_world(w, set, quick ? 0.2 : 0.5);
        set_ray_kernel(RayKernel::Portable);
        const Timing tp = time_world(w, set, quick ? 0.2 : 0.5);
        set_ray_kernel(kernel);
        const std::size_t brute_rays =
            std::max<std::size_t>(200, static_cast<std::size_t>(4e7 / scene.boxes.size()));
        const Timing tf = time_brute(brute, set, quick ? brute_rays / 4 : brute_rays);
        const double ns = 1e9 / tb.closest_rps,
                     per_log = ns / std::log2(static_cast<double>(scene.boxes.size()));
        std::printf("%8zu %5d %13.0f %13.0f %12.0f %12.0f %7.0fx %8.1f %10.1f %12.0f %13.0f\n",
                    scene.boxes.size(), w.static_bvh().depth(), tb.closest_rps, tb.any_rps, tf.closest_rps,
                    tf.any_rps, tb.closest_rps / tf.closest_rps, ns, per_log, tb.closest_wall_rps,
                    tp.closest_rps);
        std::fflush(stdout);
        rows.push_back(std::to_string(scene.boxes.size()) + "," + fmt("%.0f", tb.closest_rps) + "," +
                       fmt("%.0f", tb.any_rps) + "," + fmt("%.0f", tf.closest_rps) + "," +
                       fmt("%.0f", tf.any_rps) + "," + fmt("%.1f", ns) + "," +
                       fmt("%.0f", tb.closest_wall_rps) + "," + fmt("%.0f", tp.closest_rps));
    }
    std::printf("Load average at the end: %s\n", load_average().c_str());
    write_csv("physics_rays",
              "shapes,bvh_closest_rps,bvh_any_rps,brute_closest_rps,brute_any_rps,bvh_ns_per_ray,"
              "bvh_closest_wall_rps,portable_kernel_closest_rps",
              rows);
    plot("physics_rays",
         "set title 'Rays per second (thread CPU time) vs scene size, one thread'\n"
         "set logscale xy\nset xlabel 'boxes in the scene'\nset ylabel 'rays per second'\n"
         "set key bottom left\n"
         "plot 'physics_rays.csv' every ::1 using 1:2 with linespoints title 'BVH closest hit', \\\n"
         "     '' every ::1 using 1:3 with linespoints title 'BVH any hit', \\\n"
         "     '' every ::1 using 1:4 with linespoints title 'brute force closest', \\\n"
         "     '' every ::1 using 1:5 with linespoints title 'brute force any'\n");

    // Accuracy on the 2k-box level: random rays and the hard-case set against the double reference.
    const auto scene = scenes::make_rooms(2000, 1);
    World w;
    scenes::add_to_world(scene, w);
    const auto ref = to_ref(scene);
    Accuracy random_acc, hard_acc;
    Rng rng(2024);
    const int accuracy_rays = quick ? 100000 : 1000000;
    for (int i = 0; i < accuracy_rays; ++i)
        compare(w, ref, {scenes::random_origin(scene, rng), scenes::random_direction(rng), 100.0f},
                random_acc);
    for (const geometry::Ray& r : hard_cases(scene, 5, quick ? 500 : 2000)) compare(w, ref, r, hard_acc);
    std::printf("\nAccuracy against the double-precision brute force (2k-box level, %zu boxes):\n",
                scene.boxes.size());
    std::printf("%12s %10s %10s %12s %10s %16s\n", "set", "rays", "hits", "mismatches", "boundary",
                "max |d error|");
    std::vector<std::string> acc_rows;
    for (auto [name, a] : {std::pair{"random", random_acc}, std::pair{"hard_cases", hard_acc}}) {
        std::printf("%12s %10lld %10lld %12lld %10lld %16.3g\n", name, a.rays, a.hits, a.mismatches,
                    a.boundary, a.max_abs_error);
        acc_rows.push_back(std::string(name) + "," + std::to_string(a.rays) + "," + std::to_string(a.hits) +
                           "," + std::to_string(a.mismatches) + "," + std::to_string(a.boundary) + "," +
                           fmt("%.3g", a.max_abs_error));
    }
    std::printf(
        "(mismatch: a hit/miss or > 1 mm distance disagreement that survives growing/shrinking the boxes by\n"
        " 0.1 mm; boundary: the ray passes within 0.1 mm of an edge or vertex, where float rounding of the\n"
        " inputs decides which side it is on)\n");
    write_csv("physics_rays_accuracy", "set,rays,hits,mismatches,boundary,max_abs_distance_error", acc_rows);
    return random_acc.mismatches + hard_acc.mismatches == 0 ? 0 : 1;
}

// ---- --level FILE -------------------------------------------------------------------------------------

struct LevelScene {
    std::vector<RefBox> boxes; // walls, floors, doors (closed), panels, pickups
    std::vector<std::size_t> box_body;
    std::vector<Vec3> floor_points; // where ray origins may start (over floors)
    struct Floor {
        Vec3 centre;
        Quat rotation;
        Vec2 half;
    };
    std::vector<Floor> floors;
};

Result<int> build_level(const level::Level& lvl, World& w, LevelScene& out) {
    auto add_box = [&](Vec3 centre, Quat q, Vec3 half, const std::string& what) -> Result<void> {
        BodyDesc d;
        d.shape = Shape::box(half);
        d.transform = {centre, q};
        auto id = w.add(d, what);
        if (!id) return id.error();
        out.boxes.push_back({DVec3(centre), glm::dquat(q), DVec3(half)});
        return ok();
    };
    for (const auto& e : lvl.entities) {
        const Quat q = e.orientation();
        const std::string what =
            "entity " + std::to_string(e.id) + " (" + std::string(level::type_name(e.type())) + ")";
        Result<void> r = ok();
        if (auto* wall = e.try_as<level::WallProps>()) {
            r = add_box(e.position + q * Vec3(0, wall->size.y * 0.5f, 0), q, wall->size * 0.5f, what);
        } else if (auto* floor = e.try_as<level::FloorProps>()) {
            const float dy = floor->ceiling ? floor->thickness * 0.5f : -floor->thickness * 0.5f;
            r = add_box(e.position + q * Vec3(0, dy, 0), q,
                        Vec3(floor->size.x * 0.5f, floor->thickness * 0.5f, floor->size.y * 0.5f), what);
            if (!floor->ceiling) out.floors.push_back({e.position, q, floor->size * 0.5f});
        } else if (auto* door = e.try_as<level::DoorProps>()) {
            r = add_box(e.position + q * Vec3(0, door->height * 0.5f, 0), q,
                        Vec3(door->width * 0.5f, door->height * 0.5f, 0.1f), what);
        } else if (auto* panel = e.try_as<level::ControlPanelProps>()) {
            r = add_box(e.position + q * Vec3(0, panel->size.y * 0.5f, 0), q, panel->size * 0.5f, what);
        }
        if (!r) return r.error();
    }
    w.build_static();
    return static_cast<int>(out.boxes.size());
}

int run_level(const CommandLine& cli) {
    const auto file = paths::resolve_user_path(*cli.get("level"));
    auto rays_arg = cli.get_int("rays", 1000000, 1, 100000000);
    auto seed_arg = cli.get_int("seed", 1, 0, 2147483647);
    if (!rays_arg || !seed_arg) {
        std::fprintf(stderr, "ks_bench rays: %s\n",
                     (!rays_arg ? rays_arg.error() : seed_arg.error()).str().c_str());
        return 2;
    }
    auto lvl = level::load_level_file(file);
    if (!lvl) {
        std::fprintf(stderr, "ks_bench rays: %s\n", lvl.error().str().c_str());
        return 2;
    }
    World w;
    LevelScene scene;
    auto built = build_level(*lvl, w, scene);
    if (!built) {
        std::fprintf(stderr, "ks_bench rays: %s\n", built.error().str().c_str());
        return 2;
    }
    if (scene.floors.empty()) {
        std::fprintf(stderr, "ks_bench rays: %s has no floor to start rays from\n", file.string().c_str());
        return 2;
    }
    Rng rng(static_cast<std::uint64_t>(*seed_arg));
    std::vector<geometry::Ray> rays(*rays_arg);
    for (geometry::Ray& r : rays) {
        const auto& f = scene.floors[rng.below(static_cast<std::uint32_t>(scene.floors.size()))];
        const Vec3 local(rng.uniform(-f.half.x, f.half.x), rng.uniform(0.1f, 10.0f),
                         rng.uniform(-f.half.y, f.half.y));
        r = {f.centre + f.rotation * local, scenes::random_direction(rng), 100.0f};
    }
    std::vector<RayHit> hits(rays.size());
    std::vector<char> hit_flag(rays.size());
    const double start = cpu_seconds();
    for (std::size_t i = 0; i < rays.size(); ++i) hit_flag[i] = w.ray_closest(rays[i], hits[i]);
    const double elapsed = cpu_seconds() - start;
    long long hit_count = 0, mismatches = 0, boundary = 0;
    double checksum = 0.0, max_err = 0.0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        if (hit_flag[i]) ++hit_count, checksum += hits[i].distance;
        const auto v =
            reference::judge(DVec3(rays[i].origin), DVec3(rays[i].direction), 100.0,
                             hit_flag[i] ? int(hits[i].body.index) : -1, hits[i].distance, scene.boxes);
        mismatches += v == reference::Verdict::Mismatch;
        boundary += v == reference::Verdict::Boundary;
        if (hit_flag[i] && v == reference::Verdict::Match) {
            const auto want =
                reference::closest(DVec3(rays[i].origin), DVec3(rays[i].direction), scene.boxes, 100.0);
            max_err = std::max(max_err, std::abs(hits[i].distance - want.distance));
        }
    }
    if (auto dump = cli.get("dump")) {
        std::ofstream out(*dump);
        out << "ox,oy,oz,dx,dy,dz,max_distance,hit,distance,body,nx,ny,nz\n";
        char line[512];
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const geometry::Ray& r = rays[i];
            const RayHit& h = hits[i];
            std::snprintf(line, sizeof line, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%d,%.9g,%d,%.9g,%.9g,%.9g\n",
                          r.origin.x, r.origin.y, r.origin.z, r.direction.x, r.direction.y, r.direction.z,
                          r.max_distance, hit_flag[i] ? 1 : 0, hit_flag[i] ? h.distance : -1.0f,
                          hit_flag[i] ? int(h.body.index) : -1, h.normal.x, h.normal.y, h.normal.z);
            out << line;
        }
    }
    const double rps = rays.size() / elapsed;
    std::printf(
        "level %s: %zu boxes, %zu rays, %.0f closest-hit rays/s (thread CPU time), %lld hits, %lld "
        "mismatches and %lld boundary cases vs the double reference (max |d error| %.3g), checksum %.6f\n",
        file.string().c_str(), scene.boxes.size(), rays.size(), rps, hit_count, mismatches, boundary, max_err,
        checksum);
    if (cli.has("json"))
        std::printf(
            "{\"level\":\"%s\",\"shapes\":%zu,\"rays\":%zu,\"rays_per_second\":%.0f,\"hits\":%lld,"
            "\"mismatches\":%lld,\"boundary\":%lld,\"max_abs_distance_error\":%.3g,\"checksum\":%.6f}\n",
            file.string().c_str(), scene.boxes.size(), rays.size(), rps, hit_count, mismatches, boundary,
            max_err, checksum);
    return mismatches == 0 ? 0 : 1;
}

// ---- --boxes N: one generated scene, for profiling (callgrind) and quick checks -------------------------

int run_boxes(const CommandLine& cli) {
    auto boxes_arg = cli.get_int("boxes", 2000, 20, 1000000);
    auto rays_arg = cli.get_int("rays", 200000, 1, 100000000);
    auto seed_arg = cli.get_int("seed", 7, 0, 2147483647);
    auto passes_arg = cli.get_int("passes", 1, 1, 1000);
    if (!boxes_arg || !rays_arg || !seed_arg || !passes_arg) {
        std::fprintf(stderr, "ks_bench rays: %s\n",
                     (!boxes_arg  ? boxes_arg.error()
                      : !rays_arg ? rays_arg.error()
                      : !seed_arg ? seed_arg.error()
                                  : passes_arg.error())
                         .str()
                         .c_str());
        return 2;
    }
    const auto scene = scenes::make_rooms(*boxes_arg, 1);
    World w;
    scenes::add_to_world(scene, w);
    w.build_static();
    const auto set = make_rays(scene, *rays_arg, static_cast<std::uint64_t>(*seed_arg));
    std::vector<RayHit> hits(set.rays.size());
    std::vector<char> hit_flag(set.rays.size());
    double elapsed = 1e30; // the fastest of --passes passes (the least disturbed by other processes)
    for (int pass = 0; pass < *passes_arg; ++pass) {
        const double start = cpu_seconds();
        for (std::size_t i = 0; i < set.rays.size(); ++i) hit_flag[i] = w.ray_closest(set.rays[i], hits[i]);
        elapsed = std::min(elapsed, cpu_seconds() - start);
    }
    long long hit_count = 0, mismatches = 0;
    double checksum = 0.0;
    const auto ref = to_ref(scene);
    const bool check = !cli.has("no-check");
    for (std::size_t i = 0; i < set.rays.size(); ++i) {
        if (hit_flag[i]) ++hit_count, checksum += hits[i].distance;
        if (check)
            mismatches += reference::judge(DVec3(set.rays[i].origin), DVec3(set.rays[i].direction), 100.0,
                                           hit_flag[i] ? int(hits[i].body.index) : -1, hits[i].distance,
                                           ref) == reference::Verdict::Mismatch;
    }
    std::printf(
        "%zu boxes, %zu rays, %s kernel: %.0f closest-hit rays/s (thread CPU time, best of %d), %lld hits, "
        "%s%lld mismatches, checksum %.6f, load average %s\n",
        scene.boxes.size(), set.rays.size(), kernel_name(ray_kernel()), set.rays.size() / elapsed,
        *passes_arg, hit_count, check ? "" : "(not checked) ", mismatches, checksum, load_average().c_str());
    return mismatches == 0 ? 0 : 1;
}

int rays_command(int argc, const char* const* argv) {
    auto cli = CommandLine::parse(argc, argv, {"json", "quick", "no-check"});
    if (!cli) {
        std::fprintf(stderr, "ks_bench rays: %s\n", cli.error().str().c_str());
        return 2;
    }
    if (auto unknown = cli->unknown(
            {"level", "boxes", "rays", "seed", "json", "dump", "quick", "no-check", "kernel", "passes"});
        !unknown.empty()) {
        std::fprintf(stderr,
                     "ks_bench rays: unknown option --%s (known: --level FILE --rays N --seed S --json "
                     "--dump FILE --quick --kernel portable|avx2; --boxes N --rays N --seed S --passes P "
                     "--no-check)\n",
                     unknown[0].c_str());
        return 2;
    }
    if (auto kernel = cli->get("kernel")) {
        const bool known = *kernel == "portable" || *kernel == "avx2";
        if (!known || !set_ray_kernel(*kernel == "avx2" ? RayKernel::Avx2 : RayKernel::Portable)) {
            std::fprintf(stderr, "ks_bench rays: --kernel %s is %s (use portable%s)\n", kernel->c_str(),
                         known ? "not supported by this CPU" : "unknown", cpu_has_avx2() ? " or avx2" : "");
            return 2;
        }
    }
    if (cli->has("level")) return run_level(*cli);
    if (cli->has("boxes")) return run_boxes(*cli);
    return run_default(cli->has("quick"));
}

const ks::bench::Registrar registrar(
    {"rays", "BVH ray casts vs brute force, error vs a double reference; --level FILE", rays_command});

} // namespace
} // namespace ks::physics::bench
