#include "reference_levels.h"

#include "level/shutdown_objective.h"

#include <doctest/doctest.h>

#include <cmath>

namespace ks::test {
namespace {

using namespace ks::level;

// Degrees in (-180, 180], rounded to 1e-3 so that pi fractions give tidy numbers in the file.
float tidy_degrees(double radians) {
    double deg = radians * 180.0 / std::numbers::pi;
    deg = std::fmod(deg, 360.0);
    if (deg <= -180.0) deg += 360.0;
    if (deg > 180.0) deg -= 360.0;
    return static_cast<float>(std::round(deg * 1000.0) / 1000.0);
}

constexpr double kPi = std::numbers::pi;
constexpr float kWallHeight = 16.0f;
constexpr float kWallThickness = 0.5f;

Settings reference_settings() {
    Settings s;
    s.ambient_color = {1, 1, 1}; // AmbientLight 0xFFFFFF, 0.2
    s.ambient_intensity = 0.2f;
    s.sun_color = {1, 1, 1}; // PointLight 0xFFFFFF, 0.1 at (0, 40, 0)
    s.sun_intensity = 0.1f;
    // The reference sun is a point light at (0, 40, 0) above the main level's centre (40, 0, 0); our sun is
    // directional, travelling from that point towards the centre.
    s.sun_direction = {0.70710677f, -0.70710677f, 0.0f};
    s.gravity = -25.0f;
    // The reference's fog parameters were not measured; keep our default, snapped to the file's 8-bit
    // colours.
    s.fog_color = {13 / 255.0f, 15 / 255.0f, 20 / 255.0f};
    return s;
}

struct WallRow {
    const char* name;
    float x, base_y, z, width, height, rot_y;
};

void add_wall(Level& level, const WallRow& row, const char* texture, float texture_scale) {
    Entity& e = level.add(EntityType::Wall, {row.x, row.base_y, row.z}, row.name);
    e.rotation.x = tidy_degrees(row.rot_y);
    auto& wall = e.as<WallProps>();
    wall.size = {row.width, row.height, kWallThickness};
    wall.texture = texture;
    wall.texture_scale = texture_scale;
}

void add_floor(Level& level, const char* name, Vec3 position, Vec2 size, bool ceiling) {
    auto& floor = level.add(EntityType::Floor, position, name).as<FloorProps>();
    floor.size = size;
    floor.ceiling = ceiling;
    floor.texture = ceiling ? "ceiling" : "tiles";
    floor.texture_scale = 2.0f; // floor1.jpg repeats every 2 units (repeat w/2)
}

void add_stair(Level& level, const char* name, Vec3 position, float yaw_degrees) {
    Entity& e = level.add(EntityType::Stair, position, name);
    e.rotation.x = yaw_degrees;
    auto& stair = e.as<StairProps>();
    stair.size = {12, 6, 12};
    stair.steps = 10;
    stair.texture = "tiles";
}

void add_top_light(Level& level, const char* name, float x, float z, float rot_y) {
    Entity& e = level.add(EntityType::TopLight, {x, 16, z}, name);
    e.rotation.x = tidy_degrees(rot_y);
    auto& light = e.as<TopLightProps>();
    light.light = {{1, 1, 1}, 1.0f, 24.0f, true};
    light.hang = 2.0f; // fixture at y 16, bulb (PointLight) at y 14
}

void add_floor_light(Level& level, const char* name, Vec3 position, double rot_y) {
    Entity& e = level.add(EntityType::FloorLight, position, name);
    e.rotation.x = tidy_degrees(rot_y);
    auto& light = e.as<FloorLightProps>();
    light.light = {{1, 1, 1}, 0.8f, 20.0f, true};
    light.height = 4.0f;
}

void add_robot(Level& level, const char* name, Vec3 position, float rot_y, bool dummy = false) {
    Entity& e = level.add(EntityType::Robot, position, name);
    e.rotation.x = robot_yaw_from_reference(rot_y);
    auto& robot = e.as<RobotProps>();
    robot = RobotProps{}; // the struct defaults are the reference's numbers (section 5.2)
    robot.health = 100;
    robot.velocity = 8;
    robot.rotation_velocity = 8;
    robot.shooting_distance = 11;
    robot.eye_radius_min = 19;
    robot.eye_radius_max = 25;
    robot.cooldown = 1;
    robot.hit_probability = 0.7f;
    robot.angry_duration = 10;
    robot.damage = 10;
    robot.dummy = dummy;
}

void add_pickup(Level& level, const char* name, Vec3 position, const char* kind, float amount) {
    auto& pickup = level.add(EntityType::Pickup, position, name).as<PickupProps>();
    pickup.kind.value = kind;
    pickup.amount = amount;
}

void add_gas_cylinder(Level& level, const char* name, float x, float z, double rot_y) {
    Entity& e = level.add(EntityType::GasCylinder, {x, 0, z}, name);
    e.rotation.x = tidy_degrees(rot_y);
    auto& gas = e.as<GasCylinderProps>();
    gas.radius = 0.5f;
    gas.height = 2.0f;
    gas.damage = 30.0f;
    gas.blast_radius = 7.0f; // surroundRadius; the blast box is (0.5 + 7) wide each side of the axis
    gas.explosion_power = 25.0f;
}

// Not in the reference (it was silent): ambient emitters placed for issue 14.
void add_sound(Level& level, const char* name, Vec3 position, const char* sound, float volume, float radius) {
    auto& emitter = level.add(EntityType::Sound, position, name).as<SoundProps>();
    emitter.sound.value = sound;
    emitter.volume = volume;
    emitter.radius = radius;
    emitter.loop = true;
}

} // namespace

float robot_yaw_from_reference(float rot_y_radians) {
    return tidy_degrees(rot_y_radians - kPi / 2);
}

Level reference_main_level() {
    Level level;
    level.name = "Main level";
    level.settings = reference_settings();
    level.player_start = {{0, 0, 25}, 0};

    // 4.3 walls: type 0 (concrete, defaultWall.png repeating every 10 units), thickness 0.5 centred on the
    // reference's planes. -z is "north" (the way the player faces at the start).
    const float h = kWallHeight;
    const float pi2 = static_cast<float>(kPi / 2);
    const WallRow walls[] = {
        {"Room 1 west wall", -10, 0, 0, 60, h, pi2},
        {"Room 1 east wall", 10, 0, 0, 60, h, pi2},
        {"Room 1 south wall", 0, 0, 30, 20, h, 0},
        {"Door 1 west side wall", -6.25f, 0, -30, 7.5f, h, 0},
        {"Door 1 east side wall", 6.25f, 0, -30, 7.5f, h, 0},
        {"Door 1 lintel", 0, 5, -30, 5, 11, 0},
        {"Room 2 west wall", -10, 0, -60, 60, h, pi2},
        {"Room 2 north wall", 25, 0, -90, 70, h, 0},
        {"Room 2 east wall", 60, 0, -30, 120, h, pi2},
        {"Door 2 west side wall", 21.25f, 0, 30, 22.5f, h, 0},
        {"Door 2 east side wall", 48.75f, 0, 30, 22.5f, h, 0},
        {"Door 2 lintel", 35, 5, 30, 5, 11, 0},
        {"East platform west face", 48, 0, -37, 12, 6, pi2},
        {"East platform north face", 54, 0, -43, 12, 6, 0},
        {"Room 3 west wall", 25, 0, 50, 40, h, pi2},
        {"Room 3 south wall", 62.5f, 0, 70, 75, h, 0},
        {"Room 3 north wall", 80, 0, 30, 40, h, 0},
        {"Room 3 east wall (gap under the ceiling)", 100, 0, 50, 40, 11, pi2},
    };
    for (const WallRow& row : walls) add_wall(level, row, "concrete", 10.0f);

    // 4.2 floors.
    add_floor(level, "Ground", {40, 0, 0}, {120, 200}, false);
    add_floor(level, "Ceiling", {40, 16, 0}, {120, 200}, true);
    add_floor(level, "Corner platform", {-4, 6, -84}, {12, 12}, false);
    add_floor(level, "East platform", {54, 6, -37}, {12, 12}, false);

    // 4.4 doors (doorHeight 5; each leaf slides 2 units in 0.5 s).
    for (auto [name, position] : {std::pair{"Door 1 (room 1 to room 2)", Vec3(0, 0, -30)},
                                  std::pair{"Door 2 (room 2 to room 3)", Vec3(35, 0, 30)}}) {
        auto& door = level.add(EntityType::Door, position, name).as<DoorProps>();
        door.width = 5;
        door.height = 5;
        door.open_offset = 2;
        door.open_time = 0.5f;
    }

    // 4.5 stairs: ours rise toward local -z, so "rises toward -z" is yaw 0 and "toward -x" yaw 90.
    add_stair(level, "Stair to the corner platform (from the south)", {-4, 0, -72}, 0);
    add_stair(level, "Stair to the corner platform (from the east)", {8, 0, -84}, 90);
    add_stair(level, "Stair to the east platform", {54, 0, -25}, 0);

    // 4.6 lights.
    add_top_light(level, "Room 1 top light", 0, 20, 0);
    add_top_light(level, "Room 2 top light (west, middle)", 0, -40, 0);
    add_top_light(level, "Room 2 top light (west, north)", 0, -80, 0);
    add_top_light(level, "Room 2 top light (east, north)", 35, -80, 0);
    add_top_light(level, "Room 2 top light (east, middle)", 35, -40, 0);
    add_top_light(level, "Room 2 top light (east, south)", 35, 0, 0);
    add_top_light(level, "Room 3 top light (east)", 90, 50, static_cast<float>(-kPi / 2));
    add_top_light(level, "Room 3 top light (west)", 40, 50, static_cast<float>(-kPi / 2));
    add_floor_light(level, "Room 1 floor light", {7, 0, -6}, -kPi / 4);
    add_floor_light(level, "Room 2 floor light", {40, 0, -86}, 0);
    add_floor_light(level, "Room 3 floor light", {29, 0, 65}, 3 * kPi / 4);

    // 4.7 robots.
    add_robot(level, "Robot on the east platform", {54, 6, -37}, 0);
    add_robot(level, "Robot behind door 1", {0, 0, -55}, -pi2);
    add_robot(level, "Robot in room 2 (north-east)", {50, 0, -70}, 0);
    add_robot(level, "Robot guarding door 2 (west)", {35, 0, 10}, -pi2);
    add_robot(level, "Robot guarding door 2 (east)", {50, 0, 10}, static_cast<float>(-3 * kPi / 4));
    add_robot(level, "Robot by the control panel", {82, 0, 50}, 0);
    add_robot(level, "Robot in room 3 (west)", {40, 0, 56}, 0);
    add_robot(level, "Robot in room 3 (middle)", {55, 0, 50}, 0);

    // 4.8 pickups (on the platforms, y = platform height).
    add_pickup(level, "Ammo on the corner platform", {-2, 6, -82}, "ammo", 50);
    add_pickup(level, "Shield on the corner platform", {-6, 6, -86}, "shield", 10);
    add_pickup(level, "Health on the east platform", {56, 6, -35}, "health", 10);

    // 4.9 gas cylinders.
    add_gas_cylinder(level, "Gas cylinder in room 1", -5, 12, -0.8 * kPi);
    add_gas_cylinder(level, "Gas cylinder behind door 1", 16, -38, 0.8 * kPi);
    add_gas_cylinder(level, "Gas cylinder in room 2 (north)", 32, -65, 0.3 * kPi);
    add_gas_cylinder(level, "Gas cylinder in room 2 (south)", 32, -10, 0.3 * kPi);
    add_gas_cylinder(level, "Gas cylinder in room 3 (south)", 50, 60, -0.6 * kPi);
    add_gas_cylinder(level, "Gas cylinder in room 3 (north)", 60, 40, -0.6 * kPi);

    // 4.10 control panel.
    auto& panel = level.add(EntityType::ControlPanel, {90, 0, 50}, "Control panel").as<ControlPanelProps>();
    panel.size = {2.94f, 4.0f, 5.34f};
    // Using it wins: the level's one objective, which the panel's on_use link completes (format v2).
    add_shutdown_objective(level);

    // Sound emitters: the panel beeps so a player can find it by ear; machines and a vent give the rooms a
    // voice; an alarm, quiet and short-ranged, marks the way into the last room. The level's ambient loop is
    // the format's default, ambient_facility.
    add_sound(level, "Control panel beeps", {90, 5, 50}, "computer_beeps", 0.6f, 25);
    add_sound(level, "Room 1 vent", {-8, 14, 0}, "vent_loop", 0.4f, 24);
    add_sound(level, "Room 2 machine hum", {20, 2, -86}, "machine_hum", 0.7f, 35);
    add_sound(level, "Alarm inside door 2", {35, 7, 32}, "alarm_loop", 0.3f, 16);
    return level;
}

Level reference_dojo_level() {
    Level level;
    level.name = "Dojo";
    level.settings = reference_settings();
    level.settings.ambient_sound.value = "ambient_dojo";
    level.player_start = {{-90, 0, -5}, 0};

    // 4.11: an octagon of wood walls around (-90, 0, -15): radius 16, width 16.58 * 16 / 20, height 12.
    const char* const kSides[] = {"south", "south-east", "east", "north-east",
                                  "north", "north-west", "west", "south-west"};
    for (int k = 0; k < 8; ++k) {
        const double a = k * kPi / 4;
        const std::string name = std::string("Dojo ") + kSides[k] + " wall";
        const float x = static_cast<float>(std::round((-90 + 16 * std::sin(a)) * 1e4) / 1e4);
        const float z = static_cast<float>(std::round((-15 + 16 * std::cos(a)) * 1e4) / 1e4);
        add_wall(level, {name.c_str(), x, 0, z, 13.264f, 12, static_cast<float>(a)}, "wood", 4.0f);
    }
    add_floor(level, "Dojo floor", {-90, 0, -15}, {80, 80}, false);
    add_floor_light(level, "Dojo floor light (east)", {-80.686f, 0, -5.686f}, 5 * kPi / 4);
    add_floor_light(level, "Dojo floor light (west)", {-99.314f, 0, -5.686f}, 11 * kPi / 4);
    add_pickup(level, "Dojo ammo", {-86, 0, -25}, "ammo", 50);
    add_pickup(level, "Dojo health", {-90, 0, -25}, "health", 10);
    add_pickup(level, "Dojo shield", {-94, 0, -25}, "shield", 10);
    add_robot(level, "Test robot (animation dummy)", {-90, 0, -15}, static_cast<float>(-kPi / 2), true);
    return level;
}

} // namespace ks::test

namespace {
ks::Vec3 forward_of_yaw_degrees(float yaw_degrees) {
    const float yaw = ks::radians(yaw_degrees);
    return {-std::sin(yaw), 0.0f, -std::cos(yaw)};
}
} // namespace

TEST_CASE("robot yaw conversion keeps the reference's facing") {
    // The reference robot faces its local +X rotated by rotY: (cos rotY, 0, -sin rotY).
    for (float rot_y : {0.0f, -ks::kPi / 2, -3 * ks::kPi / 4, 1.0f, 2.5f}) {
        const ks::Vec3 reference(std::cos(rot_y), 0, -std::sin(rot_y));
        const ks::Vec3 ours = forward_of_yaw_degrees(ks::test::robot_yaw_from_reference(rot_y));
        CHECK(glm::dot(reference, ours) == doctest::Approx(1).epsilon(1e-5));
        const float yaw = ks::test::robot_yaw_from_reference(rot_y);
        CHECK(yaw > -180.0f);
        CHECK(yaw <= 180.0f);
    }
    CHECK(ks::test::robot_yaw_from_reference(0) == -90.0f);
}
