// Robot patrols and the robot fields added after version 1: what the file holds, what a robot without them
// saves (exactly what it saved before), and the errors for a route nobody meant.
#include "level/level_io.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <limits>

using namespace ks::level;

namespace {

std::string level_text(const std::string& robot_props) {
    return R"({"format": "killswitch-level", "version": 2, "entities": [
  {"id": 1, "type": "floor", "position": [0, 0, 0], "props": {"size": [40, 40]}},
  {"id": 12, "type": "robot", "name": "guard", "position": [0, 0, 0], "props": )" +
           robot_props + "}\n]}\n";
}

Level guarded_level() {
    Level level;
    level.add(EntityType::Floor, {0, 0, 0}, "ground").as<FloorProps>().size = {40, 40};
    level.add(EntityType::Robot, {0, 0, 0}, "guard");
    return level;
}

RobotProps& guard(Level& level) {
    return level.entities[1].as<RobotProps>();
}

} // namespace

TEST_CASE("a patrol saves as points, mode and wait and loads back exactly") {
    Level level = guarded_level();
    Patrol& patrol = guard(level).patrol;
    patrol.points = {{0, 0, 0}, {10, 0, 0.5f}, {10, 0, -7.25f}};
    patrol.mode.value = "ping_pong";
    patrol.wait = 1.5f;
    const std::string text = save_level_string(level);
    CHECK(text.find(R"("patrol": {
          "points": [
            [0, 0, 0],
            [10, 0, 0.5],
            [10, 0, -7.25]
          ],
          "mode": "ping_pong",
          "wait": 1.5
        })") != std::string::npos);
    LoadReport report;
    auto back = load_level_string(text, "patrol.json", &report);
    REQUIRE_MESSAGE(back.ok(), report.str());
    CHECK(report.diagnostics.empty());
    CHECK(*back == level);
    CHECK(save_level_string(*back) == text);
}

TEST_CASE("a robot without a patrol, at the default search time and hearing radius, saves as before") {
    Level level = guarded_level();
    const std::string text = save_level_string(level);
    CHECK(text.find("patrol") == std::string::npos);
    CHECK(text.find("search_time") == std::string::npos);
    CHECK(text.find("hearing_radius") == std::string::npos);
    CHECK(text.find("\"dummy\": false\n") != std::string::npos); // the last field written, as before

    guard(level).search_time = 3;
    guard(level).hearing_radius = 12.5f;
    const std::string changed = save_level_string(level);
    CHECK(changed.find("\"search_time\": 3,") != std::string::npos);
    CHECK(changed.find("\"hearing_radius\": 12.5\n") != std::string::npos);
    auto back = load_level_string(changed, "changed.json");
    REQUIRE(back.ok());
    CHECK(*back == level);
}

TEST_CASE("a patrol of a million points is refused without reading them, naming the robot") {
    std::string points = "[0, 0, 0]";
    points.reserve(11 * 1000000);
    for (int i = 1; i < 1000000; ++i) points += ",[0,0,0]";
    LoadReport report;
    auto level =
        load_level_string(level_text(R"({"patrol": {"points": [)" + points + "]}}"), "huge.json", &report);
    CHECK_FALSE(level.ok());
    CHECK(report.error_count() == 1);
    CHECK_MESSAGE(report.str().find("huge.json:3:92: entities[1].props.patrol.points: robot 12 (\"guard\"): "
                                    "patrol has 1000000 points; at most 256") != std::string::npos,
                  report.str());
}

TEST_CASE("a patrol point far outside the level is an error naming the robot, the point and the level") {
    LoadReport report;
    auto level = load_level_string(
        level_text(R"({"patrol": {"points": [[0, 0, 0], [15, 0, 15], [900, 0, 5]]}})"), "far.json", &report);
    CHECK_FALSE(level.ok());
    CHECK(report.error_count() == 1);
    CHECK_MESSAGE(
        report.str().find("far.json:3:127: entities[1].props.patrol.points[2]: robot 12 (\"guard\"): "
                          "patrol point (900, 0, 5) is 880 units outside the level") != std::string::npos,
        report.str());
    // Just inside the reach (50 units beyond the floor's edge at x 20) loads.
    auto near = load_level_string(level_text(R"({"patrol": {"points": [[69, 0, 0]]}})"), "near.json");
    CHECK(near.ok());
}

TEST_CASE("a spawner's patrol point far outside the level is the same error as a robot's") {
    // The spawned robots walk the spawner's patrol: a point they cannot reach strands every one of them.
    const std::string text = R"({"format": "killswitch-level", "version": 2, "entities": [
  {"id": 1, "type": "floor", "position": [0, 0, 0], "props": {"size": [40, 40]}},
  {"id": 14, "type": "spawner", "name": "hatch", "position": [0, 0, 0], "props": {"patrol": {"points": [[5, 0, 5], [0, 0, -900]]}}}
]}
)";
    LoadReport report;
    CHECK_FALSE(load_level_string(text, "spawn.json", &report).ok());
    CHECK(report.error_count() == 1);
    CHECK_MESSAGE(
        report.str().find("entities[1].props.patrol.points[1]: spawner 14 (\"hatch\"): patrol point "
                          "(0, 0, -900) is 880 units outside the level") != std::string::npos,
        report.str());
    CHECK_MESSAGE(report.str().find("move it to where the spawned robots can walk") != std::string::npos,
                  report.str());

    Level level = guarded_level();
    auto& spawner = level.add(EntityType::Spawner, {0, 0, 0}, "hatch").as<SpawnerProps>();
    spawner.robot.patrol.points = {{5, 0, 5}};
    CHECK(validate(level).error_count() == 0);
    spawner.robot.patrol.points.push_back({0, 0, -900});
    CHECK(validate(level).error_count() == 1);
}

TEST_CASE("patrol shape errors and an empty route") {
    LoadReport report;
    CHECK_FALSE(load_level_string(level_text(R"({"patrol": {"mode": "loop"}})"), "a.json", &report).ok());
    CHECK(report.str().find("patrol.points: robot 12 (\"guard\"): missing required field \"points\"") !=
          std::string::npos);
    CHECK_FALSE(load_level_string(level_text(R"({"patrol": [[0, 0, 0]]})"), "b.json", &report).ok());
    CHECK(report.str().find("props.patrol: robot 12 (\"guard\"): expected patrol as an object") !=
          std::string::npos);
    CHECK_FALSE(load_level_string(level_text(R"({"patrol": {"points": [[0, 0]]}})"), "c.json", &report).ok());
    CHECK(report.str().find("patrol.points[0]: robot 12 (\"guard\"): expected an array of 3 numbers") !=
          std::string::npos);

    auto empty = load_level_string(level_text(R"({"patrol": {"points": [], "wait": 2}})"), "d.json", &report);
    REQUIRE(empty.ok());
    CHECK(report.warning_count() == 1);
    CHECK(report.str().find("patrol has no points, so the robot wanders") != std::string::npos);
    CHECK_FALSE(empty->entities[1].as<RobotProps>().patrol.active());
}

TEST_CASE("validate finds a patrol point that is not finite, too many points and a bad mode in memory") {
    Level level = guarded_level();
    level.entities[1].id = 12;
    level.next_id = 13;
    Patrol& patrol = guard(level).patrol;
    patrol.points = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {std::numeric_limits<float>::quiet_NaN(), 0, 5}};
    patrol.mode.value = "zigzag";
    const std::string report = validate(level, "draft.json").str();
    CHECK_MESSAGE(
        report.find("entities[1].props.patrol.points[3]: robot 12 (\"guard\"): patrol point (NaN, 0, 5) "
                    "is not finite") != std::string::npos,
        report);
    CHECK(report.find("robot 12 (\"guard\"): unknown patrol mode \"zigzag\"") != std::string::npos);

    patrol.mode.value = "loop";
    patrol.points.assign(kMaxPatrolPoints + 1, {1, 0, 1});
    CHECK(validate(level).str().find("patrol has 257 points; at most 256") != std::string::npos);
    patrol.points.resize(kMaxPatrolPoints);
    CHECK(validate(level).diagnostics.empty());
}
