#pragma once
// A play-test report: what the autoplay bot met in N runs of a level (game/playtest_analysis.h runs them),
// run by run and in aggregate, with heat maps of where it took damage and where it died. Plain data, its
// JSON file (LEVEL.playtest.json beside LEVEL.json, never inside it; the schema is in docs/editor.md,
// "Play-test reports") and the binning of points into x/z cells. Everything here is a pure function of the
// runs, so the same runs give the same report byte for byte.
#include "core/math.h"
#include "core/result.h"
#include "game/difficulty.h"
#include "geometry/aabb.h"
#include "level/level.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ks::game {

enum class RunOutcome : std::uint8_t { Win, Death, Timeout };
// "win", "death", "timeout": the words of HeadlessStats::outcome.
const char* run_outcome_name(RunOutcome outcome);

struct DamageSample {
    double time = 0.0;   // simulated seconds into the run
    Vec3 at{0.0f};       // the player's feet when hit
    Vec3 from{0.0f};     // where it came from (a robot's hand tip, a blast centre; the eye for a fall)
    float amount = 0.0f; // before the shield, as the PlayerDamaged event says
    bool operator==(const DamageSample&) const = default;
};

struct RunRecord {
    std::uint64_t seed = 1;
    RunOutcome outcome = RunOutcome::Timeout;
    double time = 0.0;         // simulated seconds when the run ended
    float damage_taken = 0.0f; // PlayerState::damage_taken at the end
    int robots_killed = 0, shots = 0;
    std::uint64_t state_hash = 0; // Game::state_hash at the end: the same run gives the same hash
    std::optional<Vec3> death;    // the feet where the player died
    std::vector<DamageSample> damage;
    std::vector<Vec3> path; // the feet at the start, every path interval, and where the run ended
    bool operator==(const RunRecord&) const = default;
};

// Mean, median, least and greatest of some numbers (all zero for none).
struct Spread {
    int count = 0;
    double mean = 0.0, median = 0.0, min = 0.0, max = 0.0;
    bool operator==(const Spread&) const = default;
};
Spread spread_of(std::vector<double> values);

// One cell of a heat map that something fell into: its column (x) and row (z), the sum of what fell in,
// and the mean height of the points (where to draw it: a level has floors at several heights).
struct HeatCell {
    int column = 0, row = 0;
    float value = 0.0f;
    float y = 0.0f;
    bool operator==(const HeatCell&) const = default;
};

// A grid of square cells over the ground plane: cell (c, r) covers x in [origin_x + c·size, +size) and
// z in [origin_z + r·size, +size). Only cells that hold something are listed, row by row.
struct HeatGrid {
    float cell_size = 4.0f;
    float origin_x = 0.0f, origin_z = 0.0f;
    int columns = 0, rows = 0;
    std::vector<HeatCell> cells;
    float max_value() const;
    bool operator==(const HeatGrid&) const = default;
};

// Sums values into the cells of a grid covering `area` (x and z; its corner snapped down to a multiple of
// the cell size, so the same point always lands in the same cell whatever the area).
class HeatBinner {
  public:
    HeatBinner(const geometry::Aabb& area, float cell_size);
    // False (and nothing added) for a point outside the grid or not finite.
    bool add(const Vec3& at, float value);
    bool cell_of(const Vec3& at, int& column, int& row) const;
    HeatGrid grid() const;

  private:
    HeatGrid shape_;
    std::vector<float> value_, height_sum_;
    std::vector<int> count_;
};

struct PlaytestReport {
    std::string level;      // the level's file name, or its name when it has no file
    std::string level_hash; // level_fingerprint() of the level analysed: a different one means stale
    int requested = 0;      // runs asked for: seeds 1..requested
    bool cancelled = false; // stopped early: `runs` holds the runs that had finished
    double seconds_limit = 300.0, path_interval = 0.25;
    std::string bot_profile = "perfect"; // who played (game/bot_profiles.h); absent in older files: perfect
    Difficulty difficulty = Difficulty::Normal;
    int wins = 0, deaths = 0, timeouts = 0;
    double win_rate = 0.0;       // wins / finished runs
    Spread time_to_win;          // over the won runs
    Spread damage_taken;         // over every finished run
    HeatGrid damage_heat;        // damage (before the shield) summed per cell
    HeatGrid death_heat;         // deaths counted per cell
    std::vector<RunRecord> runs; // by seed
    bool operator==(const PlaytestReport&) const = default;
    // Four lines for a terminal or the log: runs (profile, difficulty), win rate and times, damage, and where
    // the players died.
    std::string summary() const;
};

// What a report says besides the runs themselves.
struct ReportSetup {
    std::string level, level_hash;
    std::string bot_profile = "perfect";
    Difficulty difficulty = Difficulty::Normal;
    int requested = 0;
    bool cancelled = false;
    double seconds_limit = 300.0, path_interval = 0.25;
    float cell_size = 4.0f;
    geometry::Aabb level_area = geometry::Aabb::empty(); // the heat maps cover this and every point
};
PlaytestReport summarize_runs(std::vector<RunRecord> runs, const ReportSetup& setup);

// A place where players died: a death heat map cell's centre (x, z; y the deaths' mean height) and count.
struct DeathPlace {
    Vec3 at{0.0f};
    int deaths = 0;
    bool operator==(const DeathPlace&) const = default;
};
// The `most` cells with the most deaths, most first (ties: the first cell in row order).
std::vector<DeathPlace> deadliest_places(const PlaytestReport& report, std::size_t most);
// The designer's warning when the new-player bot died in most of the report's runs (empty otherwise): a
// person new to the game would most likely die here too. The summary ends with it; the editor shows it.
std::string new_player_warning(const PlaytestReport& report);

// 16 hex digits of FNV-1a over the level as its file would be written (level::save_level_string).
std::string level_fingerprint(const level::Level& level);
// LEVEL.playtest.json beside LEVEL.json (the level's extension replaced).
std::filesystem::path playtest_report_path(const std::filesystem::path& level_file);

std::string playtest_report_json(const PlaytestReport& report);
Result<PlaytestReport> parse_playtest_report(std::string_view text, const std::string& file_name);
Result<void> save_playtest_report(const std::filesystem::path& path, const PlaytestReport& report);
Result<PlaytestReport> load_playtest_report(const std::filesystem::path& path);

} // namespace ks::game
