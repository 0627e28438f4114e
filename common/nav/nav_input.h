#pragma once
// What Recast rasterises for a level: the triangles of every entity's static solid shape
// (level::static_solid_shape: walls, floors, stair wedges, lamp stands, gas cylinders, the control panel;
// cylinders as 16-sided prisms) and of every brush's faces (level::world_brush), each triangle's area
// (walkable where its slope allows), the triangles each tile touches, and each door's doorway footprint,
// whose polygons get the door flag.
#include "core/math.h"
#include "core/result.h"
#include "geometry/aabb.h"
#include "level/level.h"
#include "nav/nav_settings.h"

#include <array>
#include <string>
#include <vector>

namespace ks::nav {

// A doorway's floor footprint: a convex quad on the xz plane (y of the corners unused) and the height span
// it marks. Polygons whose centre lies inside become that door's polygons.
struct DoorFootprint {
    int entity_id = 0;
    std::array<Vec3, 4> corners{};
    float y_min = 0.0f, y_max = 0.0f;
    bool open = false; // the door's state when the level starts
    bool contains(const Vec3& p, float margin) const;
};

struct TileGrid {
    Vec3 origin{0.0f};       // min corner of the level's bounds
    float tile_world = 0.0f; // tile edge in world units
    int columns = 0, rows = 0;
};

struct InputGeometry {
    std::vector<float> vertices;      // x, y, z
    std::vector<int> triangles;       // three vertex indices each
    std::vector<unsigned char> areas; // per triangle: RC_WALKABLE_AREA or RC_NULL_AREA
    geometry::Aabb bounds = geometry::Aabb::empty();
    std::vector<DoorFootprint> doors;
    TileGrid grid;
    std::vector<std::vector<int>> tile_triangles; // per tile (row-major), the triangles touching it
};

// Gathers the input of `level`; an error names the entity with non-finite or absurd numbers, or says the
// level has no solid shape at all (nothing to walk on).
Result<InputGeometry> collect_input(const level::Level& level, const NavSettings& settings);

// Whether tile (column, row) is built from the same input in both: the same grid and height span, the same
// triangles touching it (corners and areas, in order) and the same doorways over it (with its border). A
// tile built from equal input is the same tile (the build is deterministic), so it may be copied.
bool same_tile_input(const InputGeometry& a, const InputGeometry& b, int column, int row,
                     const NavSettings& settings);

// The border Recast adds around each tile, in cells: the agent radius plus a margin so that erosion near a
// tile edge sees the neighbouring tile's obstacles.
int tile_border_cells(const NavSettings& settings);

} // namespace ks::nav
