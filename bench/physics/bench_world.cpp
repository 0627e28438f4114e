// ks_bench world: world step time against the number of characters (10 -> 10k) running around a generated
// 2k-box level, with the BVH + movers' grid broadphase, against the same world finding movers by testing
// every pair (MoverBroadphase::AllPairs) stepped in lockstep in the same run (every collision event compared
// bit for bit), and the same characters moved by the same controller gathering only static boxes with an
// all-pairs AABB scan (the reference game's broadphase).
#include "bench_registry.h"
#include "bench_util.h"
#include "scenes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <span>

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

constexpr int kSettleSteps = 30;

// N characters in the level, steered every second by their own random stream: two crowds made with the same
// N step the same unless their worlds differ.
struct Crowd {
    World world;
    std::vector<BodyId> ids;
    Rng rng{42};
    int steps = -kSettleSteps; // the first steps settle (characters spread out of crates) unsteered
    Crowd(const scenes::RoomsScene& scene, int n, MoverBroadphase movers) : world(settings(movers)) {
        scenes::add_to_world(scene, world);
        for (int i = 0; i < n; ++i) {
            BodyDesc d;
            d.shape = Shape::capsule(1.0f, 0.5f);
            d.motion = Motion::Character;
            Vec3 p = scenes::random_origin(scene, rng);
            p.y = 1.51f;
            d.transform.position = p;
            ids.push_back(*world.add(d, "character"));
        }
        steer(world, ids, rng);
    }
    static WorldSettings settings(MoverBroadphase movers) {
        WorldSettings s;
        s.movers = movers;
        return s;
    }
    // One step; returns its thread CPU time in microseconds.
    double step() {
        if (steps >= 0 && steps % 120 == 0) steer(world, ids, rng);
        ++steps;
        const double t0 = cpu_seconds();
        world.step(1.0f / 120.0f);
        return (cpu_seconds() - t0) * 1e6;
    }
    // FNV-1a over the bits of every final position and velocity: equal hashes mean equal states, bit for bit.
    std::uint64_t state_hash() const {
        std::uint64_t hash = 1469598103934665603ull;
        auto mix = [&](float v) {
            std::uint32_t bits;
            std::memcpy(&bits, &v, sizeof bits);
            for (int k = 0; k < 4; ++k) hash = (hash ^ ((bits >> (8 * k)) & 0xffu)) * 1099511628211ull;
        };
        for (BodyId id : ids) {
            const Vec3 p = world.transform(id).position, v = world.character(id).movement.velocity;
            for (int k = 0; k < 3; ++k) mix(p[k]), mix(v[k]);
        }
        return hash;
    }
};

bool same_bits(const Collision& a, const Collision& b) {
    return a.self == b.self && a.other == b.other && std::memcmp(&a.point, &b.point, sizeof a.point) == 0 &&
           std::memcmp(&a.normal, &b.normal, sizeof a.normal) == 0 &&
           std::memcmp(&a.penetration, &b.penetration, sizeof a.penetration) == 0;
}

// Collision events of a step that differ between the two worlds (position by position, bit for bit; a
// missing or extra event counts too).
long long mismatches(std::span<const Collision> a, std::span<const Collision> b) {
    long long bad = static_cast<long long>(std::max(a.size(), b.size()) - std::min(a.size(), b.size()));
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) bad += same_bits(a[i], b[i]) ? 0 : 1;
    return bad;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// The reference's broadphase for the level: the same controller moving the same characters, obstacles
// found by scanning every static box (no character-character contacts, so less work than a world step).
double static_scan_us(const scenes::RoomsScene& scene, const Crowd& crowd) {
    AllPairs all;
    for (const auto& b : scene.boxes) {
        all.shapes.push_back(Shape::box(b.half));
        all.xfs.push_back({b.centre, b.rotation()});
        all.boxes.push_back(all.shapes.back().bounds(all.xfs.back()));
    }
    std::vector<Vec3> pos;
    std::vector<CharacterState> states;
    for (BodyId id : crowd.ids)
        pos.push_back(crowd.world.transform(id).position), states.push_back(crowd.world.character(id));
    CharacterScratch scratch;
    const int steps = std::clamp(20000 / static_cast<int>(crowd.ids.size()), 2, 60);
    const double t0 = cpu_seconds();
    for (int s = 0; s < steps; ++s)
        for (std::size_t i = 0; i < pos.size(); ++i)
            move_character(all, 1.0f, 0.5f, {}, states[i], pos[i], 1.0f / 120.0f, scratch);
    return (cpu_seconds() - t0) / steps * 1e6;
}

int world_command(int argc, const char* const* argv) {
    bool quick = false;
    int only = 0, only_steps = 0; // --chars N [--steps S]: one row, no reference (for profiling)
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        quick |= a == "--quick";
        if (a == "--chars" && i + 1 < argc) only = std::clamp(std::atoi(argv[++i]), 1, 100000);
        if (a == "--steps" && i + 1 < argc) only_steps = std::clamp(std::atoi(argv[++i]), 1, 100000);
    }
    const auto scene = scenes::make_rooms(2000, 1);
    std::printf(
        "World step (120 Hz) with N characters (capsule r 1, h 3, running at 15 u/s in random directions) in "
        "a\n%zu-box level: the movers' grid against the all-pairs reference (every mover against every "
        "other)\nin lockstep; mismatches: collision events that differ bit for bit. Thread CPU time per "
        "step. "
        "Load average at the start: %s\n",
        scene.boxes.size(), load_average().c_str());
    std::printf("%7s %10s %10s %12s %12s %7s %10s %10s %12s\n", "chars", "grid us", "median us",
                "all-pairs us", "median us", "ratio", "mismatch", "contacts", "static-scan");
    std::vector<std::string> rows;
    const std::vector<int> counts = only    ? std::vector<int>{only}
                                    : quick ? std::vector<int>{10, 100, 1000}
                                            : std::vector<int>{10, 100, 1000, 10000};
    for (int n : counts) {
        Crowd grid(scene, n, MoverBroadphase::Grid);
        for (int i = 0; i < kSettleSteps; ++i) grid.step();
        const int steps = only_steps ? only_steps : std::clamp(200000 / n, 10, 240);
        if (only) {
            std::vector<double> us;
            long long contacts = 0;
            for (int i = 0; i < steps; ++i)
                us.push_back(grid.step()),
                    contacts += static_cast<long long>(grid.world.collisions().size() / 2);
            double sum = 0;
            for (double u : us) sum += u;
            std::printf("%7d %10.1f %10.1f   contacts/step %.1f, state hash %016llx, load average %s\n", n,
                        sum / steps, median(us), static_cast<double>(contacts) / steps,
                        static_cast<unsigned long long>(grid.state_hash()), load_average().c_str());
            return 0;
        }
        Crowd reference(scene, n, MoverBroadphase::AllPairs);
        for (int i = 0; i < kSettleSteps; ++i) reference.step();
        long long bad = mismatches(grid.world.collisions(), reference.world.collisions()), contacts = 0;
        std::vector<double> grid_us, reference_us;
        for (int i = 0; i < steps; ++i) {
            grid_us.push_back(grid.step());
            reference_us.push_back(reference.step());
            bad += mismatches(grid.world.collisions(), reference.world.collisions());
            contacts += static_cast<long long>(grid.world.collisions().size() / 2);
        }
        if (grid.state_hash() != reference.state_hash()) ++bad;
        double grid_sum = 0, reference_sum = 0;
        for (int i = 0; i < steps; ++i) grid_sum += grid_us[i], reference_sum += reference_us[i];
        const double us = grid_sum / steps, ref_us = reference_sum / steps;
        const double scan_us = static_scan_us(scene, grid);
        std::printf("%7d %10.1f %10.1f %12.1f %12.1f %6.1fx %10lld %10.1f %12.1f\n", n, us, median(grid_us),
                    ref_us, median(reference_us), ref_us / us, bad, static_cast<double>(contacts) / steps,
                    scan_us);
        std::fflush(stdout);
        rows.push_back(std::to_string(n) + "," + fmt("%.2f", us) + "," + fmt("%.4f", us / n) + "," +
                       fmt("%.2f", scan_us) + "," + fmt("%.2f", median(grid_us)) + "," + fmt("%.2f", ref_us) +
                       "," + fmt("%.2f", median(reference_us)) + "," + std::to_string(bad));
    }
    std::printf("Load average at the end: %s\n", load_average().c_str());
    if (quick) return 0; // a short run leaves the CSV and the plot alone
    write_csv("physics_world",
              "characters,us_per_step,us_per_character_step,all_pairs_us_per_step,median_us_per_step,"
              "mover_pairs_us_per_step,mover_pairs_median_us_per_step,mismatches",
              rows);
    plot(
        "physics_world",
        "set title 'World step time vs characters (2k-box level, 120 Hz)'\nset logscale xy\n"
        "set xlabel 'characters'\nset ylabel 'CPU microseconds per step'\nset key top left\n"
        "plot 'physics_world.csv' every ::1 using 1:2 with linespoints title 'BVH + movers grid (ours)', \\\n"
        "     '' every ::1 using 1:6 with linespoints title 'BVH + all mover pairs (reference)', \\\n"
        "     '' every ::1 using 1:4 with linespoints title 'static all-pairs scan, no mover contacts'\n");
    return 0;
}

const ks::bench::Registrar registrar({"world", "world step time vs number of characters in a 2k-box level",
                                      world_command});

} // namespace
} // namespace ks::physics::bench
