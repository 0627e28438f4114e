// Play-test analysis (game/playtest_analysis.h): the autoplay bot's runs of small levels built in code. A
// level without robots is won every time on a straight path; a gauntlet of tough robots is won in some
// runs and lost in others, and its deaths and hits land in the heat maps where they happened; the report
// is the same with one thread or several; a stop ends it promptly with the runs that finished; one run
// matches the headless runner with the same seed; a level the game refuses gives its error.
#include "game/playtest_analysis.h"
#include "game_test_levels.h"
#include "level/level_io.h"
#include "level/shutdown_objective.h"

#include <doctest/doctest.h>

#include <chrono>
#include <thread>

using namespace ks;
using namespace ks::game;

namespace {
using Clock = std::chrono::steady_clock;

// A 40 x 80 hall: the player starts at z = 30, the control panel stands at z = -30.
level::Level hall() {
    level::Level lv;
    lv.name = "hall";
    auto& floor = lv.add(level::EntityType::Floor, Vec3(0.0f), "ground");
    floor.as<level::FloorProps>().size = Vec2(40.0f, 80.0f);
    lv.player_start.position = Vec3(0.0f, 0.0f, 30.0f);
    lv.add(level::EntityType::ControlPanel, Vec3(0.0f, 0.0f, -30.0f), "panel");
    level::add_shutdown_objective(lv);
    return lv;
}

// The hall with two tough, quick-firing robots at z = -5 on either side of the way: the bot wins some
// runs and dies in others (each robot shot is fired or not by the game's seeded Rng).
level::Level gauntlet() {
    level::Level lv = hall();
    lv.name = "gauntlet";
    for (float x : {-8.0f, 8.0f}) {
        auto& p = lv.add(level::EntityType::Robot, Vec3(x, 0.0f, -5.0f), "guard").as<level::RobotProps>();
        p.damage = 25.0f;
        p.health = 200.0f;
        p.hit_probability = 0.6f;
        p.cooldown = 0.4f;
        p.eye_radius_min = 40.0f;
        p.eye_radius_max = 60.0f;
        p.shooting_distance = 40.0f;
    }
    return lv;
}

PlaytestReport analyze(const level::Level& lv, int runs, int threads, double seconds = 60.0) {
    AnalysisOptions o;
    o.runs = runs;
    o.threads = threads;
    o.seconds = seconds;
    auto report = analyze_level(lv, o);
    if (!report) FAIL(report.error().str());
    return std::move(*report);
}

float horizontal(const Vec3& a, const Vec3& b) {
    return glm::length(Vec2(a.x - b.x, a.z - b.z));
}
} // namespace

TEST_CASE("analysis of a level without robots: every run is won, untouched, on a path from the start to "
          "the panel") {
    const PlaytestReport r = analyze(hall(), 3, 2);
    REQUIRE(r.runs.size() == 3);
    CHECK(r.requested == 3);
    CHECK_FALSE(r.cancelled);
    CHECK(r.wins == 3);
    CHECK(r.deaths == 0);
    CHECK(r.win_rate == 1.0);
    CHECK(r.time_to_win.count == 3);
    // 60 units at the player's 15 units/s, less the E reach: about four seconds.
    CHECK(r.time_to_win.min > 2.5);
    CHECK(r.time_to_win.max < 8.0);
    CHECK(r.damage_taken.max == 0.0);
    CHECK(r.damage_heat.cells.empty());
    CHECK(r.death_heat.cells.empty());
    CHECK(r.level == "hall");
    CHECK(r.level_hash == level_fingerprint(hall()));
    for (std::size_t i = 0; i < r.runs.size(); ++i) {
        const RunRecord& run = r.runs[i];
        CHECK(run.seed == i + 1);
        CHECK(run.outcome == RunOutcome::Win);
        CHECK_FALSE(run.death);
        REQUIRE(run.path.size() >= 3);
        CHECK(run.path.front() == Vec3(0.0f, 0.0f, 30.0f));
        CHECK(horizontal(run.path.back(), Vec3(0.0f, 0.0f, -30.0f)) < 10.0f); // within reach of the panel
        // A sample every quarter second, the start, and the end.
        const double expected = run.time / 0.25 + 1.0;
        CHECK(static_cast<double>(run.path.size()) >= expected - 1.0);
        CHECK(static_cast<double>(run.path.size()) <= expected + 2.0);
        for (std::size_t k = 1; k < run.path.size(); ++k) // never faster than a running player
            CHECK(horizontal(run.path[k], run.path[k - 1]) <= 15.0f * 0.25f + 0.05f);
    }
}

TEST_CASE("analysis of a gauntlet: wins and deaths, and the heat maps hold every hit and death where it "
          "happened") {
    const PlaytestReport r = analyze(gauntlet(), 8, 0);
    REQUIRE(r.runs.size() == 8);
    MESSAGE(r.summary());
    CHECK(r.wins > 0);
    CHECK(r.deaths > 0);
    CHECK(r.wins + r.deaths + r.timeouts == 8);
    CHECK(r.win_rate == doctest::Approx(r.wins / 8.0));
    CHECK(r.time_to_win.count == r.wins);
    double damage_sum = 0.0, hits = 0.0;
    int deaths = 0;
    for (const RunRecord& run : r.runs) {
        CHECK((run.outcome == RunOutcome::Death) == run.death.has_value());
        if (run.death) ++deaths;
        float run_damage = 0.0f;
        for (const DamageSample& d : run.damage) {
            run_damage += d.amount;
            CHECK(d.amount == 25.0f);
            CHECK(d.time <= run.time);
            // Shot from a robot's hand, from the robots' side of the hall.
            CHECK(std::abs(d.from.z + 5.0f) < 4.0f);
        }
        CHECK(run_damage == doctest::Approx(run.damage_taken));
        damage_sum += run_damage;
        hits += static_cast<double>(run.damage.size());
    }
    CHECK(hits > 0);
    CHECK(deaths == r.deaths);
    double heat_sum = 0.0, death_count = 0.0;
    for (const HeatCell& c : r.damage_heat.cells) heat_sum += c.value;
    for (const HeatCell& c : r.death_heat.cells) death_count += c.value;
    CHECK(heat_sum == doctest::Approx(damage_sum));
    CHECK(death_count == deaths);
    // Each death is in the cell under it.
    HeatBinner bins(geometry::Aabb{Vec3(-20, 0, -40), Vec3(20, 0, 40)}, r.death_heat.cell_size);
    for (const RunRecord& run : r.runs) {
        if (!run.death) continue;
        int column = 0, row = 0;
        REQUIRE(bins.cell_of(*run.death, column, row));
        const float x0 = r.death_heat.origin_x + static_cast<float>(column) * r.death_heat.cell_size;
        CHECK(run.death->x >= x0);
        CHECK(run.death->x < x0 + r.death_heat.cell_size);
        bool listed = false;
        for (const HeatCell& c : r.death_heat.cells) listed = listed || (c.column == column && c.row == row);
        CHECK(listed);
    }
}

TEST_CASE("the report does not depend on the number of threads") {
    const level::Level lv = gauntlet();
    const PlaytestReport one = analyze(lv, 6, 1), two = analyze(lv, 6, 2), four = analyze(lv, 6, 4);
    CHECK(one == two);
    CHECK(one == four);
    CHECK(playtest_report_json(one) == playtest_report_json(two));
    CHECK(playtest_report_json(one) == playtest_report_json(four));
}

TEST_CASE("a run of the analysis is the headless runner's run with the same seed") {
    ks::test::ScratchDir dir;
    const level::Level lv = gauntlet();
    REQUIRE(level::save_level_file(dir / "gauntlet.json", lv));
    const PlaytestReport r = analyze(lv, 3, 2);
    for (const RunRecord& run : r.runs) {
        HeadlessOptions o;
        o.level = dir / "gauntlet.json";
        o.seconds = 60.0;
        o.seed = run.seed;
        o.autoplay = true;
        auto stats = run_headless(o);
        REQUIRE(stats);
        CAPTURE(run.seed);
        CHECK(stats->outcome == run_outcome_name(run.outcome));
        CHECK(stats->sim_time_s == run.time);
        CHECK(stats->damage_taken == run.damage_taken);
        CHECK(stats->shots == run.shots);
        CHECK(stats->state_hash == run.state_hash); // the very same simulation
    }
}

TEST_CASE("on the main level (doors, stairs, a platform) a run is the headless runner's run too") {
    // The analysis gives every game a copy of one robot navigation mesh; a copy must walk like a fresh
    // build through every door the level opens.
    auto lv = level::load_level_file(ks::test::source_dir() / "levels/main.json");
    REQUIRE(lv);
    AnalysisOptions o;
    o.runs = 2;
    o.threads = 2;
    auto report = analyze_level(*lv, o);
    REQUIRE(report);
    for (const RunRecord& run : report->runs) {
        HeadlessOptions h;
        h.level = ks::test::source_dir() / "levels/main.json";
        h.seed = run.seed;
        h.autoplay = true;
        auto stats = run_headless(h);
        REQUIRE(stats);
        CAPTURE(run.seed);
        CHECK(stats->outcome == "win");
        CHECK(stats->state_hash == run.state_hash);
        CHECK(stats->sim_time_s == run.time);
    }
}

TEST_CASE("a stopped analysis ends promptly, marked cancelled") {
    level::Level lv = hall();
    std::erase_if(lv.entities,
                  [](const level::Entity& e) { return e.type() == level::EntityType::ControlPanel; });
    lv.objectives.clear(); // nothing to win: every run would play its hour out
    AnalysisOptions o;
    o.runs = 6;
    o.threads = 2;
    o.seconds = 3600.0;
    BackgroundAnalysis job(lv, o);
    const auto started = Clock::now();
    while (job.progress().fraction() <= 0.0f && Clock::now() - started < std::chrono::seconds(30))
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    REQUIRE(job.progress().fraction() > 0.0f); // the runs are under way
    CHECK(job.progress().runs_done() == 0);
    const auto cancelled = Clock::now();
    job.cancel();
    CHECK(job.cancelling());
    while (!job.finished() && Clock::now() - cancelled < std::chrono::seconds(30))
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    const double waited = std::chrono::duration<double>(Clock::now() - cancelled).count();
    MESSAGE("finished " << waited * 1000.0 << " ms after the stop");
    REQUIRE(job.finished());
    CHECK(waited < 1.0); // a step is microseconds: the threads only finish the step they are in
    auto result = job.take_result();
    REQUIRE(result);
    CHECK(result->cancelled);
    CHECK(result->requested == 6);
    CHECK(result->runs.empty());
    CHECK_FALSE(job.take_result()); // taken once
}

TEST_CASE("a report cancelled part way holds the runs that had finished") {
    AnalysisOptions o;
    o.runs = 200;
    o.threads = 1; // one worker takes the seeds in order
    BackgroundAnalysis job(hall(), o);
    const auto started = Clock::now();
    while (job.progress().runs_done() < 2 && Clock::now() - started < std::chrono::seconds(60))
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    job.cancel();
    while (!job.finished()) std::this_thread::sleep_for(std::chrono::milliseconds(2));
    auto result = job.take_result();
    REQUIRE(result);
    CHECK(result->cancelled);
    REQUIRE(result->runs.size() >= 2);
    CHECK(result->runs.size() < 200);
    for (std::size_t i = 0; i < result->runs.size(); ++i) CHECK(result->runs[i].seed == i + 1);
    CHECK(result->wins == static_cast<int>(result->runs.size()));
}

TEST_CASE("analysis errors: bad options name the option, a level the game cannot build gives the game's "
          "error") {
    AnalysisOptions o;
    o.runs = 0;
    auto bad = analyze_level(hall(), o);
    REQUIRE_FALSE(bad);
    CHECK(bad.error().where.path == "runs");
    o.runs = 2;
    o.seconds = -1.0;
    REQUIRE_FALSE(analyze_level(hall(), o));
    o.seconds = 60.0;
    o.cell_size = 0.0f;
    REQUIRE_FALSE(analyze_level(hall(), o));
    o.cell_size = 4.0f;
    o.threads = 100000;
    REQUIRE_FALSE(analyze_level(hall(), o));
    o.threads = 0;
    o.bot_profile = "aimbot";
    auto profile = analyze_level(hall(), o);
    REQUIRE_FALSE(profile);
    CHECK(profile.error().where.path == "bot_profile");
    o.bot_profile = "perfect";

    // A robot standing on nothing in a level without a floor: the bot has no mesh to plan on.
    level::Level empty;
    empty.name = "void";
    empty.player_start.position = Vec3(0.0f, 0.0f, 0.0f);
    o.threads = 2;
    auto refused = analyze_level(empty, o);
    REQUIRE_FALSE(refused);
    MESSAGE(refused.error().str());
    CHECK_FALSE(refused.error().message.empty());
}

TEST_CASE("analysis threads: 0 means every hardware thread, never more than there are runs") {
    const int hardware = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    CHECK(analysis_threads(0, 1000) == std::min(hardware, 1000));
    CHECK(analysis_threads(0, 1) == 1);
    CHECK(analysis_threads(8, 3) == 3);
    CHECK(analysis_threads(2, 20) == 2);
}
