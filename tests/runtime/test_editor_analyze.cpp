// `killswitch-editor --analyze LEVEL --runs N --report FILE`, the real binary, without a window: it writes
// the report (beside the level by default, never over it), prints a summary, gives the same file for any
// number of threads, and refuses bad levels and options with a message and a non-zero exit.
#include "game/playtest_report.h"
#include "level/level_io.h"
#include "level/shutdown_objective.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <fstream>
#include <sstream>

using namespace ks;

namespace {
// A 40 x 80 hall with the control panel 60 units ahead of the player start, and one robot to the side.
std::filesystem::path write_hall(const test::ScratchDir& dir) {
    level::Level lv;
    lv.name = "analyze hall";
    lv.add(level::EntityType::Floor, Vec3(0.0f), "ground").as<level::FloorProps>().size = Vec2(40.0f, 80.0f);
    lv.player_start.position = Vec3(0.0f, 0.0f, 30.0f);
    lv.add(level::EntityType::Robot, Vec3(12.0f, 0.0f, 0.0f), "guard");
    lv.add(level::EntityType::ControlPanel, Vec3(0.0f, 0.0f, -30.0f), "panel");
    level::add_shutdown_objective(lv);
    const auto file = dir / "hall.json";
    REQUIRE(level::save_level_file(file, lv));
    return file;
}

std::string read(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}
} // namespace

TEST_CASE("killswitch-editor --analyze writes the report, prints a summary, the same for any thread count") {
    test::ScratchDir dir;
    const auto level_file = write_hall(dir);
    const std::string level_text = read(level_file);
    const auto one = dir / "one.json", two = dir / "two.json";
    auto a = test::run_command(test::editor_binary() + " --analyze " + level_file.string() +
                               " --runs 3 --threads 1 --seconds 60 --report " + one.string());
    auto b = test::run_command(test::editor_binary() + " --analyze " + level_file.string() +
                               " --runs 3 --threads 2 --seconds 60 --report " + two.string());
    INFO(a.output);
    INFO(b.output);
    REQUIRE(a.exit_code == 0);
    REQUIRE(b.exit_code == 0);
    CHECK(a.output.find("hall.json: 3 of 3 runs") != std::string::npos);
    CHECK(a.output.find("won 3 (100 %)") != std::string::npos);
    CHECK(a.output.find("report written to " + one.string()) != std::string::npos);
    CHECK(read(one) == read(two)); // deterministic: one thread or two
    auto report = game::load_playtest_report(one);
    REQUIRE_MESSAGE(report, (report ? "" : report.error().str()));
    CHECK(report->requested == 3);
    CHECK(report->runs.size() == 3);
    CHECK(report->wins == 3);
    CHECK(report->level == "hall.json");
    auto level = level::load_level_file(level_file);
    REQUIRE(level);
    CHECK(report->level_hash == game::level_fingerprint(*level));
    CHECK(read(level_file) == level_text); // the level itself is untouched

    // Without --report the report goes beside the level.
    auto beside =
        test::run_command(test::editor_binary() + " --analyze " + level_file.string() + " --runs 2");
    INFO(beside.output);
    REQUIRE(beside.exit_code == 0);
    CHECK(std::filesystem::exists(dir / "hall.playtest.json"));
    CHECK(read(level_file) == level_text);
}

TEST_CASE("killswitch-editor --analyze with several profiles and difficulties prints a row for each") {
    test::ScratchDir dir;
    const auto level_file = write_hall(dir);
    auto table =
        test::run_command(test::editor_binary() + " --analyze " + level_file.string() +
                          " --runs 2 --seconds 60 --bot-profile perfect,new-player --difficulty easy,hard");
    INFO(table.output);
    REQUIRE(table.exit_code == 0);
    for (const char* row : {"| hall.json | perfect | easy | 2/2 |", "| hall.json | perfect | hard | 2/2 |",
                            "| hall.json | new-player | easy |", "| hall.json | new-player | hard |"})
        CHECK(table.output.find(row) != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir / "hall.playtest.json")); // a table, no report file
}

TEST_CASE("killswitch-editor --analyze refuses a bad level or option with a message and a non-zero exit") {
    test::ScratchDir dir;
    const auto level_file = write_hall(dir);
    const std::string level_text = read(level_file);
    struct Case {
        std::string args;
        int exit_code;
        std::string message;
    };
    const Case cases[] = {
        {"--analyze " + (dir / "missing.json").string(), 1, "missing.json"},
        {"--analyze " + level_file.string() + " --runs 0", 2, "--runs"},
        {"--analyze " + level_file.string() + " --runs many", 2, "--runs"},
        {"--analyze " + level_file.string() + " --seconds -5", 2, "time limit"},
        {"--analyze " + level_file.string() + " --threads 999", 2, "--threads"},
        {"--analyze " + level_file.string() + " --report " + level_file.string(), 2, "never into it"},
        {"--analyze " + level_file.string() + " --runz 3", 2, "unknown option --runz"},
        {"--analyze " + level_file.string() + " --bot-profile aimbot", 2, "unknown bot profile 'aimbot'"},
        {"--analyze " + level_file.string() + " --difficulty brutal", 2, "use easy, normal or hard"},
        {"--threads 2", 2, "goes with --analyze"},
    };
    for (const Case& c : cases) {
        auto run = test::run_command(test::editor_binary() + " " + c.args);
        CAPTURE(c.args);
        INFO(run.output);
        CHECK(run.exit_code == c.exit_code);
        CHECK(run.output.find(c.message) != std::string::npos);
    }
    // A file that is not a level names the place of the problem.
    {
        std::ofstream(dir / "broken.json")
            << "{\"format\": \"killswitch-level\", \"version\": 2, \"entities\": [";
        auto run = test::run_command(test::editor_binary() + " --analyze " + (dir / "broken.json").string());
        INFO(run.output);
        CHECK(run.exit_code == 1);
        CHECK(run.output.find("broken.json:1:") != std::string::npos);
    }
    CHECK(read(level_file) == level_text);
    CHECK_FALSE(std::filesystem::exists(dir / "hall.playtest.json")); // nothing written on a refusal
}
