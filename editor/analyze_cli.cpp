#include "analyze_cli.h"

#include "core/files.h"
#include "core/paths.h"
#include "game/bot_profiles.h"
#include "game/playtest_analysis.h"
#include "level/campaign.h"
#include "level/level_io.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <sstream>

namespace ks::editor {

namespace {
int usage_error(const std::string& message) {
    std::fprintf(stderr, "killswitch-editor --analyze: %s\n", message.c_str());
    return 2;
}

// "a,b,c" as its words (empty words dropped).
std::vector<std::string> words(const std::string& list) {
    std::vector<std::string> out;
    std::stringstream in(list);
    for (std::string word; std::getline(in, word, ',');)
        if (!word.empty()) out.push_back(word);
    return out;
}

// What to play: the profiles and difficulties asked for (each a comma-separated list), checked.
struct Matrix {
    std::vector<std::string> profiles;
    std::vector<game::Difficulty> difficulties;
};

Result<Matrix> read_matrix(const CommandLine& cl) {
    Matrix m;
    m.profiles = words(cl.get_or("bot-profile", "perfect"));
    for (const std::string& p : m.profiles)
        if (auto known = game::bot_profile(p, Location("command line", 0, 0, "--bot-profile")); !known)
            return known.error();
    for (const std::string& d : words(cl.get_or("difficulty", "normal"))) {
        auto parsed = game::parse_difficulty(d, Location("command line", 0, 0, "--difficulty"));
        if (!parsed) return parsed.error();
        m.difficulties.push_back(*parsed);
    }
    if (m.profiles.empty() || m.difficulties.empty())
        return Error("nothing to play", Location("command line"),
                     "e.g. --bot-profile perfect,new-player --difficulty easy,normal,hard");
    return m;
}

// The levels of FILE: the campaign's, in order, when FILE is a campaign ({"levels": [...]}), else FILE.
Result<std::vector<std::filesystem::path>> levels_of(const std::filesystem::path& file) {
    auto text = files::read_text(file);
    if (!text) return text.error();
    const auto json = nlohmann::json::parse(*text, nullptr, false);
    if (!json.is_object() || !json.contains("levels") || json.contains("entities"))
        return std::vector<std::filesystem::path>{file};
    auto campaign = level::load_campaign(file);
    if (!campaign) return campaign.error();
    std::vector<std::filesystem::path> out;
    for (const level::CampaignLevel& l : campaign->levels) out.push_back(level::campaign_level_path(file, l));
    return out;
}

// One row of the table: level, bot, difficulty, wins of runs, win rate, deaths, damage, where they died.
void print_row(const game::PlaytestReport& r) {
    std::string places;
    for (const game::DeathPlace& p : game::deadliest_places(r, 3)) {
        char one[64];
        std::snprintf(one, sizeof one, "%s(%.0f, %.0f, %.0f) x%d", places.empty() ? "" : " ",
                      static_cast<double>(p.at.x), static_cast<double>(p.at.y), static_cast<double>(p.at.z),
                      p.deaths);
        places += one;
    }
    std::printf("| %s | %s | %s | %d/%zu | %.0f %% | %d | %d | %.0f | %s |\n", r.level.c_str(),
                r.bot_profile.c_str(), game::difficulty_name(r.difficulty), r.wins, r.runs.size(),
                100.0 * r.win_rate, r.deaths, r.timeouts, r.damage_taken.mean,
                places.empty() ? "-" : places.c_str());
}

// Several levels or players: a table, one row per level, bot and difficulty; no report file.
int run_table(const std::vector<std::filesystem::path>& levels, const Matrix& matrix,
              game::AnalysisOptions options) {
    std::printf("| level | bot | difficulty | won | win rate | died | timed out | damage mean | died most at "
                "(x, y, z) |\n|---|---|---|---|---|---|---|---|---|\n");
    for (const std::filesystem::path& file : levels) {
        auto level = level::load_level_file(file);
        if (!level) {
            std::fprintf(stderr, "%s\n", level.error().str().c_str());
            return 1;
        }
        options.level_name = file.filename().string();
        for (const std::string& profile : matrix.profiles)
            for (game::Difficulty difficulty : matrix.difficulties) {
                options.bot_profile = profile;
                options.difficulty = difficulty;
                auto report = game::analyze_level(*level, options);
                if (!report) {
                    std::fprintf(stderr, "%s\n", report.error().str().c_str());
                    return 1;
                }
                print_row(*report);
                std::fflush(stdout);
            }
    }
    return 0;
}
} // namespace

const std::vector<std::string>& analyze_option_names() {
    static const std::vector<std::string> names{"analyze", "runs",        "report",    "seconds",
                                                "threads", "bot-profile", "difficulty"};
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
    auto matrix = read_matrix(cl);
    if (!matrix) return usage_error(matrix.error().str());
    options.bot_profile = matrix->profiles.front();
    options.difficulty = matrix->difficulties.front();
    if (auto checked = game::check_analysis_options(options); !checked)
        return usage_error(checked.error().str());
    auto levels = levels_of(level_file);
    if (!levels) {
        std::fprintf(stderr, "%s\n", levels.error().str().c_str());
        return 1;
    }
    if (levels->size() > 1 || matrix->profiles.size() > 1 || matrix->difficulties.size() > 1) {
        if (cl.has("report"))
            return usage_error("--report takes one level, one --bot-profile and one --difficulty (a table "
                               "of several is printed, not written)");
        return run_table(*levels, *matrix, options);
    }
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
