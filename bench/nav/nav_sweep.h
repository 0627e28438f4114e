#pragma once
// The cell-size sweep of `ks_bench nav`: for one cell size, how long a mesh takes to build, how far its
// path lengths are from the exact shortest paths (visibility_reference.h) on a flat field of box
// obstacles, and how many gaps around the robot's diameter it gets wrong against the exact rule (a disc of
// radius r passes a gap of width w when w >= 2r).
#include "core/random.h"
#include "level/level.h"
#include "nav/nav_settings.h"

#include <vector>

namespace ks::bench::nav_sweep {

struct FieldQuery {
    Vec3 from{0.0f}, to{0.0f};
    float exact = 0.0f; // shortest length for the disc, from the visibility graph
};

// A 60 x 60 walled floor with box obstacles spaced so every gap is far wider than the robot, and random
// query pairs in free space with their exact lengths.
struct ObstacleField {
    level::Level level;
    std::vector<FieldQuery> queries;
};
ObstacleField make_obstacle_field(int obstacle_count, int query_count, std::uint64_t seed);

struct Gap {
    float width = 0.0f;
    Vec3 near{0.0f}, far{0.0f}; // either side of the gap's wall
};
// Side-by-side walled strips, each crossed by a wall with one gap of a given width at a random offset.
struct GapStrips {
    level::Level level;
    std::vector<Gap> gaps;
};
GapStrips make_gap_strips(float agent_radius, std::uint64_t seed);

struct SweepRow {
    float cell_size = 0.0f;
    double build_field_ms = 0.0, build_main_ms = 0.0;
    int paths = 0, unreached = 0;
    double mean_error_pct = 0.0, max_error_pct = 0.0; // (mesh - exact) / exact over reached paths
    int gaps_open = 0, wrongly_closed = 0;            // gaps the exact rule keeps open, and of those closed
    int gaps_closed = 0, wrongly_opened = 0;
};

// Builds the three levels at `cell_size` (with `base` settings otherwise) and measures them.
SweepRow measure_cell_size(float cell_size, const nav::NavSettings& base, const ObstacleField& field,
                           const GapStrips& gaps, const level::Level& main_level);

// The tile size, in cells, that keeps tiles about as wide in world units as the default's.
int tile_cells_for(float cell_size, const nav::NavSettings& base);

} // namespace ks::bench::nav_sweep
