#pragma once
// The light bake through the disk cache (core/disk_cache.h): a level's atlas is baked once and read back on
// later launches. The key hashes everything bake() reads (every surface's vertices, polygons and solids and
// whether it blocks the sun, the environment, the lights, the settings) and kLightBakeVersion; the
// executable's identity is checked too, so a rebuilt game bakes afresh. A hit leaves the LightBake and the
// meshes' light-map coordinates as the bake leaves them.
#include "core/disk_cache.h"
#include "render/light_bake.h"

#include <optional>
#include <vector>

namespace ks::render {

// bake.bake(surfaces, environment, lights, settings), or its result read from `store`; bake_ms in the
// stats is the time spent (reading the cache on a hit).
BakeStats bake_cached(LightBake& bake, const std::vector<BakeSurface>& surfaces,
                      const Environment& environment, const std::vector<Light>& lights,
                      const BakeSettings& settings = {},
                      const disk_cache::Store& store = disk_cache::Store::user());

// A bake whose computing is left to later (a worker thread, render/background_bake.h): what storing its
// result needs from the time it was laid out (the cache key, the meshes' light-map coordinates).
struct LightBakeSlot {
    std::uint64_t key = 0;
    std::vector<std::vector<Vec2>> uvs; // per surface, per vertex
};
// The first half of bake_cached: on a hit the bake is restored (as bake_cached does) and nullopt comes back;
// on a miss (or with no store) the surfaces are laid out only (LightBake::layout, the atlas computed later
// with these settings) and the slot to store the computed bake in comes back.
std::optional<LightBakeSlot> restore_or_layout(LightBake& bake, const std::vector<BakeSurface>& surfaces,
                                               const Environment& environment,
                                               const std::vector<Light>& lights, const BakeSettings& settings,
                                               const disk_cache::Store& store, BakeStats& stats);
// The second half: stores a bake computed from that layout (not a cancelled one); false when not stored.
bool store_bake(const LightBake& bake, const BakeStats& stats, const LightBakeSlot& slot,
                const disk_cache::Store& store);

// The cache key of a bake's input (for tests: equal inputs give equal keys).
std::uint64_t light_bake_key(const std::vector<BakeSurface>& surfaces, const Environment& environment,
                             const std::vector<Light>& lights, const BakeSettings& settings);

} // namespace ks::render
