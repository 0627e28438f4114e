#include "nav/nav_tile_builder.h"

#include "nav/nav_flags.h"

#include <DetourAlloc.h>
#include <DetourNavMesh.h>
#include <DetourNavMeshBuilder.h>
#include <Recast.h>

#include <cmath>
#include <memory>
#include <string>

namespace ks::nav {
namespace {

struct RecastFree {
    void operator()(rcHeightfield* p) const { rcFreeHeightField(p); }
    void operator()(rcCompactHeightfield* p) const { rcFreeCompactHeightfield(p); }
    void operator()(rcContourSet* p) const { rcFreeContourSet(p); }
    void operator()(rcPolyMesh* p) const { rcFreePolyMesh(p); }
    void operator()(rcPolyMeshDetail* p) const { rcFreePolyMeshDetail(p); }
};
template <class T>
using RecastPtr = std::unique_ptr<T, RecastFree>;

Error tile_error(const char* step, int column, int row) {
    return Error(std::string("navigation mesh: Recast failed in ") + step + " for tile (" +
                     std::to_string(column) + ", " + std::to_string(row) + ")",
                 Location{}, "out of memory, or the level is too large for the cell size: raise cell_size");
}

rcConfig tile_config(const InputGeometry& input, const NavSettings& s, int column, int row) {
    const AgentCells agent = agent_cells(s);
    rcConfig cfg{};
    cfg.cs = s.cell_size;
    cfg.ch = s.cell_height;
    cfg.walkableSlopeAngle = s.agent_max_slope_degrees;
    cfg.walkableHeight = agent.height;
    cfg.walkableClimb = agent.climb;
    cfg.walkableRadius = agent.radius;
    cfg.maxEdgeLen = static_cast<int>(s.edge_max_length / s.cell_size);
    cfg.maxSimplificationError = s.edge_max_error_cells * s.cell_size;
    cfg.minRegionArea = s.min_region_cells;
    cfg.mergeRegionArea = s.merge_region_cells;
    cfg.maxVertsPerPoly = DT_VERTS_PER_POLYGON;
    cfg.tileSize = s.tile_size_cells;
    cfg.borderSize = tile_border_cells(s);
    cfg.width = cfg.tileSize + cfg.borderSize * 2;
    cfg.height = cfg.width;
    cfg.detailSampleDist = s.detail_sample_distance_cells * s.cell_size;
    cfg.detailSampleMaxError = s.detail_max_error_cells * s.cell_height;
    const TileGrid& g = input.grid;
    const float border = static_cast<float>(cfg.borderSize) * s.cell_size;
    cfg.bmin[0] = g.origin.x + static_cast<float>(column) * g.tile_world - border;
    cfg.bmin[1] = input.bounds.min.y;
    cfg.bmin[2] = g.origin.z + static_cast<float>(row) * g.tile_world - border;
    cfg.bmax[0] = g.origin.x + static_cast<float>(column + 1) * g.tile_world + border;
    cfg.bmax[1] = input.bounds.max.y;
    cfg.bmax[2] = g.origin.z + static_cast<float>(row + 1) * g.tile_world + border;
    return cfg;
}

// Rasterises the tile's triangles and filters spans the agent cannot use; false when Recast fails.
bool rasterise(rcContext& ctx, const InputGeometry& input, const std::vector<int>& tile_tris,
               const rcConfig& cfg, TileScratch& scratch, rcHeightfield& solid) {
    if (!rcCreateHeightfield(&ctx, solid, cfg.width, cfg.height, cfg.bmin, cfg.bmax, cfg.cs, cfg.ch))
        return false;
    scratch.triangles.clear();
    scratch.areas.clear();
    for (int t : tile_tris) {
        scratch.triangles.insert(scratch.triangles.end(), &input.triangles[static_cast<size_t>(t) * 3],
                                 &input.triangles[static_cast<size_t>(t) * 3] + 3);
        scratch.areas.push_back(input.areas[static_cast<size_t>(t)]);
    }
    if (!rcRasterizeTriangles(&ctx, input.vertices.data(), static_cast<int>(input.vertices.size() / 3),
                              scratch.triangles.data(), scratch.areas.data(),
                              static_cast<int>(scratch.areas.size()), solid, cfg.walkableClimb))
        return false;
    rcFilterLowHangingWalkableObstacles(&ctx, cfg.walkableClimb, solid);
    rcFilterLedgeSpans(&ctx, cfg.walkableHeight, cfg.walkableClimb, solid);
    rcFilterWalkableLowHeightSpans(&ctx, cfg.walkableHeight, solid);
    return true;
}

void mark_doors(rcContext& ctx, const InputGeometry& input, rcCompactHeightfield& chf) {
    for (const DoorFootprint& door : input.doors) {
        float verts[12];
        for (int i = 0; i < 4; ++i) {
            verts[i * 3 + 0] = door.corners[i].x;
            verts[i * 3 + 1] = door.corners[i].y;
            verts[i * 3 + 2] = door.corners[i].z;
        }
        rcMarkConvexPolyArea(&ctx, verts, 4, door.y_min, door.y_max, kAreaDoor, chf);
    }
}

Result<TileData> pack_tile(const rcPolyMesh& pmesh, const rcPolyMeshDetail& dmesh, const NavSettings& s,
                           int column, int row) {
    if (pmesh.nverts >= 0xffff)
        return Error("navigation mesh: tile (" + std::to_string(column) + ", " + std::to_string(row) +
                         ") has too many vertices for Detour",
                     Location{}, "lower tile_size_cells");
    for (int i = 0; i < pmesh.npolys; ++i)
        pmesh.flags[i] = pmesh.areas[i] == kAreaDoor ? (kFlagWalk | kFlagDoor) : kFlagWalk;
    dtNavMeshCreateParams params{};
    params.verts = pmesh.verts;
    params.vertCount = pmesh.nverts;
    params.polys = pmesh.polys;
    params.polyAreas = pmesh.areas;
    params.polyFlags = pmesh.flags;
    params.polyCount = pmesh.npolys;
    params.nvp = pmesh.nvp;
    params.detailMeshes = dmesh.meshes;
    params.detailVerts = dmesh.verts;
    params.detailVertsCount = dmesh.nverts;
    params.detailTris = dmesh.tris;
    params.detailTriCount = dmesh.ntris;
    params.walkableHeight = s.agent_height;
    params.walkableRadius = s.agent_radius;
    params.walkableClimb = s.agent_climb;
    params.tileX = column;
    params.tileY = row;
    params.tileLayer = 0;
    rcVcopy(params.bmin, pmesh.bmin);
    rcVcopy(params.bmax, pmesh.bmax);
    params.cs = s.cell_size;
    params.ch = s.cell_height;
    params.buildBvTree = true;
    TileData tile;
    if (!dtCreateNavMeshData(&params, &tile.data, &tile.size))
        return Error("navigation mesh: Detour could not pack tile (" + std::to_string(column) + ", " +
                         std::to_string(row) + ")",
                     Location{}, "lower tile_size_cells");
    return tile;
}

} // namespace

Result<TileData> build_tile(const InputGeometry& input, const NavSettings& s, int column, int row,
                            TileScratch& scratch) {
    const std::vector<int>& tile_tris =
        input.tile_triangles[static_cast<size_t>(row * input.grid.columns + column)];
    if (tile_tris.empty()) return TileData{};
    const rcConfig cfg = tile_config(input, s, column, row);
    rcContext ctx(false);

    RecastPtr<rcHeightfield> solid(rcAllocHeightfield());
    if (!solid || !rasterise(ctx, input, tile_tris, cfg, scratch, *solid))
        return tile_error("rasterising", column, row);
    RecastPtr<rcCompactHeightfield> chf(rcAllocCompactHeightfield());
    if (!chf || !rcBuildCompactHeightfield(&ctx, cfg.walkableHeight, cfg.walkableClimb, *solid, *chf))
        return tile_error("rcBuildCompactHeightfield", column, row);
    solid.reset();
    if (!rcErodeWalkableArea(&ctx, cfg.walkableRadius, *chf))
        return tile_error("rcErodeWalkableArea", column, row);
    mark_doors(ctx, input, *chf);
    if (!rcBuildDistanceField(&ctx, *chf)) return tile_error("rcBuildDistanceField", column, row);
    if (!rcBuildRegions(&ctx, *chf, cfg.borderSize, cfg.minRegionArea, cfg.mergeRegionArea))
        return tile_error("rcBuildRegions", column, row);
    RecastPtr<rcContourSet> contours(rcAllocContourSet());
    if (!contours || !rcBuildContours(&ctx, *chf, cfg.maxSimplificationError, cfg.maxEdgeLen, *contours))
        return tile_error("rcBuildContours", column, row);
    if (contours->nconts == 0) return TileData{};
    RecastPtr<rcPolyMesh> pmesh(rcAllocPolyMesh());
    if (!pmesh || !rcBuildPolyMesh(&ctx, *contours, cfg.maxVertsPerPoly, *pmesh))
        return tile_error("rcBuildPolyMesh", column, row);
    RecastPtr<rcPolyMeshDetail> dmesh(rcAllocPolyMeshDetail());
    if (!dmesh ||
        !rcBuildPolyMeshDetail(&ctx, *pmesh, *chf, cfg.detailSampleDist, cfg.detailSampleMaxError, *dmesh))
        return tile_error("rcBuildPolyMeshDetail", column, row);
    if (pmesh->npolys == 0) return TileData{};
    return pack_tile(*pmesh, *dmesh, s, column, row);
}

} // namespace ks::nav
