#include "nav/nav_mesh.h"

#include "nav/nav_flags.h"
#include "nav/nav_input.h"
#include "nav/nav_tile_builder.h"

#include <DetourAlloc.h>
#include <DetourNavMesh.h>
#include <DetourNavMeshQuery.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <type_traits>

namespace ks::nav {
namespace {

static_assert(std::is_same_v<dtPolyRef, std::uint32_t>, "nav keeps 32-bit polygon references");

// Detour splits a 32-bit polygon reference into salt (at least 10 bits), tile and polygon bits.
constexpr int kRefBitsForTileAndPoly = 22;
constexpr int kMaxTileBits = 14;

Vec3 poly_centre(const dtMeshTile& tile, const dtPoly& poly) {
    Vec3 c(0.0f);
    for (int i = 0; i < poly.vertCount; ++i) {
        const float* v = &tile.verts[poly.verts[i] * 3];
        c += Vec3(v[0], v[1], v[2]);
    }
    return c / static_cast<float>(std::max<int>(poly.vertCount, 1));
}

Vec3 detail_vertex(const dtMeshTile& tile, const dtPoly& poly, const dtPolyDetail& detail,
                   unsigned char index) {
    const float* v = index < poly.vertCount
                         ? &tile.verts[poly.verts[index] * 3]
                         : &tile.detailVerts[(detail.vertBase + index - poly.vertCount) * 3];
    return {v[0], v[1], v[2]};
}

} // namespace

const char* status_name(PathStatus status) {
    switch (status) {
    case PathStatus::Found:
        return "found";
    case PathStatus::Partial:
        return "partial";
    case PathStatus::StartOffMesh:
        return "start off mesh";
    case PathStatus::EndOffMesh:
        return "end off mesh";
    }
    return "?";
}

NavMesh::NavMesh()
    : mesh_(nullptr, dtFreeNavMesh), query_(nullptr, dtFreeNavMeshQuery),
      filter_(std::make_unique<dtQueryFilter>()) {
    filter_->setIncludeFlags(kFlagWalk);
    filter_->setExcludeFlags(0);
}

NavMesh::~NavMesh() = default;

Result<std::unique_ptr<NavMesh>> NavMesh::build(const level::Level& level, const NavSettings& settings) {
    if (auto problem = check_settings(settings)) return *problem;
    auto input = collect_input(level, settings);
    if (!input) return input.error();
    return build_tiles(*input, level.name, settings, nullptr, nullptr, nullptr);
}

Result<std::unique_ptr<NavMesh>> NavMesh::rebuild(const NavMesh& previous, const level::Level& before,
                                                  const level::Level& edited, int* built_tiles) {
    const NavSettings& settings = previous.settings_;
    auto input = collect_input(edited, settings);
    if (!input) return input.error();
    auto previous_input = collect_input(before, settings);
    return build_tiles(*input, edited.name, settings, previous_input ? &previous : nullptr,
                       previous_input ? &*previous_input : nullptr, built_tiles);
}

namespace {
// A copy of a tile's data, for dtNavMesh::addTile with DT_TILE_FREE_DATA; empty when there is no tile (its
// input held nothing walkable). Detour makes the links anew when the copy is added.
Result<TileData> copy_tile(const dtMeshTile* tile) {
    if (!tile || !tile->header || !tile->data) return TileData{};
    auto* data = static_cast<unsigned char*>(dtAlloc(tile->dataSize, DT_ALLOC_PERM));
    if (!data) return Error("navigation mesh: out of memory copying a tile");
    std::memcpy(data, tile->data, static_cast<std::size_t>(tile->dataSize));
    return TileData{data, tile->dataSize};
}

// A copied tile's polygons get the flags the build gives them (its doors were opened and closed since).
void reset_flags(dtNavMesh& mesh, int column, int row) {
    const dtMeshTile* tile = mesh.getTileAt(column, row, 0);
    if (!tile || !tile->header) return;
    const dtPolyRef base = mesh.getPolyRefBase(tile);
    for (int p = 0; p < tile->header->polyCount; ++p) {
        const bool door = tile->polys[p].getArea() == kAreaDoor;
        (void)mesh.setPolyFlags(base | static_cast<dtPolyRef>(p), door ? (kFlagWalk | kFlagDoor) : kFlagWalk);
    }
}
} // namespace

Result<std::unique_ptr<NavMesh>> NavMesh::build_tiles(const InputGeometry& input, const std::string& name,
                                                      const NavSettings& settings, const NavMesh* previous,
                                                      const InputGeometry* previous_input, int* built_tiles) {
    const TileGrid& grid = input.grid;
    const int tile_count = grid.columns * grid.rows;
    const int tile_bits =
        std::max(1, static_cast<int>(std::bit_width(std::bit_ceil(static_cast<unsigned>(tile_count)))) - 1);
    if (tile_bits > kMaxTileBits)
        return Error("level '" + name + "' needs " + std::to_string(tile_count) +
                         " navigation tiles, more than Detour can address",
                     Location{}, "raise cell_size or tile_size_cells");

    std::unique_ptr<NavMesh> nav(new NavMesh());
    nav->settings_ = settings;
    nav->mesh_.reset(dtAllocNavMesh());
    nav->query_.reset(dtAllocNavMeshQuery());
    if (!nav->mesh_ || !nav->query_) return Error("navigation mesh: out of memory allocating Detour objects");
    dtNavMeshParams params{};
    params.orig[0] = grid.origin.x;
    params.orig[1] = grid.origin.y;
    params.orig[2] = grid.origin.z;
    params.tileWidth = grid.tile_world;
    params.tileHeight = grid.tile_world;
    params.maxTiles = 1 << tile_bits;
    params.maxPolys = 1 << (kRefBitsForTileAndPoly - tile_bits);
    if (dtStatusFailed(nav->mesh_->init(&params)))
        return Error("navigation mesh: Detour could not initialise the mesh");

    TileScratch scratch;
    int built = 0;
    for (int row = 0; row < grid.rows; ++row)
        for (int column = 0; column < grid.columns; ++column) {
            // Tiles are added in the same order either way, so they get the references a build gives.
            const bool copy =
                previous && previous_input && same_tile_input(*previous_input, input, column, row, settings);
            auto tile = copy ? copy_tile(previous->mesh_->getTileAt(column, row, 0))
                             : build_tile(input, settings, column, row, scratch);
            if (!tile) return tile.error();
            built += copy ? 0 : 1;
            if (!tile->data) continue;
            if (dtStatusFailed(nav->mesh_->addTile(tile->data, tile->size, DT_TILE_FREE_DATA, 0, nullptr))) {
                dtFree(tile->data);
                return Error("navigation mesh: Detour refused tile (" + std::to_string(column) + ", " +
                                 std::to_string(row) + ")",
                             Location{},
                             "raise cell_size: a tile has more polygons than the references address");
            }
            if (copy) reset_flags(*nav->mesh_, column, row);
            ++nav->stats_.tiles_with_polygons;
        }
    if (built_tiles) *built_tiles = built;

    const dtNavMesh& mesh = *nav->mesh_;
    for (int i = 0; i < mesh.getMaxTiles(); ++i)
        if (const dtMeshTile* t = mesh.getTile(i); t->header) nav->stats_.polygons += t->header->polyCount;
    if (nav->stats_.polygons == 0)
        return Error("level '" + name + "' has no walkable floor for a robot (radius " +
                         std::to_string(settings.agent_radius) + ", height " +
                         std::to_string(settings.agent_height) + ")",
                     Location{},
                     "add a floor entity, at least twice the robot radius wide, with headroom above it");
    nav->stats_.tile_columns = grid.columns;
    nav->stats_.tile_rows = grid.rows;
    nav->stats_.input_triangles = static_cast<int>(input.triangles.size() / 3);
    if (dtStatusFailed(nav->query_->init(nav->mesh_.get(), settings.max_search_nodes)))
        return Error("navigation mesh: Detour could not set up its query (node pool)");
    nav->corridor_.assign(static_cast<size_t>(settings.max_path_polygons), 0);
    nav->straight_points_.assign(static_cast<size_t>(settings.max_path_polygons) * 3, 0.0f);
    nav->index_door_polygons(input.doors);
    return nav;
}

Result<std::unique_ptr<NavMesh>> NavMesh::clone() const {
    std::unique_ptr<NavMesh> copy(new NavMesh());
    copy->settings_ = settings_;
    copy->stats_ = stats_;
    copy->doors_ = doors_;
    copy->islands_ = islands_;
    copy->mesh_.reset(dtAllocNavMesh());
    copy->query_.reset(dtAllocNavMeshQuery());
    if (!copy->mesh_ || !copy->query_)
        return Error("navigation mesh: out of memory allocating Detour objects");
    const dtNavMesh& source = *mesh_;
    if (dtStatusFailed(copy->mesh_->init(source.getParams())))
        return Error("navigation mesh: Detour could not initialise the copy");
    // In index order, which is the order the build added them (Detour hands out free tiles from index 0), so
    // the links between tiles are made in the same order too.
    for (int i = 0; i < source.getMaxTiles(); ++i) {
        const dtMeshTile* tile = source.getTile(i);
        auto data = copy_tile(tile);
        if (!data) return data.error();
        if (!data->data) continue;
        if (dtStatusFailed(copy->mesh_->addTile(data->data, data->size, DT_TILE_FREE_DATA,
                                                source.getTileRef(tile), nullptr))) {
            dtFree(data->data);
            return Error("navigation mesh: Detour refused a copied tile");
        }
    }
    if (dtStatusFailed(copy->query_->init(copy->mesh_.get(), settings_.max_search_nodes)))
        return Error("navigation mesh: Detour could not set up its query (node pool)");
    copy->corridor_.assign(corridor_.size(), 0);
    copy->straight_points_.assign(straight_points_.size(), 0.0f);
    return copy;
}

namespace {
// Calls visit(tile, polygon index, reference) for every polygon of every built tile.
template <class Visit>
void each_polygon(const dtNavMesh& mesh, Visit&& visit) {
    for (int i = 0; i < mesh.getMaxTiles(); ++i) {
        const dtMeshTile* tile = mesh.getTile(i);
        if (!tile->header) continue;
        const dtPolyRef base = mesh.getPolyRefBase(tile);
        for (int p = 0; p < tile->header->polyCount; ++p) visit(*tile, p, base | static_cast<dtPolyRef>(p));
    }
}
} // namespace

void NavMesh::index_door_polygons(const std::vector<DoorFootprint>& footprints) {
    for (const DoorFootprint& f : footprints) doors_.push_back({f.entity_id, f.open, {}});
    each_polygon(*mesh_, [&](const dtMeshTile& tile, int p, dtPolyRef ref) {
        const dtPoly& poly = tile.polys[p];
        if (poly.getArea() != kAreaDoor) return;
        const Vec3 centre = poly_centre(tile, poly);
        for (size_t d = 0; d < footprints.size(); ++d)
            if (footprints[d].contains(centre, settings_.cell_size)) {
                doors_[d].polygons.push_back(ref);
                ++stats_.door_polygons;
                break;
            }
    });
    for (const Door& door : doors_)
        if (!door.open) (void)set_door_open(door.entity_id, false);
}

int NavMesh::find_door(int entity_id) const {
    for (size_t i = 0; i < doors_.size(); ++i)
        if (doors_[i].entity_id == entity_id) return static_cast<int>(i);
    return -1;
}

bool NavMesh::set_door_open(int door_entity_id, bool open) {
    const int index = find_door(door_entity_id);
    if (index < 0 || doors_[static_cast<size_t>(index)].polygons.empty()) return false;
    Door* door = &doors_[static_cast<size_t>(index)];
    door->open = open;
    islands_.clear();
    const std::uint16_t flags = open ? (kFlagWalk | kFlagDoor) : kFlagDoor;
    bool all_set = true;
    for (std::uint64_t ref : door->polygons)
        all_set = !dtStatusFailed(mesh_->setPolyFlags(static_cast<dtPolyRef>(ref), flags)) && all_set;
    return all_set;
}

void NavMesh::number_islands() {
    islands_.clear();
    int count = 0;
    std::vector<dtPolyRef> frontier;
    auto walkable = [](const dtPoly& poly) {
        return (poly.flags & kFlagWalk) != 0 && poly.getType() != DT_POLYTYPE_OFFMESH_CONNECTION;
    };
    each_polygon(*mesh_, [&](const dtMeshTile& tile, int p, dtPolyRef seed) {
        if (!walkable(tile.polys[p]) || islands_.contains(seed)) return;
        islands_.emplace(seed, ++count);
        frontier.assign(1, seed);
        while (!frontier.empty()) {
            const dtPolyRef ref = frontier.back();
            frontier.pop_back();
            const dtMeshTile* at = nullptr;
            const dtPoly* poly = nullptr;
            mesh_->getTileAndPolyByRefUnsafe(ref, &at, &poly);
            for (unsigned int k = poly->firstLink; k != DT_NULL_LINK; k = at->links[k].next) {
                const dtPolyRef next = at->links[k].ref;
                const dtMeshTile* next_tile = nullptr;
                const dtPoly* next_poly = nullptr;
                if (next == 0 || islands_.contains(next)) continue;
                mesh_->getTileAndPolyByRefUnsafe(next, &next_tile, &next_poly);
                if (!walkable(*next_poly)) continue;
                islands_.emplace(next, count);
                frontier.push_back(next);
            }
        }
    });
}

int NavMesh::island(const Vec3& p, const Vec3& half_extents) {
    if (islands_.empty()) number_islands();
    Vec3 on_mesh(0.0f);
    const std::uint64_t ref = nearest_polygon(p, half_extents, on_mesh);
    if (ref == 0) return 0;
    auto it = islands_.find(ref);
    return it == islands_.end() ? 0 : it->second;
}

bool NavMesh::door_open(int door_entity_id) const {
    const int index = find_door(door_entity_id);
    return index >= 0 && doors_[static_cast<size_t>(index)].open;
}

std::vector<NavTriangle> NavMesh::triangles() const {
    std::vector<NavTriangle> out;
    each_polygon(*mesh_, [&](const dtMeshTile& tile, int p, dtPolyRef ref) {
        const dtPoly& poly = tile.polys[p];
        if (poly.getType() == DT_POLYTYPE_OFFMESH_CONNECTION) return;
        int door_id = 0;
        for (const Door& d : doors_)
            if (std::find(d.polygons.begin(), d.polygons.end(), ref) != d.polygons.end())
                door_id = d.entity_id;
        const dtPolyDetail& detail = tile.detailMeshes[p];
        for (int t = 0; t < detail.triCount; ++t) {
            const unsigned char* tri = &tile.detailTris[(detail.triBase + t) * 4];
            out.push_back({detail_vertex(tile, poly, detail, tri[0]),
                           detail_vertex(tile, poly, detail, tri[1]),
                           detail_vertex(tile, poly, detail, tri[2]), poly.flags, door_id});
        }
    });
    return out;
}

} // namespace ks::nav
