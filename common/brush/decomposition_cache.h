#pragma once
// The convex decomposition through the disk cache (core/disk_cache.h): a model's hulls are made once and read
// back on later launches, so a level with decomposed props opens as fast as one with single hulls. The key
// hashes the mesh (every vertex and triangle), the options and kDecompositionCacheVersion; the executable's
// identity is checked too, so a rebuilt game decomposes afresh. A hit gives exactly the hulls the
// decomposition gives (the points are stored bit for bit). Refusals are not cached.
#include "brush/convex_decomposition.h"
#include "core/disk_cache.h"

namespace ks::brush {

// Bump when decompose_convex makes something else from the same input, or what the cache stores changes.
inline constexpr std::uint32_t kDecompositionCacheVersion = 2;

Result<ConvexDecomposition> decompose_convex_cached(
    std::span<const DVec3> vertices, std::span<const std::array<std::uint32_t, 3>> triangles,
    const DecompositionOptions& options, const disk_cache::Store& store = disk_cache::Store::user());

// The cache key (for tests: equal inputs give equal keys).
std::uint64_t decomposition_cache_key(std::span<const DVec3> vertices,
                                      std::span<const std::array<std::uint32_t, 3>> triangles,
                                      const DecompositionOptions& options);

} // namespace ks::brush
