// The play-test report's JSON file (docs/editor.md, "Play-test reports"): written with the project's
// deterministic writer (shortest round-trip numbers, a float as its own shortest form), read back with
// every problem located by line:column and JSON path.
#include "core/files.h"
#include "game/playtest_report.h"
#include "jsonio/describe.h"
#include "jsonio/document.h"
#include "jsonio/json_path.h"
#include "jsonio/json_writer.h"
#include "jsonio/number_text.h"
#include "jsonio/object_reader.h"
#include "jsonio/text.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>

namespace ks::game {

namespace {
using jsonio::Json;
constexpr const char* kFormat = "killswitch-playtest-report";
constexpr int kVersion = 1;

Json number(float v) {
    return jsonio::float_to_double(v);
}
Json point(const Vec3& p) {
    return Json::array({number(p.x), number(p.y), number(p.z)});
}
std::string hex(std::uint64_t value) {
    char text[24];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
    return text;
}
Json spread_json(const Spread& s) {
    return {{"count", s.count}, {"mean", s.mean}, {"median", s.median}, {"min", s.min}, {"max", s.max}};
}
Json cells_json(const std::vector<HeatCell>& cells) {
    Json out = Json::array();
    for (const HeatCell& c : cells)
        out.push_back(Json::array({c.column, c.row, number(c.value), number(c.y)}));
    return out;
}
Json run_json(const RunRecord& run) {
    Json damage = Json::array();
    for (const DamageSample& d : run.damage)
        damage.push_back(
            {{"time", d.time}, {"at", point(d.at)}, {"from", point(d.from)}, {"amount", number(d.amount)}});
    Json path = Json::array(); // x, y, z of each sample, one flat list (a file of thousands of points)
    for (const Vec3& p : run.path)
        path.push_back(number(p.x)), path.push_back(number(p.y)), path.push_back(number(p.z));
    Json j;
    j["seed"] = run.seed;
    j["outcome"] = run_outcome_name(run.outcome);
    j["time"] = run.time;
    j["damage_taken"] = number(run.damage_taken);
    j["robots_killed"] = run.robots_killed;
    j["shots"] = run.shots;
    j["state_hash"] = hex(run.state_hash);
    j["death"] = run.death ? point(*run.death) : Json(nullptr);
    j["damage"] = damage;
    j["path"] = path;
    return j;
}

using jsonio::Need;
using jsonio::ObjectReader;
using jsonio::Range;
const Range kAny{};
const Range kCount{0, 1 << 30};
const char* const kRerun = "write the report again (killswitch-editor --analyze) or see docs/editor.md";

void error(ObjectReader& in, std::string_view key, std::string message, std::string hint) {
    in.sink().report(jsonio::Severity::Error, in.path_of(key), std::move(message), std::move(hint));
}

// An array of `n` finite numbers, as floats.
bool floats(ObjectReader& in, std::string_view key, std::size_t n, float* out, Need need = Need::Required) {
    double read[4] = {};
    if (!in.numbers(key, read, n, kAny, need)) return false;
    for (std::size_t i = 0; i < n; ++i) out[i] = static_cast<float>(read[i]);
    return true;
}

// A required array member; an empty one when it is missing or not an array (reported).
const Json& array(ObjectReader& in, std::string_view key) {
    static const Json empty = Json::array();
    const Json* v = in.get(key, Need::Required, kRerun);
    if (v && !v->is_array()) error(in, key, "expected an array, found " + jsonio::describe_value(*v), kRerun);
    return v && v->is_array() ? *v : empty;
}

Spread read_spread(ObjectReader& parent, const char* key) {
    Spread s;
    const Json* j = parent.get(key, Need::Required, kRerun);
    if (!j) return s;
    ObjectReader in(*j, parent.path_of(key), parent.sink(), "a spread");
    in.whole("count", s.count, kCount, Need::Required);
    in.number("mean", s.mean, kAny, Need::Required);
    in.number("median", s.median, kAny, Need::Required);
    in.number("min", s.min, kAny, Need::Required);
    in.number("max", s.max, kAny, Need::Required);
    in.finish();
    return s;
}

HeatGrid read_grid(ObjectReader& heat, const char* key) {
    HeatGrid g;
    heat.number("cell_size", g.cell_size, kAny, Need::Required);
    float origin[2] = {0.0f, 0.0f};
    floats(heat, "origin", 2, origin);
    g.origin_x = origin[0];
    g.origin_z = origin[1];
    heat.whole("columns", g.columns, {0, 1 << 20}, Need::Required);
    heat.whole("rows", g.rows, {0, 1 << 20}, Need::Required);
    const Json& cells = array(heat, key);
    const std::string cells_path = heat.path_of(key);
    for (std::size_t i = 0; i < cells.size(); ++i) {
        const std::string at = jsonio::element_path(cells_path, i);
        const Json& cell = cells[i];
        if (!cell.is_array() || cell.size() != 4) {
            heat.sink().report(
                jsonio::Severity::Error, at,
                "expected a cell [column, row, value, y], found " + jsonio::describe_value(cell), kRerun);
            continue;
        }
        double v[4] = {};
        bool ok = true;
        for (std::size_t k = 0; k < 4; ++k)
            ok &= jsonio::read_number(cell[k], jsonio::element_path(at, k), heat.sink(), v[k], kAny);
        if (!ok) continue;
        if (v[0] != std::floor(v[0]) || v[1] != std::floor(v[1]) || v[0] < 0 || v[1] < 0 ||
            v[0] >= g.columns || v[1] >= g.rows)
            heat.sink().report(jsonio::Severity::Error, at,
                               "cell column and row must be whole numbers inside the grid",
                               "[column, row, value, y] with 0 <= column < columns, 0 <= row < rows");
        g.cells.push_back({static_cast<int>(v[0]), static_cast<int>(v[1]), static_cast<float>(v[2]),
                           static_cast<float>(v[3])});
    }
    return g;
}

Vec3 point(ObjectReader& in, std::string_view key) {
    Vec3 v(0.0f);
    floats(in, key, 3, &v.x);
    return v;
}

RunRecord read_run(const Json& j, const std::string& path, jsonio::ProblemSink& sink) {
    RunRecord run;
    ObjectReader in(j, path, sink, "a run");
    int seed = 1;
    if (in.whole("seed", seed, kCount, Need::Required)) run.seed = static_cast<std::uint64_t>(seed);
    std::string outcome;
    if (in.choice("outcome", outcome, {"win", "death", "timeout"}, Need::Required))
        run.outcome = outcome == "win"     ? RunOutcome::Win
                      : outcome == "death" ? RunOutcome::Death
                                           : RunOutcome::Timeout;
    in.number("time", run.time, kAny, Need::Required);
    in.number("damage_taken", run.damage_taken, kAny, Need::Required);
    in.whole("robots_killed", run.robots_killed, kCount, Need::Required);
    in.whole("shots", run.shots, kCount, Need::Required);
    std::string hash;
    if (in.text("state_hash", hash, Need::Required)) {
        char* end = nullptr;
        run.state_hash = std::strtoull(hash.c_str(), &end, 16);
        if (hash.size() != 16 || *end != '\0')
            error(in, "state_hash", "\"state_hash\" must be 16 hex digits, found " + jsonio::quote_text(hash),
                  kRerun);
    }
    if (const Json* death = in.get("death", Need::Required, kRerun); death && !death->is_null())
        run.death = point(in, "death");
    const Json& damage = array(in, "damage");
    for (std::size_t i = 0; i < damage.size(); ++i) {
        ObjectReader d(damage[i], jsonio::element_path(in.path_of("damage"), i), sink, "a damage sample");
        DamageSample sample;
        d.number("time", sample.time, kAny, Need::Required);
        sample.at = point(d, "at");
        sample.from = point(d, "from");
        d.number("amount", sample.amount, kAny, Need::Required);
        d.finish();
        run.damage.push_back(sample);
    }
    const Json& flat = array(in, "path");
    const std::string path_at = in.path_of("path");
    if (flat.size() % 3 != 0)
        error(in, "path", "the path must hold x, y, z triples", "a multiple of three numbers");
    for (std::size_t i = 0; i + 2 < flat.size(); i += 3) {
        Vec3 p(0.0f);
        for (std::size_t k = 0; k < 3; ++k) {
            double v = 0.0;
            if (jsonio::read_number(flat[i + k], jsonio::element_path(path_at, i + k), sink, v, kAny))
                p[static_cast<int>(k)] = static_cast<float>(v);
        }
        run.path.push_back(p);
    }
    in.finish();
    return run;
}

void read_report(const Json& root, jsonio::ProblemSink& sink, PlaytestReport& r) {
    ObjectReader in(root, "", sink, "play-test report");
    int version = kVersion;
    if (in.whole("version", version, {0, 1 << 20}, Need::Required) && version != kVersion)
        error(in, "version", "report version " + std::to_string(version) + " is not known",
              "this editor reads version " + std::to_string(kVersion) + ": run the analysis again");
    in.claim("format");
    in.text("level", r.level, Need::Required);
    in.text("level_hash", r.level_hash, Need::Required);
    in.whole("requested", r.requested, {0, 1 << 20}, Need::Required);
    int completed = 0;
    const bool has_completed = in.whole("completed", completed, {0, 1 << 20}, Need::Required);
    in.flag("cancelled", r.cancelled, Need::Required);
    in.number("seconds_limit", r.seconds_limit, kAny, Need::Required);
    in.number("path_interval", r.path_interval, kAny, Need::Required);
    in.text("bot_profile", r.bot_profile, Need::Optional, 64);
    if (std::string difficulty; in.choice("difficulty", difficulty, {"easy", "normal", "hard"}))
        r.difficulty = *parse_difficulty(difficulty, {});
    if (const Json* s = in.get("summary", Need::Required, kRerun)) {
        ObjectReader summary(*s, "summary", sink, "the summary");
        summary.whole("wins", r.wins, {0, 1 << 20}, Need::Required);
        summary.whole("deaths", r.deaths, {0, 1 << 20}, Need::Required);
        summary.whole("timeouts", r.timeouts, {0, 1 << 20}, Need::Required);
        summary.number("win_rate", r.win_rate, kAny, Need::Required);
        r.time_to_win = read_spread(summary, "time_to_win");
        r.damage_taken = read_spread(summary, "damage_taken");
        summary.finish();
    }
    if (const Json* h = in.get("heat", Need::Required, kRerun)) {
        ObjectReader heat(*h, "heat", sink, "the heat maps");
        r.damage_heat = read_grid(heat, "damage");
        r.death_heat = read_grid(heat, "deaths");
        heat.finish();
    }
    const Json& runs = array(in, "runs");
    for (std::size_t i = 0; i < runs.size(); ++i)
        r.runs.push_back(read_run(runs[i], jsonio::element_path("runs", i), sink));
    in.finish();
    if (has_completed && completed != static_cast<int>(r.runs.size()))
        error(in, "completed",
              "\"completed\" says " + std::to_string(completed) + " runs but the file lists " +
                  std::to_string(r.runs.size()),
              "the file was cut short or edited: run the analysis again");
}
} // namespace

std::string playtest_report_json(const PlaytestReport& r) {
    Json j;
    j["format"] = kFormat;
    j["version"] = kVersion;
    j["level"] = r.level;
    j["level_hash"] = r.level_hash;
    j["requested"] = r.requested;
    j["completed"] = r.runs.size();
    j["cancelled"] = r.cancelled;
    j["seconds_limit"] = r.seconds_limit;
    j["path_interval"] = r.path_interval;
    j["bot_profile"] = r.bot_profile;
    j["difficulty"] = difficulty_name(r.difficulty);
    j["summary"] = {{"wins", r.wins},
                    {"deaths", r.deaths},
                    {"timeouts", r.timeouts},
                    {"win_rate", r.win_rate},
                    {"time_to_win", spread_json(r.time_to_win)},
                    {"damage_taken", spread_json(r.damage_taken)}};
    const HeatGrid& g = r.damage_heat; // both maps share the grid (summarize_runs makes them so)
    j["heat"] = {{"cell_size", number(g.cell_size)},
                 {"origin", Json::array({number(g.origin_x), number(g.origin_z)})},
                 {"columns", g.columns},
                 {"rows", g.rows},
                 {"damage", cells_json(r.damage_heat.cells)},
                 {"deaths", cells_json(r.death_heat.cells)}};
    Json runs = Json::array();
    for (const RunRecord& run : r.runs) runs.push_back(run_json(run));
    j["runs"] = runs;
    return jsonio::write_document(j);
}

Result<PlaytestReport> parse_playtest_report(std::string_view text, const std::string& file_name) {
    const std::string example = std::string("a report starts with \"format\": \"") + kFormat +
                                "\" (killswitch-editor --analyze writes one)";
    const jsonio::Document document = jsonio::Document::parse(text, file_name, {"play-test report", example});
    jsonio::Problems problems(file_name, &document.positions());
    document.report_to(problems);
    PlaytestReport r;
    if (const Json* root = document.root()) {
        const auto format = root->find("format");
        if (format == root->end() || *format != kFormat)
            problems.report(jsonio::Severity::Error, "", "not a Killswitch play-test report", example);
        else
            read_report(*root, problems, r);
    }
    problems.pass_warnings(nullptr);
    if (problems.has_errors()) return problems.combined();
    return r;
}

Result<void> save_playtest_report(const std::filesystem::path& path, const PlaytestReport& report) {
    return files::write_atomic(path, playtest_report_json(report));
}

Result<PlaytestReport> load_playtest_report(const std::filesystem::path& path) {
    auto text = files::read_text(path);
    if (!text) return text.error();
    return parse_playtest_report(*text, path.string());
}

} // namespace ks::game
