#pragma once
// Builds one tile of the navigation mesh with Recast: rasterise the triangles touching the tile (plus a
// border), filter what the agent cannot stand on or fit under, erode by the agent radius, mark doorways,
// partition into regions, trace contours, build polygons and their height detail, and pack them as a
// Detour tile. Poly areas and flags are the nav module's (nav_flags.h).
#include "core/result.h"
#include "nav/nav_input.h"
#include "nav/nav_settings.h"

#include <vector>

namespace ks::nav {

// A packed Detour tile (dtCreateNavMeshData's output, allocated with dtAlloc): hand it to
// dtNavMesh::addTile with DT_TILE_FREE_DATA, or free it with dtFree. Empty (data null) when the tile holds
// nothing walkable.
struct TileData {
    unsigned char* data = nullptr;
    int size = 0;
};

// Scratch buffers reused from tile to tile, so a build does not allocate per tile what it can keep.
struct TileScratch {
    std::vector<int> triangles;
    std::vector<unsigned char> areas;
};

Result<TileData> build_tile(const InputGeometry& input, const NavSettings& settings, int column, int row,
                            TileScratch& scratch);

} // namespace ks::nav
