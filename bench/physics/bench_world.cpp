// ks_bench world: world step time against the number of characters (10 -> 10k) running around a generated
// 2k-box level, with the BVH + hash-grid broadphase, and the same characters moved by the same
// controller but gathering obstacles with an all-pairs AABB scan (the reference's broadphase) as the
// baseline in the same run.
#include "bench_registry.h"
#include "bench_util.h"
#include "scenes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace ks::physics::bench {
namespace {

// The reference's broadphase: every static box's AABB against the character's (no structure).
class AllPairs final : public ObstacleSource {
  public:
    std::vector<Shape> shapes;
    std::vector<geometry::Transform> xfs;
    std::vector<geometry::Aabb> boxes;
    void gather(const geometry::Aabb& region, std::vector<Obstacle>& out) const override {
        for (std::size_t i = 0; i < boxes.size(); ++i)
            if (boxes[i].overlaps(region))
                out.push_back(
                    {&shapes[i], xfs[i], static_cast<std::uint32_t>(i), is_yaw_only(xfs[i].rotation)});
    }
};

void steer(World& w, const std::vector<BodyId>& ids, Rng& rng) {
    for (BodyId id : ids) {
        auto& m = w.character(id).movement;
        const float a = rng.uniform(0, 2 * kPi);
        m.velocity.x = 15 * std::cos(a);
        m.velocity.z = 15 * std::sin(a);
    }
}

int world_command(int argc, const char* const* argv) {
    bool quick = false;
    int only = 0, only_steps = 0; // --chars N [--steps S]: one row, no baseline (for profiling)
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        quick |= a == "--quick";
        if (a == "--chars" && i + 1 < argc) only = std::clamp(std::atoi(argv[++i]), 1, 100000);
        if (a == "--steps" && i + 1 < argc) only_steps = std::clamp(std::atoi(argv[++i]), 1, 100000);
    }
    const auto scene = scenes::make_rooms(2000, 1);
    std::printf(
        "World step (120 Hz) with N characters (capsule r 1, h 3, running at 15 u/s in random directions) in "
        "a\n%zu-box level. Times are thread CPU time per step. Load average at the start: %s\n",
        scene.boxes.size(), load_average().c_str());
    std::printf("%8s %14s %16s %18s %16s %10s %12s\n", "chars", "us/step", "us/char/step",
                "all-pairs us/step", "contacts/step", "speedup", "median us");
    std::vector<std::string> rows;
    const std::vector<int> counts = only    ? std::vector<int>{only}
                                    : quick ? std::vector<int>{10, 100, 1000}
                                            : std::vector<int>{10, 100, 1000, 10000};
    for (int n : counts) {
        World w;
        scenes::add_to_world(scene, w);
        Rng rng(42);
        std::vector<BodyId> ids;
        for (int i = 0; i < n; ++i) {
            BodyDesc d;
            d.shape = Shape::capsule(1.0f, 0.5f);
            d.motion = Motion::Character;
            Vec3 p = scenes::random_origin(scene, rng);
            p.y = 1.51f;
            d.transform.position = p;
            ids.push_back(*w.add(d, "character"));
        }
        steer(w, ids, rng);
        for (int i = 0; i < 30; ++i) w.step(1.0f / 120.0f); // settle, spread out of crates
        const int steps = only_steps ? only_steps : std::clamp(200000 / n, 10, 240);
        double cpu = 0;
        long long contacts = 0;
        std::vector<double> step_us;
        step_us.reserve(steps);
        for (int i = 0; i < steps; ++i) {
            if (i % 120 == 0) steer(w, ids, rng);
            const double t0 = cpu_seconds();
            w.step(1.0f / 120.0f);
            const double t = cpu_seconds() - t0;
            cpu += t;
            step_us.push_back(t * 1e6);
            contacts += static_cast<long long>(w.collisions().size() / 2);
        }
        const double us = cpu / steps * 1e6;
        // The median step is what a step costs when no other process disturbs it (the mean also carries
        // the steps that were preempted or had their caches flushed by other processes).
        std::sort(step_us.begin(), step_us.end());
        const double median_us = step_us[step_us.size() / 2], fastest_us = step_us.front();
        if (only) {
            // FNV-1a over the bits of every final position and velocity: equal hashes mean the step
            // changed nothing (bit for bit) between two builds.
            std::uint64_t hash = 1469598103934665603ull;
            auto mix = [&](float v) {
                std::uint32_t bits;
                std::memcpy(&bits, &v, sizeof bits);
                for (int k = 0; k < 4; ++k) hash = (hash ^ ((bits >> (8 * k)) & 0xffu)) * 1099511628211ull;
            };
            for (BodyId id : ids) {
                const Vec3 p = w.transform(id).position, v = w.character(id).movement.velocity;
                for (int k = 0; k < 3; ++k) mix(p[k]), mix(v[k]);
            }
            std::printf(
                "%8d %14.1f %16.3f %18s %16.1f   median %.1f us, fastest %.1f us, state hash %016llx, "
                "load average %s\n",
                n, us, us / n, "-", static_cast<double>(contacts) / steps, median_us, fastest_us,
                static_cast<unsigned long long>(hash), load_average().c_str());
            return 0;
        }

        // Baseline: the same controller and characters, obstacles found by scanning every static box.
        AllPairs all;
        for (const auto& b : scene.boxes) {
            all.shapes.push_back(Shape::box(b.half));
            all.xfs.push_back({b.centre, b.rotation()});
            all.boxes.push_back(all.shapes.back().bounds(all.xfs.back()));
        }
        std::vector<Vec3> pos;
        std::vector<CharacterState> states;
        for (BodyId id : ids) pos.push_back(w.transform(id).position), states.push_back(w.character(id));
        CharacterScratch scratch;
        const int base_steps = std::clamp(20000 / n, 2, 60);
        const double t0 = cpu_seconds();
        for (int s = 0; s < base_steps; ++s)
            for (std::size_t i = 0; i < pos.size(); ++i)
                move_character(all, 1.0f, 0.5f, {}, states[i], pos[i], 1.0f / 120.0f, scratch);
        const double base_us = (cpu_seconds() - t0) / base_steps * 1e6;
        std::printf("%8d %14.1f %16.3f %18.1f %16.1f %9.1fx %12.1f\n", n, us, us / n, base_us,
                    static_cast<double>(contacts) / steps, base_us / us, median_us);
        std::fflush(stdout);
        rows.push_back(std::to_string(n) + "," + fmt("%.2f", us) + "," + fmt("%.4f", us / n) + "," +
                       fmt("%.2f", base_us) + "," + fmt("%.2f", median_us));
    }
    std::printf("Load average at the end: %s\n", load_average().c_str());
    write_csv("physics_world",
              "characters,us_per_step,us_per_character_step,all_pairs_us_per_step,median_us_per_step", rows);
    plot("physics_world",
         "set title 'World step time vs characters (2k-box level, 120 Hz)'\nset logscale xy\n"
         "set xlabel 'characters'\nset ylabel 'CPU microseconds per step'\nset key top left\n"
         "plot 'physics_world.csv' every ::1 using 1:2 with linespoints title 'BVH + hash grid (ours)', "
         "\\\n"
         "     '' every ::1 using 1:4 with linespoints title 'all-pairs AABB scan (reference broadphase)'\n");
    return 0;
}

const ks::bench::Registrar registrar({"world", "world step time vs number of characters in a 2k-box level",
                                      world_command});

} // namespace
} // namespace ks::physics::bench
