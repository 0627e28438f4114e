#include "analyze_cli.h"

#include "core/paths.h"
#include "game/playtest_analysis.h"
#include "level/level_io.h"

#include <chrono>
#include <cstdio>
#include <filesystem>

namespace ks::editor {

namespace {
int usage_error(const std::string& message) {
    std::fprintf(stderr, "killswitch-editor --analyze: %s\n", message.c_str());
    return 2;
}
} // namespace

const std::vector<std::string>& analyze_option_names() {
    static const std::vector<std::string> names{"analyze", "runs", "report", "seconds", "threads"};
    return names;
}

int run_analyze_mode(const CommandLine& cl) {
    const std::string given = cl.get_or("analyze", "");
    if (given.empty()) return usage_error("give the level to analyse: --analyze LEVEL.json");
    const std::filesystem::path level_file = paths::resolve_user_path(given);
    game::AnalysisOptions options;
    auto runs = cl.get_int("runs", options.runs, 1, 10000);
    if (!runs) return usage_error(runs.error().str());
    options.runs = *runs;
    auto seconds = cl.get_double("seconds", options.seconds);
    if (!seconds) return usage_error(seconds.error().str());
    options.seconds = *seconds;
    auto threads = cl.get_int("threads", 0, 0, game::kMaxAnalysisThreads);
    if (!threads) return usage_error(threads.error().str());
    options.threads = *threads;
    options.level_name = level_file.filename().string();
    if (auto checked = game::check_analysis_options(options); !checked)
        return usage_error(checked.error().str());
    const std::filesystem::path report_file = cl.has("report") ? paths::resolve_user_path(*cl.get("report"))
                                                               : game::playtest_report_path(level_file);
    std::error_code ec;
    if (std::filesystem::weakly_canonical(report_file, ec) ==
        std::filesystem::weakly_canonical(level_file, ec))
        return usage_error("--report " + report_file.string() +
                           " is the level itself: the report goes beside the level, never into it (e.g. " +
                           game::playtest_report_path(level_file).string() + ")");

    auto level = level::load_level_file(level_file);
    if (!level) {
        std::fprintf(stderr, "%s\n", level.error().str().c_str());
        return 1;
    }
    const auto start = std::chrono::steady_clock::now();
    auto report = game::analyze_level(*level, options);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!report) {
        std::fprintf(stderr, "%s\n", report.error().str().c_str());
        return 1;
    }
    if (auto saved = game::save_playtest_report(report_file, *report); !saved) {
        std::fprintf(stderr, "%s\n", saved.error().str().c_str());
        return 1;
    }
    std::printf("%s\n", report->summary().c_str());
    std::printf("%d runs in %.2f s (%.2f runs/s, %d threads); report written to %s\n", options.runs, wall,
                wall > 0.0 ? options.runs / wall : 0.0, game::analysis_threads(options.threads, options.runs),
                report_file.string().c_str());
    return 0;
}

} // namespace ks::editor
