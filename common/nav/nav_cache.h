#pragma once
// The navigation mesh through the disk cache (core/disk_cache.h): a level's mesh is built once and read back
// on later launches. The key hashes what Recast rasterises (nav_input.h: every triangle, its area, the tile
// grid and the doorways, so any change to the level's solid shapes or to how they are gathered misses), the
// settings and kNavCacheVersion; the executable's identity is checked too, so a rebuilt game builds afresh.
// A hit gives the mesh the build gives: the same tiles at the same references, the same doors.
#include "core/disk_cache.h"
#include "nav/nav_mesh.h"

#include <cstdint>

namespace ks::nav {

// Bump when the build changes what it makes from the same input (Recast's steps or parameters, the tile
// data's layout, what the cache stores).
inline constexpr std::uint32_t kNavCacheVersion = 1;

// NavMesh::build(level, settings), read from `store` when an entry for the same input is there and written
// to it when not. Errors are the build's (they are not cached).
Result<std::unique_ptr<NavMesh>> build_cached(const level::Level& level, const NavSettings& settings,
                                              const disk_cache::Store& store = disk_cache::Store::user());

// The cache key of a level's mesh with these settings (for tests: equal inputs give equal keys).
Result<std::uint64_t> nav_cache_key(const level::Level& level, const NavSettings& settings);

} // namespace ks::nav
