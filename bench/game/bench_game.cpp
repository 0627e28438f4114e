// ks_bench game: headless simulation speed of the game rules.
//   1. the main level: steps/s with the autoplay bot playing it through, and with the player idle;
//   2. step time vs robot count (10 -> 1000) on a generated arena (every robot simulated, AI + character);
//   3. speed against error: the fixed step rate vs the trajectory of a scripted run (walk, turn, jump)
//      compared with a 960 Hz reference.
// Writes docs/bench/game_robots.csv, docs/bench/game_step_rate.csv and, with gnuplot, game_robots.png.
#include "bench_registry.h"
#include "core/paths.h"
#include "game/autoplay.h"
#include "game/game.h"
#include "level/level_io.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace {

using namespace ks;
using namespace ks::game;
using Clock = std::chrono::steady_clock;

std::filesystem::path out_dir() {
#ifdef KS_SOURCE_DIR
    return std::filesystem::path(KS_SOURCE_DIR) / "docs" / "bench";
#else
    return std::filesystem::path("docs") / "bench";
#endif
}

double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::unique_ptr<Game> make(const level::Level& lv, std::uint64_t seed, GameSettings settings = {}) {
    GameOptions o;
    o.seed = seed;
    o.settings = settings;
    auto g = Game::create(lv, o);
    if (!g) {
        std::fprintf(stderr, "%s\n", g.error().str().c_str());
        std::exit(1);
    }
    return std::move(*g);
}

// A square arena with pillars, `robots` robots on a grid, the player in the middle (immortal, so the AI
// keeps engaging).
level::Level arena(int robots) {
    level::Level lv;
    const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(robots))));
    const float spacing = 6.0f;
    const float half = side * spacing * 0.5f + 20.0f;
    auto& floor = lv.add(level::EntityType::Floor, Vec3(0.0f), "ground");
    floor.as<level::FloorProps>().size = Vec2(2 * half, 2 * half);
    for (int k = 0; k < 4; ++k) {
        auto& w = lv.add(level::EntityType::Wall, Vec3(0.0f), "rim");
        const float a = k * kPi * 0.5f;
        w.position = Vec3(std::sin(a) * half, 0, std::cos(a) * half);
        w.rotation.x = degrees(a);
        w.as<level::WallProps>().size = Vec3(2 * half, 16, 0.5f);
    }
    for (int i = 0; i < side; i += 3)
        for (int j = 0; j < side; j += 3) {
            auto& p = lv.add(level::EntityType::Wall, Vec3(0.0f), "pillar");
            p.position = Vec3((i - side * 0.5f) * spacing, 0, (j - side * 0.5f) * spacing); // between robots
            p.as<level::WallProps>().size = Vec3(2, 16, 2);
        }
    int placed = 0;
    for (int i = 0; i < side && placed < robots; ++i)
        for (int j = 0; j < side && placed < robots; ++j) {
            const Vec3 at((i - side * 0.5f + 0.5f) * spacing, 0, (j - side * 0.5f + 0.5f) * spacing);
            if (glm::length(at) < 4.0f) continue;
            lv.add(level::EntityType::Robot, at, "robot").rotation.x =
                static_cast<float>((i * 37 + j * 11) % 360);
            ++placed;
        }
    lv.player_start.position = Vec3(0.0f);
    return lv;
}

struct ScalingRow {
    int robots = 0;
    double us_per_step = 0, us_per_robot = 0;
    int engaged = 0; // robots alerted, chasing or shooting
    int moving = 0;  // robots with horizontal velocity this step (the character controller's real work)
};

ScalingRow measure_arena(int robots, double sim_seconds, int repeats) {
    ScalingRow best;
    best.us_per_step = 1e30;
    for (int rep = 0; rep < repeats; ++rep) {
        GameSettings s;
        s.max_health = s.start_health = 1e30f;
        auto g = make(arena(robots), 1, s);
        for (int i = 0; i < 60; ++i) g->step({}); // warm-up: buffers, BVH
        const int steps = static_cast<int>(sim_seconds * 120);
        const auto t0 = Clock::now();
        for (int i = 0; i < steps; ++i) g->step({});
        const double us = seconds_since(t0) / steps * 1e6;
        if (us >= best.us_per_step) continue;
        best.robots = static_cast<int>(g->robots().size());
        best.us_per_step = us;
        best.us_per_robot = us / std::max(1, best.robots);
        best.engaged = 0;
        best.moving = 0;
        for (const Robot& r : g->robots()) {
            best.engaged += r.mode != RobotMode::Idle ? 1 : 0;
            const Vec3 v = g->world().character(r.body).movement.velocity;
            best.moving += v.x * v.x + v.z * v.z > 1e-4f ? 1 : 0;
        }
    }
    return best;
}

// Scripted input as a function of time (so every step rate sees the same motion).
Input scripted(double t, double dt) {
    Input in;
    in.move_forward = t < 2.0 ? 1.0f : 0.3f;
    in.move_right = t > 1.0 && t < 2.5 ? 0.5f : 0.0f;
    in.look_yaw = static_cast<float>(0.8 * dt * (t < 1.5 ? 1.0 : -1.0));
    const double jump_at = 1.25;
    in.jump = t <= jump_at && t + dt > jump_at;
    return in;
}

struct RateRow {
    int hz = 0;
    double error = 0, us_per_sim_second = 0;
};

Vec3 scripted_run(const level::Level& lv, int hz, double seconds, double& wall) {
    GameSettings s;
    s.step = 1.0 / hz;
    auto g = make(lv, 1, s);
    const int steps = static_cast<int>(seconds * hz + 0.5);
    const auto t0 = Clock::now();
    for (int i = 0; i < steps; ++i) g->step(scripted(i / static_cast<double>(hz), 1.0 / hz));
    wall = seconds_since(t0);
    return g->player().feet;
}

int run(int argc, const char* const* argv) {
    bool quick = false;
    for (int i = 1; i < argc; ++i)
        if (std::strcmp(argv[i], "--quick") == 0) quick = true;

    auto main_level = level::load_level_file(paths::level("main.json"));
    if (!main_level) {
        std::fprintf(stderr, "%s\n", main_level.error().str().c_str());
        return 1;
    }

    // 1. The main level.
    std::printf("Main level (8 robots, 56 entities), fixed step 1/120 s\n");
    std::printf("%-34s %10s %12s %12s\n", "run", "steps", "steps/s", "us/step");
    const int repeats = quick ? 1 : 3;
    double best_auto = 1e30, best_idle = 1e30;
    std::int64_t auto_steps = 0;
    for (int rep = 0; rep < repeats; ++rep) {
        auto g = make(*main_level, 1);
        auto bot = Autoplay::create(*main_level, *g, 1);
        if (!bot) {
            std::fprintf(stderr, "%s\n", bot.error().str().c_str());
            return 1;
        }
        const auto t0 = Clock::now();
        std::int64_t n = 0;
        while (g->phase() == Phase::Playing && n < 120 * 120) {
            g->step(bot->decide(*g));
            ++n;
        }
        best_auto = std::min(best_auto, seconds_since(t0) / n);
        auto_steps = n;
        auto idle = make(*main_level, 1);
        const auto t1 = Clock::now();
        const int idle_steps = quick ? 1200 : 7200;
        for (int i = 0; i < idle_steps; ++i) idle->step({});
        best_idle = std::min(best_idle, seconds_since(t1) / idle_steps);
    }
    std::printf("%-34s %10lld %12.0f %12.2f\n", "autoplay to the win (incl. bot)",
                static_cast<long long>(auto_steps), 1.0 / best_auto, best_auto * 1e6);
    std::printf("%-34s %10d %12.0f %12.2f\n", "player idle at the start", quick ? 1200 : 7200,
                1.0 / best_idle, best_idle * 1e6);
    std::printf("real time needs 120 steps/s: %.0fx headroom (autoplay)\n\n", 1.0 / best_auto / 120.0);

    // 2. Robot count.
    std::printf("Step time vs robots (generated arena, all robots simulated, player immortal)\n");
    std::printf("%8s %12s %14s %10s %8s\n", "robots", "us/step", "us/robot/step", "engaged", "moving");
    std::vector<ScalingRow> rows;
    for (int n : {10, 30, 100, 300, 1000}) {
        rows.push_back(measure_arena(n, quick ? 0.5 : 2.0, repeats));
        const auto& r = rows.back();
        std::printf("%8d %12.1f %14.2f %10d %8d\n", r.robots, r.us_per_step, r.us_per_robot, r.engaged,
                    r.moving);
    }
    const double ratio = rows.back().us_per_step / rows.front().us_per_step;
    const double count_ratio = static_cast<double>(rows.back().robots) / rows.front().robots;
    std::printf("1000 vs 10 robots: %.1fx the time for %.0fx the robots\n\n", ratio, count_ratio);

    // 3. Speed against error: step rate.
    std::printf("Step rate vs error (scripted walk/strafe/turn/jump, 3 s, main level; reference 960 Hz)\n");
    std::printf("%6s %16s %20s\n", "Hz", "final pos error", "us per sim second");
    double ref_wall = 0;
    const Vec3 reference = scripted_run(*main_level, 960, 3.0, ref_wall);
    std::vector<RateRow> rates;
    for (int hz : {30, 60, 120, 240, 480}) {
        double wall = 1e30;
        Vec3 p(0.0f);
        for (int rep = 0; rep < repeats; ++rep) { // best of: the machine is shared
            double w = 0;
            p = scripted_run(*main_level, hz, 3.0, w);
            wall = std::min(wall, w);
        }
        rates.push_back({hz, glm::length(p - reference), wall / 3.0 * 1e6});
        std::printf("%6d %16.4g %20.0f\n", hz, rates.back().error, rates.back().us_per_sim_second);
    }

    if (!quick) {
        std::error_code ec;
        std::filesystem::create_directories(out_dir(), ec);
        const auto csv = out_dir() / "game_robots.csv";
        if (FILE* f = std::fopen(csv.string().c_str(), "w")) {
            std::fprintf(f, "robots,us_per_step,us_per_robot_step,engaged,moving\n");
            for (const auto& r : rows)
                std::fprintf(f, "%d,%.2f,%.3f,%d,%d\n", r.robots, r.us_per_step, r.us_per_robot, r.engaged,
                             r.moving);
            std::fclose(f);
        }
        if (FILE* f = std::fopen((out_dir() / "game_step_rate.csv").string().c_str(), "w")) {
            std::fprintf(f, "hz,final_position_error,us_per_sim_second\n");
            for (const auto& r : rates) std::fprintf(f, "%d,%.6g,%.1f\n", r.hz, r.error, r.us_per_sim_second);
            std::fclose(f);
        }
        const auto png = out_dir() / "game_robots.png";
        const std::string plot =
            "gnuplot -e \"set terminal pngcairo size 800,500; set output '" + png.string() +
            "'; set datafile separator ','; set logscale xy; set xlabel 'robots'; set ylabel "
            "'microseconds per 1/120 s step'; set key top left; set title 'Game step time vs "
            "robot count'; plot '" +
            csv.string() +
            "' every ::1 using 1:2 with linespoints title 'step', 8333 with lines title "
            "'real-time budget (1/120 s)'\" 2>/dev/null";
        if (std::system("command -v gnuplot >/dev/null 2>&1") == 0 && std::system(plot.c_str()) == 0)
            std::printf("\nwrote %s, game_step_rate.csv and %s\n", csv.string().c_str(),
                        png.string().c_str());
        else
            std::printf("\nwrote %s and game_step_rate.csv (gnuplot unavailable: no plot)\n",
                        csv.string().c_str());
    } else {
        std::printf("\n--quick: shorter runs, docs/bench/game_* left as they are\n");
    }
    return 0;
}

ks::bench::Registrar registrar{
    {"game", "headless game steps/s (main level), step time vs robots, step rate vs error", run}};

} // namespace
