#pragma once
// The light bake through the disk cache (core/disk_cache.h): a level's atlas is baked once and read back on
// later launches. The key hashes everything bake() reads (every surface's vertices, polygons and solids and
// whether it blocks the sun, the environment, the lights, the settings) and kLightBakeVersion; the
// executable's identity is checked too, so a rebuilt game bakes afresh. A hit leaves the LightBake and the
// meshes' light-map coordinates as the bake leaves them.
#include "core/disk_cache.h"
#include "render/light_bake.h"

namespace ks::render {

// bake.bake(surfaces, environment, lights, settings), or its result read from `store`; bake_ms in the
// stats is the time spent (reading the cache on a hit).
BakeStats bake_cached(LightBake& bake, const std::vector<BakeSurface>& surfaces,
                      const Environment& environment, const std::vector<Light>& lights,
                      const BakeSettings& settings = {},
                      const disk_cache::Store& store = disk_cache::Store::user());

// The cache key of a bake's input (for tests: equal inputs give equal keys).
std::uint64_t light_bake_key(const std::vector<BakeSurface>& surfaces, const Environment& environment,
                             const std::vector<Light>& lights, const BakeSettings& settings);

} // namespace ks::render
