#pragma once
// Small levels for the navigation tests, built in code: floors, walls between two points, doorways,
// stairs, cylinders; and the robot settings the tests build with.
#include "level/level.h"
#include "nav/nav_mesh.h"
#include "nav/nav_settings.h"

#include <memory>
#include <vector>

namespace ks::test {

// The robot's settings with the character controller's step height and slope
// (physics::CharacterSettings: 0.65 and 50 degrees; the nav tests cannot see physics).
nav::NavSettings robot_settings();
// The mesh of `level` with robot_settings(); fails the test when it cannot be built.
std::unique_ptr<nav::NavMesh> build_robot_mesh(const level::Level& level);

// A floor whose walking surface is at `centre` (y), `size` along x and z.
level::Entity& add_floor(level::Level& level, Vec3 centre, Vec2 size);
// A wall standing on y = a.y from a to b (along x or along z), `thickness` thick and `height` tall.
level::Entity& add_wall(level::Level& level, Vec3 a, Vec3 b, float thickness = 0.5f, float height = 4.0f);
// A wall from a to b (along x) with an opening of `gap` width starting at x = gap_min_x.
void add_wall_with_gap(level::Level& level, Vec3 a, Vec3 b, float gap_min_x, float gap,
                       float thickness = 0.5f);
level::Entity& add_door(level::Level& level, Vec3 bottom_centre, float width, bool open);
level::Entity& add_cylinder(level::Level& level, Vec3 bottom_centre, float radius);

// Where the path (a polyline) first crosses the plane z = `z`, as x; nullopt when it never does.
std::optional<float> crossing_x(const std::vector<Vec3>& path, float z);
// Smallest horizontal distance from any segment of the path to `point`.
float closest_approach(const std::vector<Vec3>& path, Vec3 point);

} // namespace ks::test
