// ks_bench soak: the headless game plays the main level and a generated large level (30 rooms, 116
// robots) for a simulated hour each with the autoplay bot (then idle, the world still running), checking
// every step for NaN and sampling VmRSS every simulated minute. Prints one table per level, writes
// docs/bench/soak.csv and docs/bench/soak_rss.png, exits 1 on a non-finite value or RSS growth after the
// warm-up beyond --rss-limit. Not in `ks_bench all` (an hour each is several CPU minutes).
//   ks_bench soak [--minutes M] [--level main|large|both] [--columns C] [--rows R] [--robots-per-room N]
//                 [--seed S] [--warm-up MINUTES] [--rss-limit KIB] [--no-files]
#include "bench_registry.h"
#include "core/paths.h"
#include "level/level_io.h"
#include "physics/bench_util.h" // bench/physics/
#include "soak/soak.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

using namespace ks;

std::string load_average() {
    std::FILE* f = std::fopen("/proc/loadavg", "r");
    char buffer[128] = "?";
    if (f) {
        if (!std::fgets(buffer, sizeof buffer, f)) std::snprintf(buffer, sizeof buffer, "?");
        std::fclose(f);
    }
    std::string s = buffer;
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
    return s;
}

const char* phase_name(game::Phase p) {
    return p == game::Phase::Playing ? "playing" : p == game::Phase::Won ? "won" : "dead";
}

struct LevelRun {
    std::string name;
    soak::SoakResult result;
};

int run(int argc, const char* const* argv) {
    double minutes = 60.0, warm_up_minutes = 5.0;
    long rss_limit_kib = 2048;
    std::string which = "both";
    soak::LargeLevelOptions large;
    std::uint64_t seed = 1;
    bool files = true;
    for (int i = 1; i < argc; ++i) {
        auto value = [&](const char* name) -> const char* {
            if (std::strcmp(argv[i], name) != 0) return nullptr;
            if (i + 1 >= argc) {
                std::fprintf(stderr, "soak: %s needs a value\n", name);
                std::exit(2);
            }
            return argv[++i];
        };
        if (const char* v = value("--minutes"))
            minutes = std::atof(v);
        else if (const char* v = value("--level"))
            which = v;
        else if (const char* v = value("--columns"))
            large.columns = std::atoi(v);
        else if (const char* v = value("--rows"))
            large.rows = std::atoi(v);
        else if (const char* v = value("--robots-per-room"))
            large.robots_per_room = std::atoi(v);
        else if (const char* v = value("--seed"))
            seed = std::strtoull(v, nullptr, 10);
        else if (const char* v = value("--warm-up"))
            warm_up_minutes = std::atof(v);
        else if (const char* v = value("--rss-limit"))
            rss_limit_kib = std::atol(v);
        else if (std::strcmp(argv[i], "--no-files") == 0)
            files = false;
        else {
            std::fprintf(
                stderr,
                "soak: unknown option '%s' (see the comment at the top of bench/soak/bench_soak.cpp)\n",
                argv[i]);
            return 2;
        }
    }
    if (!(minutes > 0.0 && minutes <= 24 * 60) || large.columns < 1 || large.rows < 1 ||
        large.columns * large.rows < 2 || large.robots_per_room < 0 ||
        (which != "main" && which != "large" && which != "both")) {
        std::fprintf(stderr, "soak: --minutes in (0, 1440], --columns/--rows >= 1 (2 rooms at least), "
                             "--level main|large|both\n");
        return 2;
    }

    std::vector<std::pair<std::string, level::Level>> levels;
    if (which != "large") {
        auto main_level = level::load_level_file(paths::level("main.json"));
        if (!main_level) {
            std::fprintf(stderr, "%s\n", main_level.error().str().c_str());
            return 1;
        }
        levels.emplace_back("main", std::move(*main_level));
    }
    large.seed = seed;
    if (which != "main") levels.emplace_back("large", soak::large_level(large));

    std::printf(
        "Soak: %.0f simulated minutes per level, autoplay bot (then idle), NaN check every step, VmRSS "
        "every simulated minute. Load average at start: %s\n",
        minutes, load_average().c_str());
    std::vector<LevelRun> runs;
    std::vector<std::string> csv_rows;
    int failures = 0;
    for (auto& [name, lv] : levels) {
        soak::SoakOptions options;
        options.sim_seconds = minutes * 60.0;
        options.seed = seed;
        options.immortal = name == "large";
        options.restart_on_end = name == "main"; // main: round after round; large: one world all hour
        std::printf("\n%s level (%zu entities)%s\n", name.c_str(), lv.entities.size(),
                    options.immortal ? ", player immortal, one game (idle after the bot wins)"
                                     : ", a new round whenever the bot wins or dies");
        std::printf("%8s %9s %9s %9s %7s %8s %7s %6s %6s %5s %9s %8s\n", "sim min", "RSS MiB", "dRSS KiB",
                    "CPU s", "alive", "engaged", "moving", "shots", "kills", "ammo", "to panel", "phase");
        long first_rss = -1;
        auto row = [&](const soak::SoakSample& s) {
            if (first_rss < 0) first_rss = s.rss_kib;
            std::printf("%8.1f %9.2f %9ld %9.2f %7d %8d %7d %6d %6d %5d %9.1f %8s\n", s.sim_time / 60.0,
                        s.rss_kib / 1024.0, s.rss_kib - first_rss, s.cpu_s, s.robots_alive, s.robots_engaged,
                        s.robots_moving, s.shots, s.kills, s.ammo, s.to_panel, phase_name(s.phase));
            std::fflush(stdout);
            csv_rows.push_back(name + "," + ks::physics::bench::fmt("%.1f", s.sim_time / 60.0) + "," +
                               std::to_string(s.rss_kib) + "," + ks::physics::bench::fmt("%.3f", s.cpu_s) +
                               "," + std::to_string(s.robots_alive) + "," + std::to_string(s.robots_engaged) +
                               "," + std::to_string(s.robots_moving));
        };
        soak::SoakResult r = soak::run_soak(lv, options, row);
        const long growth = r.rss_growth_after(warm_up_minutes * 60.0);
        std::printf("%s: %d robots; first round %s", name.c_str(), r.robots, r.outcome.c_str());
        if (r.outcome_time >= 0.0) std::printf(" at %.1f s", r.outcome_time);
        std::printf("; %d round(s): %d won, %d lost", r.rounds, r.wins, r.deaths);
        std::printf("; %lld steps in %.1f CPU s (%.0f steps per CPU s); %d events; state %016llx\n",
                    static_cast<long long>(r.steps), r.cpu_s, r.cpu_s > 0 ? r.steps / r.cpu_s : 0.0, r.events,
                    static_cast<unsigned long long>(r.state_hash));
        std::printf("RSS growth after %.0f min warm-up: %ld KiB (limit %ld); non-finite values: %s\n",
                    warm_up_minutes, growth, rss_limit_kib, r.problem.empty() ? "none" : r.problem.c_str());
        if (!r.problem.empty() || growth > rss_limit_kib ||
            r.steps < static_cast<std::int64_t>(options.sim_seconds * 120.0 - 1)) {
            std::printf("FAILED\n");
            ++failures;
        }
        runs.push_back({name, std::move(r)});
    }
    std::printf("\nLoad average at the end: %s\n", load_average().c_str());

    if (files && minutes >= 10.0) {
        namespace b = ks::physics::bench;
        const auto path = b::write_csv(
            "soak", "level,sim_minutes,rss_kib,cpu_s,robots_alive,robots_engaged,robots_moving", csv_rows);
        std::printf("wrote %s\n", path.string().c_str());
        std::string script =
            "set title 'Soak: resident memory per simulated minute'\nset xlabel 'simulated minutes'\n"
            "set ylabel 'VmRSS (MiB)'\nplot ";
        for (std::size_t i = 0; i < runs.size(); ++i)
            script += (i ? ", " : "") + std::string("'soak.csv' every ::1 using (strcol(1) eq '") +
                      runs[i].name + "' ? $2 : 1/0):($3/1024) with linespoints title '" + runs[i].name +
                      " level'";
        b::plot("soak_rss", script + "\n");
    }
    return failures == 0 ? 0 : 1;
}

ks::bench::Registrar registrar{{"soak",
                                "one simulated hour per level (main, generated large) with the bot: NaN, RSS",
                                run, /*in_default_suite=*/false}};

} // namespace
