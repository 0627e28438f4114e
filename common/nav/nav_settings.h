#pragma once
// The numbers a navigation mesh is built with: the agent it is built for (a robot's capsule, its step
// height and steepest walkable slope) and the voxel grid Recast samples the level on (cell size, cell
// height, tile size). See docs/navigation.md for why the defaults are what they are.
#include "core/math.h"
#include "core/result.h"
#include "level/entity_shapes.h"

#include <optional>

namespace ks::nav {

struct NavSettings {
    // The agent. Radius and height default to the robot's body (level::kRobotRadius, kRobotHeight); the
    // step height and slope belong to the character controller (physics), which nav does not see, so
    // they start at 0 and robot_nav_settings() fills them from the numbers the game passes in.
    float agent_radius = level::kRobotRadius;
    float agent_height = level::kRobotHeight;
    float agent_climb = 0.0f;
    float agent_max_slope_degrees = 0.0f;

    // The voxel grid. The cell size is a quarter of the robot radius, so erosion by the radius is a whole
    // number of cells and removes exactly the radius; the cell height is small enough that the 0.65 step
    // height is 13 cells, not rounded down to a 0.6 that would refuse the 0.6-unit steps.
    float cell_size = 0.2f;
    float cell_height = 0.05f;
    int tile_size_cells = 64;          // tiles of 64 x 64 cells (12.8 units at the default cell size)
    float edge_max_error_cells = 1.3f; // how far simplified polygon edges may stray from the voxels
    float edge_max_length = 12.0f;     // world units; longer border edges are split
    int min_region_cells = 64;         // islands smaller than this (8 x 8 cells) are dropped
    int merge_region_cells = 400;      // regions smaller than this merge into a neighbour
    float detail_sample_distance_cells = 6.0f;
    float detail_max_error_cells = 1.0f; // in cell heights

    // Queries look for the nearest polygon within this box around a point (half extents).
    Vec3 query_extents{2.0f, 2.0f, 2.0f};
    // find_path and path_length search any-angle (Detour's DT_FINDPATH_ANY_ANGLE): shortest paths for
    // a higher query cost (docs/performance.md); false gives Detour's plain polygon A*.
    bool any_angle_paths = true;
    int max_path_polygons = 4096; // the longest corridor a path query follows
    int max_search_nodes = 65535; // Detour's node pool (its maximum)
};

// Settings for the robots: radius and height from level's body constants, step height and steepest slope
// from the character controller (physics::CharacterSettings::step_height, max_slope_degrees), which the
// game passes in so the numbers live in one place.
NavSettings robot_nav_settings(float step_height, float max_slope_degrees);
// The same for the player's body (level::kPlayerRadius, kPlayerHeight): the autoplay bot plans on it and the
// editor asks it whether the player can walk to the control panel.
NavSettings player_nav_settings(float step_height, float max_slope_degrees);

// A clear error for settings Recast cannot build with (non-positive sizes, a slope outside (0, 90), tiles
// too small for the agent's border); nullopt when they are usable.
std::optional<Error> check_settings(const NavSettings& settings);

// The agent's sizes in whole cells, as Recast takes them: the radius and height rounded up (the mesh keeps
// at least that much clearance), the climb rounded down (never more than the controller climbs).
struct AgentCells {
    int radius = 0;
    int height = 0;
    int climb = 0;
};
AgentCells agent_cells(const NavSettings& settings);

} // namespace ks::nav
