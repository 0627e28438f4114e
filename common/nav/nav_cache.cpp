#include "nav/nav_cache.h"

#include "core/log.h"
#include "core/startup_trace.h"
#include "nav/nav_input.h"

#include <DetourAlloc.h>
#include <DetourNavMesh.h>
#include <DetourNavMeshQuery.h>

#include <cstring>

namespace ks::nav {

namespace {
constexpr const char* kKind = "navmesh";
// Sanity bounds for what a cache file may claim (a corrupt count must not allocate the world).
constexpr std::uint64_t kMaxTiles = 1 << 14, kMaxTileBytes = 64ull << 20, kMaxDoors = 1 << 16,
                        kMaxDoorPolygons = 1 << 22;

void hash_settings(disk_cache::Hasher& h, const NavSettings& s) {
    h.value(s.agent_radius).value(s.agent_height).value(s.agent_climb).value(s.agent_max_slope_degrees);
    h.value(s.cell_size).value(s.cell_height).value(s.tile_size_cells).value(s.edge_max_error_cells);
    h.value(s.edge_max_length).value(s.min_region_cells).value(s.merge_region_cells);
    h.value(s.detail_sample_distance_cells).value(s.detail_max_error_cells);
    h.value(s.query_extents.x).value(s.query_extents.y).value(s.query_extents.z);
    h.value(s.any_angle_paths).value(s.max_path_polygons).value(s.max_search_nodes);
}

std::uint64_t input_key(const InputGeometry& in, const NavSettings& settings) {
    disk_cache::Hasher h;
    h.value(kNavCacheVersion);
    hash_settings(h, settings);
    h.values(in.vertices).values(in.triangles).values(in.areas);
    h.value(in.grid.origin.x).value(in.grid.origin.y).value(in.grid.origin.z);
    h.value(in.grid.tile_world).value(in.grid.columns).value(in.grid.rows);
    h.value(in.doors.size());
    for (const DoorFootprint& d : in.doors) {
        h.value(d.entity_id).value(d.y_min).value(d.y_max).value(d.open);
        for (const Vec3& c : d.corners) h.value(c.x).value(c.y).value(c.z);
    }
    return h.digest();
}
} // namespace

std::string NavMesh::write_tiles() const {
    const NavMesh& nav = *this;
    disk_cache::Writer w;
    w.value(nav.stats_);
    const dtNavMesh& mesh = *nav.mesh_;
    w.value(*mesh.getParams());
    std::uint64_t tiles = 0;
    for (int i = 0; i < mesh.getMaxTiles(); ++i)
        if (const dtMeshTile* t = mesh.getTile(i); t->header && t->data) ++tiles;
    w.value(tiles);
    // In index order, the order the build added them (as NavMesh::clone restores them).
    for (int i = 0; i < mesh.getMaxTiles(); ++i) {
        const dtMeshTile* t = mesh.getTile(i);
        if (!t->header || !t->data) continue;
        w.value(static_cast<std::uint64_t>(mesh.getTileRef(t)));
        w.values(std::vector<unsigned char>(t->data, t->data + t->dataSize));
    }
    w.value(static_cast<std::uint64_t>(nav.doors_.size()));
    for (const Door& d : nav.doors_) {
        w.value(d.entity_id);
        w.value(d.open);
        w.values(d.polygons);
    }
    return std::move(w.data());
}

std::unique_ptr<NavMesh> NavMesh::read_tiles(std::string_view payload, const NavSettings& settings) {
    disk_cache::Reader r(payload);
    std::unique_ptr<NavMesh> nav(new NavMesh());
    nav->settings_ = settings;
    dtNavMeshParams params{};
    std::uint64_t tiles = 0;
    if (!r.value(nav->stats_) || !r.value(params) || !r.value(tiles) || tiles > kMaxTiles) return nullptr;
    nav->mesh_.reset(dtAllocNavMesh());
    nav->query_.reset(dtAllocNavMeshQuery());
    if (!nav->mesh_ || !nav->query_ || dtStatusFailed(nav->mesh_->init(&params))) return nullptr;
    std::vector<unsigned char> bytes;
    for (std::uint64_t i = 0; i < tiles; ++i) {
        std::uint64_t ref = 0;
        if (!r.value(ref) || !r.values(bytes, kMaxTileBytes) || bytes.size() < sizeof(dtMeshHeader))
            return nullptr;
        auto* data = static_cast<unsigned char*>(dtAlloc(static_cast<int>(bytes.size()), DT_ALLOC_PERM));
        if (!data) return nullptr;
        std::memcpy(data, bytes.data(), bytes.size());
        if (dtStatusFailed(nav->mesh_->addTile(data, static_cast<int>(bytes.size()), DT_TILE_FREE_DATA,
                                               static_cast<dtTileRef>(ref), nullptr))) {
            dtFree(data);
            return nullptr;
        }
    }
    std::uint64_t doors = 0;
    if (!r.value(doors) || doors > kMaxDoors) return nullptr;
    for (std::uint64_t i = 0; i < doors; ++i) {
        Door d;
        if (!r.value(d.entity_id) || !r.value(d.open) || !r.values(d.polygons, kMaxDoorPolygons))
            return nullptr;
        nav->doors_.push_back(std::move(d));
    }
    if (!r.at_end() || dtStatusFailed(nav->query_->init(nav->mesh_.get(), settings.max_search_nodes)))
        return nullptr;
    nav->corridor_.assign(static_cast<size_t>(settings.max_path_polygons), 0);
    nav->straight_points_.assign(static_cast<size_t>(settings.max_path_polygons) * 3, 0.0f);
    return nav;
}

Result<std::uint64_t> nav_cache_key(const level::Level& level, const NavSettings& settings) {
    if (auto problem = check_settings(settings)) return *problem;
    auto input = collect_input(level, settings);
    if (!input) return input.error();
    return input_key(*input, settings);
}

Result<std::unique_ptr<NavMesh>> build_cached(const level::Level& level, const NavSettings& settings,
                                              const disk_cache::Store& store) {
    if (!store.enabled()) return NavMesh::build(level, settings);
    auto key = nav_cache_key(level, settings);
    if (!key) return NavMesh::build(level, settings); // the build reports the problem
    if (auto payload = store.load(kKind, *key)) {
        if (auto nav = NavMesh::read_tiles(*payload, settings)) {
            startup::mark("navigation mesh (from the cache)");
            return nav;
        }
        log::info(store.file(kKind, *key).string(),
                  ": cache entry does not hold a navigation mesh, building it");
    }
    auto built = NavMesh::build(level, settings);
    if (built) {
        (void)store.save(kKind, *key, (*built)->write_tiles());
        startup::mark("navigation mesh (built, cached)");
    }
    return built;
}

} // namespace ks::nav
