// ks_bench crowd: 1 000 robots in the game, on the main level and on a generated level of ten times its floor
// area (the soak benchmark's rooms), against the real-time budget of one 120 Hz step (8.3 ms). Every robot
// is simulated (AI, navigation, character controller); the player is immortal and stands still, so the
// robots near it keep fighting. Robots are placed at random free spots: a ray down onto a floor, then a
// capsule overlap test against the level and the robots placed before.
#include "bench_registry.h"
#include "bench_util.h"
#include "core/paths.h"
#include "game/game.h"
#include "level/level_io.h"
#include "soak/soak.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace ks::physics::bench {
namespace {

std::unique_ptr<game::Game> make_game(const level::Level& lv) {
    game::GameOptions o;
    o.seed = 1;
    o.settings.max_health = o.settings.start_health = 1e30f;
    auto g = game::Game::create(lv, o);
    if (!g) {
        std::fprintf(stderr, "%s\n", g.error().str().c_str());
        std::exit(1);
    }
    return std::move(*g);
}

// The x/z box of the level's floors (ceilings left out).
geometry::Aabb floor_box(const level::Level& lv) {
    geometry::Aabb box = geometry::Aabb::empty();
    for (const level::Entity& e : lv.entities) {
        if (e.type() != level::EntityType::Floor || e.as<level::FloorProps>().ceiling) continue;
        const Vec2 half = e.as<level::FloorProps>().size * 0.5f;
        box.grow(geometry::Aabb{e.position - Vec3(half.x, 0, half.y), e.position + Vec3(half.x, 0, half.y)});
    }
    return box;
}

// Adds `count` robots at random free floor spots of `lv` (feet on a floor whose normal is within 45 degrees
// of up, a capsule of the robot's size clear of the level and of the robots already placed).
void add_robots(level::Level& lv, int count, std::uint64_t seed) {
    const auto probe = make_game(lv);
    const World& w = probe->world();
    const geometry::Aabb box = floor_box(lv);
    const game::GameSettings settings;
    const float r = settings.robot_radius + 0.05f, h = settings.robot_height;
    std::vector<Vec3> placed;
    Rng rng(seed);
    std::vector<BodyId> overlaps;
    for (int tries = 0; static_cast<int>(placed.size()) < count && tries < count * 200; ++tries) {
        const Vec3 top(rng.uniform(box.min.x, box.max.x), 15.5f, rng.uniform(box.min.z, box.max.z));
        RayHit hit;
        if (!w.ray_closest({top, Vec3(0, -1, 0), 20.0f}, hit, RayFilter(layer::kSolid)) ||
            hit.normal.y < 0.7f)
            continue;
        const Vec3 feet = hit.point + Vec3(0, 0.02f, 0);
        overlaps.clear();
        if (w.overlap_capsule({feet + Vec3(0, r, 0), feet + Vec3(0, h - r, 0)}, r, overlaps) > 0) continue;
        bool crowded = false;
        for (const Vec3& p : placed) {
            const Vec2 d(p.x - feet.x, p.z - feet.z);
            crowded |= std::abs(p.y - feet.y) < h && glm::dot(d, d) < 4 * r * r;
        }
        if (crowded) continue;
        placed.push_back(feet);
        lv.add(level::EntityType::Robot, feet, "crowd robot").rotation.x = rng.uniform(0.0f, 360.0f);
    }
}

struct CrowdRow {
    std::string level;
    double area = 0;
    int robots = 0;
    double mean_us = 0, median_us = 0, p99_us = 0;
};

CrowdRow measure(const std::string& name, level::Level lv, int robots, int steps) {
    CrowdRow row;
    row.level = name;
    const geometry::Aabb box = floor_box(lv);
    row.area = static_cast<double>(box.max.x - box.min.x) * (box.max.z - box.min.z);
    add_robots(lv, robots, 7);
    auto g = make_game(lv);
    row.robots = static_cast<int>(g->robots().size());
    for (int i = 0; i < 60; ++i) g->step({}); // warm-up: buffers, caches, robots leave their spawn poses
    std::vector<double> us;
    for (int i = 0; i < steps; ++i) {
        const double t0 = cpu_seconds();
        g->step({});
        us.push_back((cpu_seconds() - t0) * 1e6);
    }
    double sum = 0;
    for (double u : us) sum += u;
    std::sort(us.begin(), us.end());
    row.mean_us = sum / steps;
    row.median_us = us[us.size() / 2];
    row.p99_us = us[std::min(us.size() - 1, us.size() * 99 / 100)];
    return row;
}

int crowd_command(int argc, const char* const* argv) {
    bool quick = false;
    for (int i = 1; i < argc; ++i) quick |= std::strcmp(argv[i], "--quick") == 0;
    auto main_level = level::load_level_file(paths::level("main.json"));
    if (!main_level) {
        std::fprintf(stderr, "%s\n", main_level.error().str().c_str());
        return 1;
    }
    const geometry::Aabb box = floor_box(*main_level);
    const double main_area = static_cast<double>(box.max.x - box.min.x) * (box.max.z - box.min.z);
    soak::LargeLevelOptions large;
    large.robots_per_room = 0;
    large.columns = large.rows =
        std::max(2, static_cast<int>(std::lround(std::sqrt(10.0 * main_area / 1600.0))));
    const int steps = quick ? 60 : 360;
    std::printf(
        "1 000 robots added to a level (player immortal and idle), Game::step at 120 Hz, thread CPU time "
        "per\nstep over %d steps after 60 of warm-up; the real-time budget of a step is 8 333 us. Load "
        "average: %s\n",
        steps, load_average().c_str());
    std::printf("%-28s %10s %8s %10s %10s %10s %9s\n", "level", "floor m2", "robots", "mean us", "median us",
                "p99 us", "budget");
    std::vector<std::string> rows;
    for (int which = 0; which < 2; ++which) {
        const CrowdRow r = which == 0 ? measure("main", *main_level, 1000, steps)
                                      : measure("generated " + std::to_string(large.columns) + "x" +
                                                    std::to_string(large.rows) + " rooms",
                                                soak::large_level(large), 1000, steps);
        std::printf("%-28s %10.0f %8d %10.1f %10.1f %10.1f %8.1f%%\n", r.level.c_str(), r.area, r.robots,
                    r.mean_us, r.median_us, r.p99_us, 100.0 * r.mean_us / 8333.3);
        std::fflush(stdout);
        rows.push_back(r.level + "," + fmt("%.0f", r.area) + "," + std::to_string(r.robots) + "," +
                       fmt("%.1f", r.mean_us) + "," + fmt("%.1f", r.median_us) + "," + fmt("%.1f", r.p99_us));
    }
    if (!quick) write_csv("physics_crowd", "level,floor_area,robots,mean_us,median_us,p99_us", rows);
    return 0;
}

const ks::bench::Registrar
    registrar({"crowd", "1 000 robots on the main level and on a level of 10x its area", crowd_command});

} // namespace
} // namespace ks::physics::bench
