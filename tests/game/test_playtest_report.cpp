// The play-test report (game/playtest_report.h) without running the game: heat-map binning (cells, edges,
// points outside, the mean height), the aggregate numbers, the JSON file's round trip and its errors
// (located by line and JSON path), the file beside the level, and the level fingerprint.
#include "core/log.h"
#include "game/playtest_report.h"
#include "jsonio/bad_documents.h"
#include "level/level_io.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <fstream>

using namespace ks;
using namespace ks::game;

namespace {
RunRecord run(std::uint64_t seed, RunOutcome outcome, double time) {
    RunRecord r;
    r.seed = seed;
    r.outcome = outcome;
    r.time = time;
    r.path = {Vec3(0.0f, 0.0f, 10.0f), Vec3(1.25f, 0.5f, 7.5f), Vec3(2.5f, 0.0f, 5.0f)};
    return r;
}

// Three runs: a win, a death after two hits in the same cell, a timeout hit once on a platform.
std::vector<RunRecord> three_runs() {
    RunRecord won = run(1, RunOutcome::Win, 20.5);
    RunRecord died = run(2, RunOutcome::Death, 12.25);
    died.damage = {{3.0, Vec3(1.0f, 0.0f, 1.0f), Vec3(5.0f, 2.0f, 1.0f), 40.0f},
                   {4.5, Vec3(2.0f, 0.0f, 3.0f), Vec3(5.0f, 2.0f, 1.0f), 60.0f}};
    died.damage_taken = 100.0f;
    died.death = Vec3(2.0f, 0.0f, 3.0f);
    RunRecord late = run(3, RunOutcome::Timeout, 300.0);
    late.damage = {{100.0, Vec3(-9.0f, 4.0f, -9.0f), Vec3(-9.0f, 7.0f, -9.0f), 10.0f}};
    late.damage_taken = 10.0f;
    return {late, died, won}; // out of order: the report sorts by seed
}

ReportSetup setup() {
    ReportSetup s;
    s.level = "arena.json";
    s.level_hash = "0123456789abcdef";
    s.requested = 3;
    s.cell_size = 4.0f;
    s.level_area = geometry::Aabb{Vec3(-10.0f, 0.0f, -10.0f), Vec3(10.0f, 4.0f, 10.0f)};
    return s;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    REQUIRE(at != std::string::npos);
    return text.replace(at, from.size(), to);
}
} // namespace

TEST_CASE("heat-map binning: cells from a snapped corner, edges belong to the higher cell, outside and "
          "non-finite points are refused, heights are averaged") {
    HeatBinner bins(geometry::Aabb{Vec3(-10.0f, 0.0f, -10.0f), Vec3(10.0f, 0.0f, 10.0f)}, 4.0f);
    const HeatGrid empty = bins.grid();
    CHECK(empty.origin_x == -12.0f); // -10 snapped down to a multiple of 4
    CHECK(empty.origin_z == -12.0f);
    CHECK(empty.columns == 6); // -12 .. 12
    CHECK(empty.rows == 6);
    CHECK(empty.cells.empty());
    int column = -1, row = -1;
    REQUIRE(bins.cell_of(Vec3(0.5f, 0.0f, -0.1f), column, row));
    CHECK(column == 3);
    CHECK(row == 2);
    REQUIRE(bins.cell_of(Vec3(-8.0f, 0.0f, -12.0f), column, row)); // on the lines: the higher cell
    CHECK(column == 1);
    CHECK(row == 0);
    CHECK_FALSE(bins.cell_of(Vec3(12.0f, 0.0f, 0.0f), column, row));
    CHECK_FALSE(bins.cell_of(Vec3(-12.01f, 0.0f, 0.0f), column, row));
    CHECK_FALSE(bins.add(Vec3(std::nanf(""), 0.0f, 0.0f), 1.0f));
    CHECK_FALSE(bins.add(Vec3(0.0f), std::numeric_limits<float>::infinity()));
    CHECK(bins.add(Vec3(0.5f, 2.0f, -0.1f), 10.0f));
    CHECK(bins.add(Vec3(3.9f, 4.0f, -3.9f), 5.0f)); // the same cell
    CHECK(bins.add(Vec3(-11.0f, 0.0f, 11.0f), 1.0f));
    const HeatGrid g = bins.grid();
    REQUIRE(g.cells.size() == 2);
    CHECK(g.cells[0] == HeatCell{3, 2, 15.0f, 3.0f}); // row by row
    CHECK(g.cells[1] == HeatCell{0, 5, 1.0f, 0.0f});
    CHECK(g.max_value() == 15.0f);

    // The same point lands in the same cell whatever the area.
    HeatBinner wider(geometry::Aabb{Vec3(-30.0f), Vec3(50.0f)}, 4.0f);
    REQUIRE(wider.cell_of(Vec3(0.5f, 0.0f, -0.1f), column, row));
    const HeatGrid w = wider.grid();
    CHECK(w.origin_x + static_cast<float>(column) * w.cell_size == 0.0f);
    CHECK(w.origin_z + static_cast<float>(row) * w.cell_size == -4.0f);
}

TEST_CASE("a huge area gets bigger cells instead of an unbounded grid") {
    HeatBinner bins(geometry::Aabb{Vec3(-1e6f), Vec3(1e6f)}, 1.0f);
    const HeatGrid g = bins.grid();
    CHECK(g.columns <= 1024);
    CHECK(g.rows <= 1024);
    CHECK(g.cell_size >= 1e6f * 2.0f / 1024.0f);
}

TEST_CASE("summarize_runs: outcomes, win rate, time to win and damage spreads, heat maps of hits and "
          "deaths") {
    const PlaytestReport r = summarize_runs(three_runs(), setup());
    REQUIRE(r.runs.size() == 3);
    CHECK(r.runs[0].seed == 1);
    CHECK(r.runs[2].seed == 3);
    CHECK(r.wins == 1);
    CHECK(r.deaths == 1);
    CHECK(r.timeouts == 1);
    CHECK(r.win_rate == doctest::Approx(1.0 / 3.0));
    CHECK(r.time_to_win == Spread{1, 20.5, 20.5, 20.5, 20.5});
    CHECK(r.damage_taken == Spread{3, 110.0 / 3.0, 10.0, 0.0, 100.0});
    CHECK(spread_of({4.0, 1.0, 3.0, 2.0}) == Spread{4, 2.5, 2.5, 1.0, 4.0});
    // Hits at (1, 1) and (2, 3) share the cell [0, 4) x [0, 4); the platform hit has its own.
    REQUIRE(r.damage_heat.cells.size() == 2);
    CHECK(r.damage_heat.cells[0].value == 10.0f);
    CHECK(r.damage_heat.cells[0].y == 4.0f);
    CHECK(r.damage_heat.cells[1].value == 100.0f);
    CHECK(r.damage_heat.max_value() == 100.0f);
    REQUIRE(r.death_heat.cells.size() == 1);
    CHECK(r.death_heat.cells[0].value == 1.0f);
    CHECK(r.death_heat.cells[0].column == r.damage_heat.cells[1].column);
    CHECK(r.death_heat.cells[0].row == r.damage_heat.cells[1].row);
    // Both maps share one grid.
    CHECK(r.death_heat.origin_x == r.damage_heat.origin_x);
    CHECK(r.death_heat.columns == r.damage_heat.columns);
    CHECK(r.summary().find("won 1 (33 %)") != std::string::npos);
    // Where players died: the death cell's centre and count, in the summary's last line.
    const auto places = deadliest_places(r, 3);
    REQUIRE(places.size() == 1);
    CHECK(places[0].deaths == 1);
    CHECK(places[0].at.x == doctest::Approx(2.0f)); // the cell [0, 4) x [0, 4)
    CHECK(places[0].at.z == doctest::Approx(2.0f));
    CHECK(r.summary().find("died most at (x, y, z) (2, 0, 2) x1") != std::string::npos);
    CHECK(r.summary().find("bot perfect, normal") != std::string::npos);
}

TEST_CASE("the report's JSON file reads back equal, byte for byte, beside the level") {
    const PlaytestReport r = summarize_runs(three_runs(), setup());
    const std::string text = playtest_report_json(r);
    auto back = parse_playtest_report(text, "arena.playtest.json");
    REQUIRE_MESSAGE(back, (back ? "" : back.error().str()));
    CHECK(*back == r);
    CHECK(playtest_report_json(*back) == text);
    // Who played, and against which robots: saved, read back; a file from before them reads as the perfect
    // bot on Normal.
    ReportSetup hard_setup = setup();
    hard_setup.bot_profile = "new-player";
    hard_setup.difficulty = Difficulty::Hard;
    const PlaytestReport hard = summarize_runs(three_runs(), hard_setup);
    const std::string hard_text = playtest_report_json(hard);
    CHECK(hard_text.find("\"bot_profile\": \"new-player\"") != std::string::npos);
    auto hard_back = parse_playtest_report(hard_text, "arena.playtest.json");
    REQUIRE(hard_back);
    CHECK(*hard_back == hard);
    auto old = parse_playtest_report(replaced(replaced(hard_text, "\"bot_profile\": \"new-player\",", ""),
                                              "\"difficulty\": \"hard\",", ""),
                                     "old.playtest.json");
    REQUIRE_MESSAGE(old, (old ? "" : old.error().str()));
    CHECK(old->bot_profile == "perfect");
    // One death in three runs: no warning; two of three for the new player: a warning naming where.
    CHECK(new_player_warning(hard).empty());
    std::vector<RunRecord> deadly = three_runs();
    deadly[0].outcome = RunOutcome::Death;
    deadly[0].death = Vec3(1.0f, 0.0f, 1.0f);
    const PlaytestReport lost = summarize_runs(deadly, hard_setup);
    CHECK(new_player_warning(lost).find("died in 2 of 3 runs, most at (2, 0, 2)") != std::string::npos);
    CHECK(lost.summary().find("new-player bot died in 2 of 3") != std::string::npos);
    CHECK(new_player_warning(summarize_runs(deadly, setup())).empty()); // the perfect bot: no warning
    CHECK(old->difficulty == Difficulty::Normal);
    CHECK_FALSE(parse_playtest_report(replaced(hard_text, "\"hard\"", "\"brutal\""), "bad.playtest.json"));
    CHECK(text.find("\"format\": \"killswitch-playtest-report\"") != std::string::npos);
    CHECK(text.find("\"path\": [0, 0, 10, 1.25, 0.5, 7.5, 2.5, 0, 5]") != std::string::npos);

    CHECK(playtest_report_path("levels/main.json") == std::filesystem::path("levels/main.playtest.json"));
    CHECK(playtest_report_path("/a/b/arena") == std::filesystem::path("/a/b/arena.playtest.json"));
    ks::test::ScratchDir dir;
    const auto file = playtest_report_path(dir / "arena.json");
    REQUIRE(save_playtest_report(file, r));
    auto loaded = load_playtest_report(file);
    REQUIRE(loaded);
    CHECK(*loaded == r);
}

TEST_CASE("a broken report file is refused with its place and a fix") {
    const std::string text = playtest_report_json(summarize_runs(three_runs(), setup()));
    auto check_error = [](const std::string& bad, const std::string& message_part, const std::string& path) {
        auto r = parse_playtest_report(bad, "bad.playtest.json");
        REQUIRE_FALSE(r);
        INFO(r.error().str());
        CHECK(r.error().message.find(message_part) != std::string::npos);
        CHECK(r.error().where.file == "bad.playtest.json");
        CHECK(r.error().where.path == path);
        if (!path.empty()) CHECK(r.error().where.line > 1);
    };
    check_error("{\"format\": ", "file ends early", "");
    check_error("{\"format\": \"killswitch-level\"}", "not a Killswitch play-test report", "");
    check_error(replaced(text, "\"version\": 1", "\"version\": 7"), "version 7", "version");
    check_error(replaced(text, "\"outcome\": \"death\"", "\"outcome\": \"won\""), "unknown value \"won\"",
                "runs[1].outcome");
    check_error(replaced(text, "\"wins\": 1,", ""), "missing required field \"wins\"", "summary.wins");
    check_error(replaced(text, "\"completed\": 3", "\"completed\": 4"), "says 4 runs", "completed");
    check_error(replaced(text, "\"path\": [0, 0, 10,", "\"path\": [0, 0,"), "x, y, z triples",
                "runs[0].path");
    check_error(replaced(text, "\"time\": 20.5", "\"time\": \"late\""),
                "expected a number, found the string \"late\"", "runs[0].time");
    auto missing = load_playtest_report("/nonexistent/none.playtest.json");
    REQUIRE_FALSE(missing);
    CHECK(missing.error().str().find("none.playtest.json") != std::string::npos);
}

TEST_CASE("a report read like every file: bad documents at their line:column, unknown fields warned") {
    for (const ks::test::BadDocument& bad : ks::test::bad_documents()) {
        CAPTURE(bad.name);
        auto r = parse_playtest_report(bad.text, "bad.playtest.json");
        REQUIRE_FALSE(r);
        CHECK(r.error().str().find("bad.playtest.json" + bad.place + bad.message) != std::string::npos);
    }
    const std::string text = playtest_report_json(summarize_runs(three_runs(), setup()));
    ks::log::Capture capture;
    auto extra = parse_playtest_report(replaced(text, "\"wins\": 1,", "\"wins\": 1, \"winz\": 2,"), "r.json");
    REQUIRE(extra);
    CHECK(capture.text().find("summary.winz: unknown field \"winz\" is ignored (did you mean \"wins\"?") !=
          std::string::npos);
}

TEST_CASE("the level fingerprint follows the level's content") {
    level::Level a;
    a.name = "a";
    a.add(level::EntityType::Floor, Vec3(0.0f), "ground");
    level::Level b = a;
    CHECK(level_fingerprint(a) == level_fingerprint(b));
    CHECK(level_fingerprint(a).size() == 16);
    b.entities[0].position.x = 1.0f;
    CHECK(level_fingerprint(a) != level_fingerprint(b));
    // A level read back from its file has the fingerprint of the one written.
    auto reread = level::load_level_string(level::save_level_string(b), "b.json");
    REQUIRE(reread);
    CHECK(level_fingerprint(*reread) == level_fingerprint(b));
}
