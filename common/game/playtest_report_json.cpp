// The play-test report's JSON file (docs/editor.md, "Play-test reports"): written with the project's
// deterministic writer (shortest round-trip numbers, a float as its own shortest form), read back with
// every problem located by line:column and JSON path.
#include "core/files.h"
#include "game/playtest_report.h"
#include "jsonio/json_path.h"
#include "jsonio/json_writer.h"
#include "jsonio/number_text.h"
#include "jsonio/position_map.h"

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

// Reads a parsed report, keeping the first problem (later reads return defaults); located on demand.
class Reader {
  public:
    Reader(std::string_view text, std::string file) : text_(text), file_(std::move(file)) {}

    void fail(const std::string& path, const std::string& message, const std::string& hint) {
        if (error_) return;
        if (!positions_) positions_ = jsonio::PositionMap::scan(text_);
        error_ = Error(message, jsonio::location_at(file_, positions_->find(path), path), hint);
    }
    const std::optional<Error>& error() const { return error_; }

    const Json* member(const Json& object, const std::string& parent, const char* key) {
        const std::string path = jsonio::member_path(parent, key);
        if (!object.is_object() || !object.contains(key)) {
            fail(path, std::string("missing \"") + key + "\"",
                 "write the report again (killswitch-editor --analyze) or see docs/editor.md");
            return nullptr;
        }
        return &object[key];
    }
    double real(const Json& object, const std::string& parent, const char* key) {
        const Json* v = member(object, parent, key);
        if (!v) return 0.0;
        if (!v->is_number() || !std::isfinite(v->get<double>())) {
            fail(jsonio::member_path(parent, key), std::string("\"") + key + "\" must be a finite number",
                 "e.g. 12.5");
            return 0.0;
        }
        return v->get<double>();
    }
    int whole(const Json& object, const std::string& parent, const char* key, int min, int max) {
        const double v = real(object, parent, key);
        if (!error_ && (v != std::floor(v) || v < min || v > max))
            fail(jsonio::member_path(parent, key),
                 std::string("\"") + key + "\" must be a whole number in " + std::to_string(min) + ".." +
                     std::to_string(max),
                 "");
        return error_ ? 0 : static_cast<int>(v);
    }
    std::string text(const Json& object, const std::string& parent, const char* key) {
        const Json* v = member(object, parent, key);
        if (v && !v->is_string())
            fail(jsonio::member_path(parent, key), std::string("\"") + key + "\" must be a string", "");
        return v && v->is_string() ? v->get<std::string>() : std::string();
    }
    const Json& array(const Json& object, const std::string& parent, const char* key) {
        static const Json empty = Json::array();
        const Json* v = member(object, parent, key);
        if (v && !v->is_array())
            fail(jsonio::member_path(parent, key), std::string("\"") + key + "\" must be an array", "");
        return v && v->is_array() ? *v : empty;
    }
    // An array of `n` finite numbers.
    bool numbers(const Json& value, const std::string& path, std::size_t n, float* out) {
        if (!value.is_array() || value.size() != n) {
            fail(path, "expected an array of " + std::to_string(n) + " numbers", "");
            return false;
        }
        for (std::size_t i = 0; i < n; ++i) {
            if (!value[i].is_number() || !std::isfinite(value[i].get<double>())) {
                fail(jsonio::element_path(path, i), "expected a finite number", "");
                return false;
            }
            out[i] = value[i].get<float>();
        }
        return true;
    }
    Vec3 vec3(const Json& object, const std::string& parent, const char* key) {
        Vec3 v(0.0f);
        if (const Json* m = member(object, parent, key))
            numbers(*m, jsonio::member_path(parent, key), 3, &v.x);
        return v;
    }

  private:
    std::string_view text_;
    std::string file_;
    std::optional<jsonio::PositionMap> positions_;
    std::optional<Error> error_;
};

Spread read_spread(Reader& in, const Json& parent, const std::string& path, const char* key) {
    Spread s;
    const Json* j = in.member(parent, path, key);
    if (!j) return s;
    const std::string at = jsonio::member_path(path, key);
    s.count = in.whole(*j, at, "count", 0, 1 << 30);
    s.mean = in.real(*j, at, "mean");
    s.median = in.real(*j, at, "median");
    s.min = in.real(*j, at, "min");
    s.max = in.real(*j, at, "max");
    return s;
}

HeatGrid read_grid(Reader& in, const Json& heat, const std::string& path, const char* key) {
    HeatGrid g;
    g.cell_size = static_cast<float>(in.real(heat, path, "cell_size"));
    float origin[2] = {0.0f, 0.0f};
    if (const Json* o = in.member(heat, path, "origin"))
        in.numbers(*o, jsonio::member_path(path, "origin"), 2, origin);
    g.origin_x = origin[0];
    g.origin_z = origin[1];
    g.columns = in.whole(heat, path, "columns", 0, 1 << 20);
    g.rows = in.whole(heat, path, "rows", 0, 1 << 20);
    const Json& cells = in.array(heat, path, key);
    const std::string cells_path = jsonio::member_path(path, key);
    for (std::size_t i = 0; i < cells.size() && !in.error(); ++i) {
        float v[4];
        const std::string at = jsonio::element_path(cells_path, i);
        if (!in.numbers(cells[i], at, 4, v)) break;
        if (v[0] != std::floor(v[0]) || v[1] != std::floor(v[1]) || v[0] < 0 || v[1] < 0 ||
            v[0] >= static_cast<float>(g.columns) || v[1] >= static_cast<float>(g.rows))
            in.fail(at, "cell column and row must be whole numbers inside the grid",
                    "[column, row, value, y] with 0 <= column < columns, 0 <= row < rows");
        g.cells.push_back({static_cast<int>(v[0]), static_cast<int>(v[1]), v[2], v[3]});
    }
    return g;
}

RunRecord read_run(Reader& in, const Json& j, const std::string& path) {
    RunRecord run;
    run.seed = static_cast<std::uint64_t>(in.whole(j, path, "seed", 0, 1 << 30));
    const std::string outcome = in.text(j, path, "outcome");
    if (outcome == "win")
        run.outcome = RunOutcome::Win;
    else if (outcome == "death")
        run.outcome = RunOutcome::Death;
    else if (outcome == "timeout")
        run.outcome = RunOutcome::Timeout;
    else
        in.fail(jsonio::member_path(path, "outcome"), "unknown outcome \"" + outcome + "\"",
                "one of win, death, timeout");
    run.time = in.real(j, path, "time");
    run.damage_taken = static_cast<float>(in.real(j, path, "damage_taken"));
    run.robots_killed = in.whole(j, path, "robots_killed", 0, 1 << 30);
    run.shots = in.whole(j, path, "shots", 0, 1 << 30);
    const std::string hash = in.text(j, path, "state_hash");
    char* end = nullptr;
    run.state_hash = std::strtoull(hash.c_str(), &end, 16);
    if (!in.error() && (hash.size() != 16 || *end != '\0'))
        in.fail(jsonio::member_path(path, "state_hash"), "\"state_hash\" must be 16 hex digits", "");
    if (const Json* death = in.member(j, path, "death"); death && !death->is_null())
        run.death = in.vec3(j, path, "death");
    const Json& damage = in.array(j, path, "damage");
    for (std::size_t i = 0; i < damage.size() && !in.error(); ++i) {
        const std::string at = jsonio::element_path(jsonio::member_path(path, "damage"), i);
        DamageSample d;
        d.time = in.real(damage[i], at, "time");
        d.at = in.vec3(damage[i], at, "at");
        d.from = in.vec3(damage[i], at, "from");
        d.amount = static_cast<float>(in.real(damage[i], at, "amount"));
        run.damage.push_back(d);
    }
    const Json& flat = in.array(j, path, "path");
    if (flat.size() % 3 != 0)
        in.fail(jsonio::member_path(path, "path"), "the path must hold x, y, z triples",
                "a multiple of three numbers");
    const std::string path_at = jsonio::member_path(path, "path");
    for (std::size_t i = 0; i + 2 < flat.size() && !in.error(); i += 3) {
        Vec3 p;
        for (std::size_t k = 0; k < 3; ++k) {
            if (!flat[i + k].is_number() || !std::isfinite(flat[i + k].get<double>()))
                in.fail(jsonio::element_path(path_at, i + k), "expected a finite number", "");
            else
                p[static_cast<int>(k)] = flat[i + k].get<float>();
        }
        run.path.push_back(p);
    }
    return run;
}

Result<Json> parse_json(std::string_view text, const std::string& file_name) {
    try {
        return Json::parse(text);
    } catch (const nlohmann::json::exception& e) {
        std::string what = e.what();
        if (auto p = what.find("parse error"); p != std::string::npos) what = what.substr(p);
        std::size_t offset = 0;
        if (const auto* pe = dynamic_cast<const nlohmann::json::parse_error*>(&e))
            offset = pe->byte > 0 ? pe->byte - 1 : 0;
        return Error(what, jsonio::location_at(file_name, jsonio::position_of_offset(text, offset)),
                     "the report is not valid JSON: run the analysis again");
    }
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
    auto parsed = parse_json(text, file_name);
    if (!parsed) return parsed.error();
    const Json& j = *parsed;
    Reader in(text, file_name);
    if (!j.is_object() || !j.contains("format") || j["format"] != kFormat)
        return Error("not a Killswitch play-test report", Location(file_name, 1, 1),
                     std::string("a report starts with \"format\": \"") + kFormat +
                         "\" (killswitch-editor --analyze writes one)");
    if (const int version = in.whole(j, "", "version", 0, 1 << 20); !in.error() && version != kVersion)
        in.fail("version", "report version " + std::to_string(version) + " is not known",
                "this editor reads version " + std::to_string(kVersion) + ": run the analysis again");
    PlaytestReport r;
    r.level = in.text(j, "", "level");
    r.level_hash = in.text(j, "", "level_hash");
    r.requested = in.whole(j, "", "requested", 0, 1 << 20);
    const int completed = in.whole(j, "", "completed", 0, 1 << 20);
    if (const Json* c = in.member(j, "", "cancelled"); c && !c->is_boolean())
        in.fail("cancelled", "\"cancelled\" must be true or false", "");
    else if (c)
        r.cancelled = c->get<bool>();
    r.seconds_limit = in.real(j, "", "seconds_limit");
    r.path_interval = in.real(j, "", "path_interval");
    if (const Json* s = in.member(j, "", "summary")) {
        r.wins = in.whole(*s, "summary", "wins", 0, 1 << 20);
        r.deaths = in.whole(*s, "summary", "deaths", 0, 1 << 20);
        r.timeouts = in.whole(*s, "summary", "timeouts", 0, 1 << 20);
        r.win_rate = in.real(*s, "summary", "win_rate");
        r.time_to_win = read_spread(in, *s, "summary", "time_to_win");
        r.damage_taken = read_spread(in, *s, "summary", "damage_taken");
    }
    if (const Json* heat = in.member(j, "", "heat")) {
        r.damage_heat = read_grid(in, *heat, "heat", "damage");
        r.death_heat = read_grid(in, *heat, "heat", "deaths");
    }
    const Json& runs = in.array(j, "", "runs");
    for (std::size_t i = 0; i < runs.size() && !in.error(); ++i)
        r.runs.push_back(read_run(in, runs[i], jsonio::element_path("runs", i)));
    if (!in.error() && completed != static_cast<int>(r.runs.size()))
        in.fail("completed",
                "\"completed\" says " + std::to_string(completed) + " runs but the file lists " +
                    std::to_string(r.runs.size()),
                "the file was cut short or edited: run the analysis again");
    if (in.error()) return *in.error();
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
