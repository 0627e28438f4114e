#include "game/playtest_report.h"

#include "level/level_io.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ks::game {

namespace {
// Heat maps of absurd extent (a point thrown far off by a broken level) would allocate without bound: the
// grid never grows past this many cells a side (its cells grow instead).
constexpr int kMaxCellsPerSide = 1024;
} // namespace

const char* run_outcome_name(RunOutcome outcome) {
    switch (outcome) {
    case RunOutcome::Win:
        return "win";
    case RunOutcome::Death:
        return "death";
    case RunOutcome::Timeout:
        return "timeout";
    }
    return "timeout";
}

Spread spread_of(std::vector<double> values) {
    Spread s;
    if (values.empty()) return s;
    std::sort(values.begin(), values.end());
    s.count = static_cast<int>(values.size());
    double sum = 0.0;
    for (double v : values) sum += v;
    s.mean = sum / static_cast<double>(values.size());
    const std::size_t mid = values.size() / 2;
    s.median = values.size() % 2 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
    s.min = values.front();
    s.max = values.back();
    return s;
}

float HeatGrid::max_value() const {
    float best = 0.0f;
    for (const HeatCell& c : cells) best = std::max(best, c.value);
    return best;
}

HeatBinner::HeatBinner(const geometry::Aabb& area, float cell_size) {
    float cell = std::isfinite(cell_size) && cell_size > 0.01f ? cell_size : 4.0f;
    geometry::Aabb a = area;
    if (!a.valid() || !std::isfinite(a.min.x) || !std::isfinite(a.max.x) || !std::isfinite(a.min.z) ||
        !std::isfinite(a.max.z))
        a = {Vec3(0.0f), Vec3(0.0f)};
    const float extent = std::max(a.max.x - a.min.x, a.max.z - a.min.z);
    while (extent / cell >= static_cast<float>(kMaxCellsPerSide - 1)) cell *= 2.0f;
    shape_.cell_size = cell;
    shape_.origin_x = std::floor(a.min.x / cell) * cell;
    shape_.origin_z = std::floor(a.min.z / cell) * cell;
    shape_.columns = static_cast<int>(std::floor((a.max.x - shape_.origin_x) / cell)) + 1;
    shape_.rows = static_cast<int>(std::floor((a.max.z - shape_.origin_z) / cell)) + 1;
    const auto n = static_cast<std::size_t>(shape_.columns) * static_cast<std::size_t>(shape_.rows);
    value_.assign(n, 0.0f);
    height_sum_.assign(n, 0.0f);
    count_.assign(n, 0);
}

bool HeatBinner::cell_of(const Vec3& at, int& column, int& row) const {
    if (!std::isfinite(at.x) || !std::isfinite(at.z)) return false;
    const float c = std::floor((at.x - shape_.origin_x) / shape_.cell_size);
    const float r = std::floor((at.z - shape_.origin_z) / shape_.cell_size);
    if (c < 0.0f || r < 0.0f || c >= static_cast<float>(shape_.columns) ||
        r >= static_cast<float>(shape_.rows))
        return false;
    column = static_cast<int>(c);
    row = static_cast<int>(r);
    return true;
}

bool HeatBinner::add(const Vec3& at, float value) {
    int column = 0, row = 0;
    if (!std::isfinite(at.y) || !std::isfinite(value) || !cell_of(at, column, row)) return false;
    const auto i = static_cast<std::size_t>(row) * static_cast<std::size_t>(shape_.columns) +
                   static_cast<std::size_t>(column);
    value_[i] += value;
    height_sum_[i] += at.y;
    ++count_[i];
    return true;
}

HeatGrid HeatBinner::grid() const {
    HeatGrid g = shape_;
    for (int row = 0; row < shape_.rows; ++row)
        for (int column = 0; column < shape_.columns; ++column) {
            const auto i = static_cast<std::size_t>(row) * static_cast<std::size_t>(shape_.columns) +
                           static_cast<std::size_t>(column);
            if (count_[i] == 0) continue;
            g.cells.push_back({column, row, value_[i], height_sum_[i] / static_cast<float>(count_[i])});
        }
    return g;
}

PlaytestReport summarize_runs(std::vector<RunRecord> runs, const ReportSetup& setup) {
    std::sort(runs.begin(), runs.end(),
              [](const RunRecord& a, const RunRecord& b) { return a.seed < b.seed; });
    PlaytestReport r;
    r.level = setup.level;
    r.level_hash = setup.level_hash;
    r.requested = setup.requested;
    r.cancelled = setup.cancelled;
    r.seconds_limit = setup.seconds_limit;
    r.path_interval = setup.path_interval;
    r.bot_profile = setup.bot_profile;
    r.difficulty = setup.difficulty;
    std::vector<double> win_times, damage;
    geometry::Aabb area = setup.level_area;
    auto grow = [&area](const Vec3& p) {
        if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) area.grow(p);
    };
    for (const RunRecord& run : runs) {
        if (run.outcome == RunOutcome::Win) ++r.wins, win_times.push_back(run.time);
        if (run.outcome == RunOutcome::Death) ++r.deaths;
        if (run.outcome == RunOutcome::Timeout) ++r.timeouts;
        damage.push_back(run.damage_taken);
        for (const DamageSample& d : run.damage) grow(d.at);
        if (run.death) grow(*run.death);
    }
    r.win_rate = runs.empty() ? 0.0 : static_cast<double>(r.wins) / static_cast<double>(runs.size());
    r.time_to_win = spread_of(std::move(win_times));
    r.damage_taken = spread_of(std::move(damage));
    HeatBinner damage_bins(area, setup.cell_size), death_bins(area, setup.cell_size);
    for (const RunRecord& run : runs) {
        for (const DamageSample& d : run.damage) damage_bins.add(d.at, d.amount);
        if (run.death) death_bins.add(*run.death, 1.0f);
    }
    r.damage_heat = damage_bins.grid();
    r.death_heat = death_bins.grid();
    r.runs = std::move(runs);
    return r;
}

std::vector<DeathPlace> deadliest_places(const PlaytestReport& report, std::size_t most) {
    const HeatGrid& g = report.death_heat;
    std::vector<DeathPlace> places;
    for (const HeatCell& c : g.cells)
        places.push_back({Vec3(g.origin_x + (static_cast<float>(c.column) + 0.5f) * g.cell_size, c.y,
                               g.origin_z + (static_cast<float>(c.row) + 0.5f) * g.cell_size),
                          static_cast<int>(std::lround(c.value))});
    std::stable_sort(places.begin(), places.end(),
                     [](const DeathPlace& a, const DeathPlace& b) { return a.deaths > b.deaths; });
    if (places.size() > most) places.resize(most);
    return places;
}

std::string new_player_warning(const PlaytestReport& report) {
    const int finished = static_cast<int>(report.runs.size());
    if (report.bot_profile != "new-player" || finished == 0 || 2 * report.deaths <= finished) return {};
    std::string warning = "warning: the new-player bot died in " + std::to_string(report.deaths) + " of " +
                          std::to_string(finished) + " runs";
    if (const auto places = deadliest_places(report, 1); !places.empty()) {
        char at[96];
        std::snprintf(at, sizeof at, ", most at (%.0f, %.0f, %.0f)", static_cast<double>(places[0].at.x),
                      static_cast<double>(places[0].at.y), static_cast<double>(places[0].at.z));
        warning += at;
    }
    return warning + ": a new player would most likely die there too (give the fight cover, fewer or weaker "
                     "robots, or health before it)";
}

std::string PlaytestReport::summary() const {
    const int finished = static_cast<int>(runs.size());
    char head[320], wins_line[256], damage_line[256];
    std::snprintf(head, sizeof head, "%s: %d of %d runs%s (seeds 1..%d, %.0f s limit each; bot %s, %s)",
                  level.c_str(), finished, requested, cancelled ? " (cancelled)" : "", requested,
                  seconds_limit, bot_profile.c_str(), difficulty_name(difficulty));
    if (time_to_win.count > 0)
        std::snprintf(wins_line, sizeof wins_line,
                      "won %d (%.0f %%), died %d, timed out %d; time to win mean %.1f s, median %.1f s, "
                      "min %.1f s, max %.1f s",
                      wins, 100.0 * win_rate, deaths, timeouts, time_to_win.mean, time_to_win.median,
                      time_to_win.min, time_to_win.max);
    else
        std::snprintf(wins_line, sizeof wins_line, "won none, died %d, timed out %d", deaths, timeouts);
    std::snprintf(damage_line, sizeof damage_line,
                  "damage taken mean %.0f, median %.0f, max %.0f; heat map: %zu cells hit, %zu with deaths",
                  damage_taken.mean, damage_taken.median, damage_taken.max, damage_heat.cells.size(),
                  death_heat.cells.size());
    std::string deaths_line;
    for (const DeathPlace& place : deadliest_places(*this, 3)) {
        char one[96];
        std::snprintf(one, sizeof one, "%s(%.0f, %.0f, %.0f) x%d", deaths_line.empty() ? "" : ", ",
                      static_cast<double>(place.at.x), static_cast<double>(place.at.y),
                      static_cast<double>(place.at.z), place.deaths);
        deaths_line += one;
    }
    deaths_line = deaths_line.empty() ? "no deaths" : "died most at (x, y, z) " + deaths_line;
    const std::string warning = new_player_warning(*this);
    return std::string(head) + "\n" + wins_line + "\n" + damage_line + "\n" + deaths_line +
           (warning.empty() ? "" : "\n" + warning);
}

std::string level_fingerprint(const level::Level& level) {
    std::uint64_t h = 1469598103934665603ull;
    for (const unsigned char c : level::save_level_string(level)) {
        h ^= c;
        h *= 1099511628211ull;
    }
    char text[24];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
    return text;
}

std::filesystem::path playtest_report_path(const std::filesystem::path& level_file) {
    std::filesystem::path p = level_file;
    p.replace_extension(".playtest.json");
    return p;
}

} // namespace ks::game
