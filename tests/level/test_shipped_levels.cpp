// levels/main.json and levels/dojo.json: clean loads, byte-stable saves, and the reference layout.
#include "level/level_io.h"
#include "reference_levels.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <map>

using namespace ks::level;

namespace {

std::filesystem::path shipped(const char* name) {
    return ks::test::source_dir() / "levels" / name;
}

// KS_WRITE_SHIPPED_LEVELS=1 regenerates the shipped files from the reference tables (the generator);
// without it the tests check the files as they are.
void maybe_write(const char* name, const Level& level) {
    if (const char* flag = std::getenv("KS_WRITE_SHIPPED_LEVELS"); flag && std::string(flag) == "1") {
        auto saved = save_level_file(shipped(name), level);
        REQUIRE_MESSAGE(saved.ok(), saved.error().str());
    }
}

Level load_clean(const char* name) {
    LoadReport report;
    auto level = load_level_file(shipped(name), &report);
    REQUIRE_MESSAGE(level.ok(), report.str());
    CHECK_MESSAGE(report.error_count() == 0, report.str());
    CHECK_MESSAGE(report.warning_count() == 0, report.str());
    return std::move(level).value();
}

std::map<EntityType, int> count_types(const Level& level) {
    std::map<EntityType, int> counts;
    for (const Entity& e : level.entities) ++counts[e.type()];
    return counts;
}

ks::Vec3 forward_of_yaw(float yaw_degrees) {
    const float yaw = ks::radians(yaw_degrees);
    return {-std::sin(yaw), 0.0f, -std::cos(yaw)};
}

bool on_floor(const Level& level, ks::Vec3 point) {
    for (const Entity& e : level.entities) {
        const auto* floor = e.try_as<FloorProps>();
        if (!floor || floor->ceiling || std::fabs(e.position.y - point.y) > 1e-4f) continue;
        if (std::fabs(point.x - e.position.x) <= floor->size.x / 2 + 1e-4f &&
            std::fabs(point.z - e.position.z) <= floor->size.y / 2 + 1e-4f)
            return true;
    }
    return false;
}

} // namespace

TEST_CASE("main.json loads cleanly, matches the reference layout and re-saves byte-identically") {
    maybe_write("main.json", ks::test::reference_main_level());
    const Level level = load_clean("main.json");
    const std::string text = ks::test::read_file(shipped("main.json"));
    CHECK(save_level_string(level) == text);
    CHECK(level == ks::test::reference_main_level());

    auto counts = count_types(level);
    CHECK(counts[EntityType::Wall] == 18);
    CHECK(counts[EntityType::Floor] == 4);
    CHECK(counts[EntityType::Door] == 2);
    CHECK(counts[EntityType::Stair] == 3);
    CHECK(counts[EntityType::TopLight] == 8);
    CHECK(counts[EntityType::FloorLight] == 3);
    CHECK(counts[EntityType::Robot] == 8);
    CHECK(counts[EntityType::Pickup] == 3);
    CHECK(counts[EntityType::GasCylinder] == 6);
    CHECK(counts[EntityType::ControlPanel] == 1);
    CHECK(counts[EntityType::Sound] == 4);
    CHECK(level.settings.ambient_sound.value == "ambient_facility");
    CHECK(level.player_start.position == ks::Vec3(0, 0, 25));
    CHECK(level.player_start.yaw == 0.0f);

    int ceilings = 0;
    for (const Entity& e : level.entities) {
        CHECK_MESSAGE(!e.name.empty(), "entity ", e.id, " has no name");
        // Everything lies inside the main level's footprint (the dojo at x -90 is a separate file).
        CHECK(e.position.x >= -20.0f);
        CHECK(e.position.x <= 100.0f);
        if (const auto* wall = e.try_as<WallProps>()) {
            CHECK(wall->texture == "concrete");
            CHECK(wall->size.z == 0.5f);
        }
        if (const auto* floor = e.try_as<FloorProps>()) {
            ceilings += floor->ceiling;
            CHECK(floor->texture == (floor->ceiling ? "ceiling" : "tiles"));
        }
        if (const auto* robot = e.try_as<RobotProps>()) {
            CHECK(robot->health == 100.0f);
            CHECK(robot->shooting_distance == 11.0f);
            CHECK(robot->eye_radius_min == 19.0f);
            CHECK(robot->eye_radius_max == 25.0f);
            CHECK(robot->hit_probability == 0.7f);
            CHECK_FALSE(robot->dummy);
        }
        if (e.try_as<TopLightProps>()) CHECK(e.position.y == 16.0f);
        if (const auto* light = e.try_as<FloorLightProps>()) {
            CHECK(light->light.intensity == 0.8f);
            CHECK(light->light.range == 20.0f);
        }
        // Every stair's top edge lands on a platform at the stair's full rise.
        if (const auto* stair = e.try_as<StairProps>()) {
            const ks::Vec3 top = e.position + forward_of_yaw(e.rotation.x) * (stair->size.z / 2) +
                                 ks::Vec3(0, stair->size.y, 0);
            CHECK_MESSAGE(on_floor(level, top), e.name, " ends at (", top.x, ", ", top.y, ", ", top.z, ")");
        }
        // Pickups stand on a floor (the platforms in the main level).
        if (e.try_as<PickupProps>()) CHECK_MESSAGE(on_floor(level, e.position), e.name);
    }
    CHECK(ceilings == 1);
}

TEST_CASE("dojo.json loads cleanly, matches the reference and re-saves byte-identically") {
    maybe_write("dojo.json", ks::test::reference_dojo_level());
    const Level level = load_clean("dojo.json");
    CHECK(save_level_string(level) == ks::test::read_file(shipped("dojo.json")));
    CHECK(level == ks::test::reference_dojo_level());

    auto counts = count_types(level);
    CHECK(counts[EntityType::Wall] == 8);
    CHECK(counts[EntityType::Floor] == 1);
    CHECK(counts[EntityType::FloorLight] == 2);
    CHECK(counts[EntityType::Pickup] == 3);
    CHECK(counts[EntityType::Robot] == 1);
    CHECK(counts[EntityType::TopLight] == 0); // no ceiling, no top lights
    CHECK(level.entities.size() == 15);
    CHECK(level.settings.ambient_sound.value == "ambient_dojo");
    CHECK(level.player_start.position == ks::Vec3(-90, 0, -5));

    for (const Entity& e : level.entities) {
        if (const auto* wall = e.try_as<WallProps>()) {
            CHECK(wall->texture == "wood");
            CHECK(wall->size.x == doctest::Approx(13.264));
            CHECK(wall->size.y == 12.0f);
            // Octagon: each wall's centre is 16 from the dojo centre and its face looks at the centre.
            const ks::Vec3 from_centre = e.position - ks::Vec3(-90, 0, -15);
            CHECK(glm::length(from_centre) == doctest::Approx(16).epsilon(1e-4));
            const ks::Vec3 normal = -forward_of_yaw(e.rotation.x); // local +z
            CHECK(glm::dot(glm::normalize(from_centre), normal) == doctest::Approx(1).epsilon(1e-4));
        }
        if (const auto* robot = e.try_as<RobotProps>()) CHECK(robot->dummy);
        if (const auto* floor = e.try_as<FloorProps>()) CHECK_FALSE(floor->ceiling);
    }
}

TEST_CASE(
    "archive.json loads with no error or warning and re-saves byte-identically; its walls are brushes") {
    // Built by the editor from levels/source/archive.kss (tests/editor/test_archive_script.cpp rebuilds it).
    const Level level = load_clean("archive.json");
    CHECK(save_level_string(level) == ks::test::read_file(shipped("archive.json")));
    CHECK(level.name == "The Archive");
    auto counts = count_types(level);
    CHECK(counts[EntityType::Brush] >= 15);
    CHECK(counts[EntityType::ControlPanel] == 1);
    CHECK(counts[EntityType::Robot] >= 1);
    CHECK(level.objectives.size() == 2);
}

TEST_CASE(
    "lockdown.json loads with no error or warning (format and logic checks) and re-saves byte-identically") {
    // Built by the editor from levels/source/lockdown.kss (tests/editor/test_lockdown_script.cpp rebuilds
    // it).
    const Level level = load_clean("lockdown.json");
    CHECK(save_level_string(level) == ks::test::read_file(shipped("lockdown.json")));
    CHECK(level.name == "Lockdown");

    auto counts = count_types(level);
    CHECK(counts[EntityType::Trigger] >= 1);
    CHECK(counts[EntityType::Spawner] >= 1);
    CHECK(counts[EntityType::Message] >= 1);
    CHECK(counts[EntityType::ControlPanel] == 1);
    CHECK(counts[EntityType::Stair] >= 1);
    CHECK(counts[EntityType::GasCylinder] >= 1);
    CHECK(level.objectives.size() >= 2);
    int locked = 0;
    for (const Entity& e : level.entities) {
        CHECK_MESSAGE(!e.name.empty(), "entity ", e.id, " has no name");
        if (const auto* door = e.try_as<DoorProps>()) locked += door->locked;
        if (const auto* wall = e.try_as<WallProps>()) CHECK(wall->size.y <= 16.0f); // main.json's storey
        if (e.try_as<PickupProps>()) CHECK_MESSAGE(on_floor(level, e.position), e.name);
        if (const auto* stair = e.try_as<StairProps>()) {
            const ks::Vec3 top = e.position + forward_of_yaw(e.rotation.x) * (stair->size.z / 2) +
                                 ks::Vec3(0, stair->size.y, 0);
            CHECK_MESSAGE(on_floor(level, top), e.name, " ends at (", top.x, ", ", top.y, ", ", top.z, ")");
        }
    }
    CHECK(locked >= 1);
}
