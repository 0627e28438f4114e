// ks_bench playtest: the editor's Analyze (game/playtest_analysis.h) on levels/main.json: N bot runs
// (default 20, seeds 1..N) with one worker thread and with every hardware thread, wall seconds and runs per
// second (median of --reps), that both give the same report, and where the time goes (the two navigation
// meshes, built once; each run's game build on a copy of the robots' mesh; the steps).
//   ks_bench playtest [--runs N] [--reps R] [--quick]
#include "bench_registry.h"
#include "core/paths.h"
#include "game/autoplay.h"
#include "game/playtest_analysis.h"
#include "level/level_io.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace ks;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

std::string load_average() {
    std::FILE* f = std::fopen("/proc/loadavg", "r");
    char text[64] = "?";
    if (f) {
        if (!std::fgets(text, sizeof text, f)) std::strcpy(text, "?");
        std::fclose(f);
    }
    std::string s = text;
    return s.substr(0, s.find(' ', s.find(' ', s.find(' ') + 1) + 1));
}

// Where one run's time goes, single-threaded: the analysis' fixed cost (the bot's mesh and the robots' mesh,
// built side by side), then per run the game's build on a copy of the robots' mesh and the steps to the end.
void breakdown(const level::Level& level, double seconds) {
    const auto t0 = Clock::now();
    auto bot_mesh = game::build_autoplay_mesh(level, game::AutoplaySettings{}.cylinder_keep_out);
    const double bot_mesh_s = seconds_since(t0);
    const auto t1 = Clock::now();
    auto robot_mesh = game::build_robot_navigation(level);
    const double robot_mesh_s = seconds_since(t1);
    if (!bot_mesh || !robot_mesh) return;
    const std::shared_ptr<const nav::NavMesh> shared_robot_mesh = std::move(*robot_mesh);
    game::GameOptions fresh, copied;
    copied.navigation = shared_robot_mesh;
    (void)game::Game::create(level, fresh); // the robot clips, loaded once per process
    const auto t2 = Clock::now();
    auto built = game::Game::create(level, fresh);
    const double fresh_s = seconds_since(t2);
    const auto t3 = Clock::now();
    auto made = game::Game::create(level, copied);
    const double copied_s = seconds_since(t3);
    if (!built || !made) return;
    game::Game& g = **made;
    game::Autoplay bot(g, *bot_mesh, 1);
    const auto t4 = Clock::now();
    const auto limit = static_cast<std::int64_t>(seconds / g.settings().step);
    while (g.steps() < limit && g.phase() == game::Phase::Playing) g.step(bot.decide(g));
    const double play_s = seconds_since(t4);
    std::printf("once per analysis: the bot's mesh %.0f ms, the robots' mesh %.0f ms (side by side)\n"
                "per run: the game's build %.1f ms on a copy of the robots' mesh (%.0f ms building its own); "
                "seed 1 won in %lld steps, %.1f ms (%.0f steps/s)\n\n",
                1000.0 * bot_mesh_s, 1000.0 * robot_mesh_s, 1000.0 * copied_s, 1000.0 * fresh_s,
                static_cast<long long>(g.steps()), 1000.0 * play_s,
                static_cast<double>(g.steps()) / std::max(play_s, 1e-9));
}

int run_playtest(int argc, const char* const* argv) {
    int runs = 20, reps = 3;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--quick")) runs = 4, reps = 1;
        if (!std::strcmp(argv[i], "--runs") && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
        if (!std::strcmp(argv[i], "--reps") && i + 1 < argc) reps = std::max(1, std::atoi(argv[++i]));
    }
    const auto file = paths::level("main.json");
    auto level = level::load_level_file(file);
    if (!level) {
        std::fprintf(stderr, "%s\n", level.error().str().c_str());
        return 1;
    }
    const int hardware = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    std::printf("play-test analysis of levels/main.json: %d bot runs (seeds 1..%d, 300 s limit each), median "
                "of %d; %d hardware threads; load average %s\n\n",
                runs, runs, reps, hardware, load_average().c_str());
    breakdown(*level, 300.0);
    std::printf("%-10s %12s %10s %10s   %s\n", "threads", "seconds", "runs/s", "speed-up", "report");
    std::string first_json;
    double one_thread = 0.0;
    for (int threads : {1, hardware}) {
        std::vector<double> times;
        std::string summary, json;
        for (int r = 0; r < reps; ++r) {
            game::AnalysisOptions options;
            options.runs = runs;
            options.threads = threads;
            options.level_name = "main.json";
            const auto start = Clock::now();
            auto report = game::analyze_level(*level, options);
            times.push_back(seconds_since(start));
            if (!report) {
                std::fprintf(stderr, "%s\n", report.error().str().c_str());
                return 1;
            }
            json = game::playtest_report_json(*report);
            summary = std::to_string(report->wins) + "/" + std::to_string(report->runs.size()) + " won";
        }
        if (first_json.empty()) first_json = json;
        const double t = median(times);
        if (threads == 1) one_thread = t;
        std::printf("%-10d %12.2f %10.2f %10.2f   %s, %s\n", threads, t, runs / t, one_thread / t,
                    summary.c_str(), json == first_json ? "same report" : "REPORT DIFFERS");
        if (json != first_json) return 1;
        if (hardware == 1) break;
    }
    return 0;
}

bench::Registrar
    registrar({"playtest",
               "editor Analyze: 20 bot runs of the main level, one thread against every hardware "
               "thread",
               run_playtest});

} // namespace
