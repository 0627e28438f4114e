#pragma once
// Helpers for the physics benchmarks: timing, tables, CSV under docs/bench/, gnuplot PNGs (a missing
// gnuplot prints a note and the benchmark still succeeds).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace ks::physics::bench {

inline double now_seconds() {
    using clock = std::chrono::steady_clock;
    return std::chrono::duration<double>(clock::now().time_since_epoch()).count();
}

// CPU time of this thread: on a shared machine it excludes time stolen by other processes (wall time is
// printed beside it).
inline double cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// The machine's load average (1, 5, 15 min) as /proc/loadavg prints it: timings are printed beside it.
inline std::string load_average() {
    std::ifstream in("/proc/loadavg");
    std::string a, b, c;
    if (!(in >> a >> b >> c)) return "unknown";
    return a + " " + b + " " + c;
}

inline std::filesystem::path bench_dir() {
    std::filesystem::path dir = std::filesystem::path(KS_SOURCE_DIR) / "docs" / "bench";
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    return dir;
}

// Writes `header` and rows as CSV to docs/bench/<name>.csv; returns the path.
inline std::filesystem::path write_csv(const std::string& name, const std::string& header,
                                       const std::vector<std::string>& rows) {
    const auto path = bench_dir() / (name + ".csv");
    std::ofstream out(path);
    out << header << "\n";
    for (const auto& r : rows) out << r << "\n";
    return path;
}

inline bool have_gnuplot() {
    static const bool found = std::system("command -v gnuplot >/dev/null 2>&1") == 0;
    return found;
}

// Runs a gnuplot script (the terminal and output are set here) writing docs/bench/<name>.png.
inline void plot(const std::string& name, const std::string& script) {
    if (!have_gnuplot()) {
        std::printf("note: gnuplot not found; %s.png not drawn (the CSV is written)\n", name.c_str());
        return;
    }
    const auto dir = bench_dir();
    const auto script_path = std::filesystem::temp_directory_path() / ("ks_" + name + ".gp");
    {
        std::ofstream gp(script_path);
        gp << "set terminal pngcairo size 900,560 font 'sans,10' noenhanced\n"
           << "set output '" << (dir / (name + ".png")).string() << "'\n"
           << "set datafile separator ','\n"
           << "set key top left\nset grid\n"
           << "cd '" << dir.string() << "'\n"
           << script;
    }
    const std::string cmd = "gnuplot '" + script_path.string() + "' 2>&1";
    if (std::system(cmd.c_str()) != 0)
        std::printf("note: gnuplot failed for %s.png\n", name.c_str());
    else
        std::printf("plot: docs/bench/%s.png\n", name.c_str());
    std::filesystem::remove(script_path);
}

inline std::string fmt(const char* f, double a) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, a);
    return buf;
}

} // namespace ks::physics::bench
