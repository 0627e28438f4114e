#pragma once
// Runs the game without a window: `killswitch --headless --level FILE [--seconds S] [--seed N] [--autoplay]
// [--record FILE | --replay FILE] [--stats-json FILE|-] [--logic-trace FILE|-] [--difficulty
// easy|normal|hard] [--bot-profile NAME]`. The runtime's main calls
//   auto options = ks::game::parse_headless_options(command_line);   // Result<HeadlessOptions>
//   auto stats = ks::game::run_headless(*options);                     // Result<HeadlessStats>
// and returns exit code 0 on success (print stats->summary()). Without --autoplay or --replay the player
// stands still (a soak test of the AI). A replay runs exactly its recorded steps with its recorded seed.
#include "core/cli.h"
#include "core/result.h"
#include "game/game.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace ks::game {

struct HeadlessOptions {
    std::filesystem::path level;
    double seconds = 300.0; // simulated time limit
    std::uint64_t seed = 1;
    bool autoplay = false;
    Difficulty difficulty = Difficulty::Normal;
    std::string bot_profile = "perfect";              // game/bot_profiles.h; only with autoplay
    std::filesystem::path record, replay, stats_json; // stats_json "-" = stdout
    std::filesystem::path
        logic_trace; // every logic event and action, a line each (logic_trace.h); "-" = stdout
    // Observers a driver adds (the runtime's --audio-out recorder): called once the level and game exist,
    // after every step, and once at the end (the game in its final state). An error stops the run and is
    // returned.
    std::function<Result<void>(const level::Level&, const Game&)> on_start;
    std::function<Result<void>(const Game&)> after_step;
    std::function<Result<void>(const Game&)> on_finish;
};

struct HeadlessStats {
    std::string outcome = "timeout"; // win, death, timeout
    double sim_time_s = 0.0;
    int robots_killed = 0;
    float damage_taken = 0.0f;
    int shots = 0;
    double steps_per_second = 0.0;
    std::uint64_t state_hash = 0;
    std::int64_t steps = 0;
    std::string to_json() const; // one line
    std::string summary() const;
};

// The option names (for the runtime's CommandLine::parse flags and unknown-option checks).
const std::vector<std::string>& headless_flags();        // --headless, --autoplay
const std::vector<std::string>& headless_option_names(); // every option above
Result<HeadlessOptions> parse_headless_options(const CommandLine& command_line);
// --seconds (in (0, 86400]; `seconds` keeps its default when absent) and --seed (a non-negative integer),
// shared by every headless command line; `seconds_hint` says what the limit applies to in the error's fix.
Result<void> parse_run_limits(const CommandLine& command_line, double& seconds, std::uint64_t& seed,
                              std::string_view seconds_hint);
// --difficulty (game/difficulty.h; `difficulty` keeps its value when absent).
Result<void> parse_difficulty_option(const CommandLine& command_line, Difficulty& difficulty);
Result<HeadlessStats> run_headless(const HeadlessOptions& options);

} // namespace ks::game
