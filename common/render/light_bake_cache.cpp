#include "render/light_bake_cache.h"

#include "core/log.h"
#include "core/startup_trace.h"

#include <chrono>
#include <cstddef>

namespace ks::render {

namespace {
constexpr const char* kKind = "lightbake";
constexpr std::uint64_t kMaxCount = 1ull << 28; // a sanity bound on any stored vector

// Guards against a silently incomplete cache: a new field in these types changes their size, and then what
// the cache stores and hashes must be extended with it (and kLightBakeVersion bumped).
static_assert(sizeof(BakeSettings) == 48, "BakeSettings changed: hash the new field in light_bake_key");
static_assert(sizeof(BakeStats) == 64, "BakeStats changed: check what the cache stores");
static_assert(sizeof(BakedAtlas) == 2 * sizeof(int) + 5 * sizeof(std::vector<int>),
              "BakedAtlas gained a member: store it below and bump kLightBakeVersion");
static_assert(sizeof(Vertex) == 14 * sizeof(float) && offsetof(Vertex, lightmap_uv) == 12 * sizeof(float),
              "Vertex is hashed as bytes up to lightmap_uv: no padding, lightmap_uv last");
static_assert(sizeof(Environment) == 17 * sizeof(float), "Environment is hashed as bytes: no padding");

void hash_light(disk_cache::Hasher& h, const Light& l) {
    h.value(static_cast<int>(l.type)).value(l.position).value(l.direction).value(l.color);
    h.value(l.intensity).value(l.range).value(l.cos_outer).value(l.cos_inner).value(l.dynamic);
}

std::vector<std::vector<Vec2>> lightmap_uvs(const std::vector<BakeSurface>& surfaces) {
    std::vector<std::vector<Vec2>> uvs(surfaces.size());
    for (std::size_t i = 0; i < surfaces.size(); ++i)
        for (const Vertex& v : surfaces[i].mesh->vertices) uvs[i].push_back(v.lightmap_uv);
    return uvs;
}

std::string write_entry(const LightBake& bake, const std::vector<std::vector<Vec2>>& uvs,
                        const BakeStats& stats) {
    const BakedAtlas atlas = bake.atlas();
    disk_cache::Writer w;
    w.value(stats);
    w.value(atlas.width);
    w.value(atlas.height);
    w.values(atlas.base);
    w.value(static_cast<std::uint64_t>(atlas.shares.size()));
    for (const auto& s : atlas.shares) w.values(s);
    w.value(static_cast<std::uint64_t>(atlas.bounce_shares.size()));
    for (const auto& s : atlas.bounce_shares) w.values(s);
    w.values(atlas.light_color);
    w.values(atlas.light_on);
    for (const auto& uv : uvs) w.values(uv);
    return std::move(w.data());
}

// False (and `bake` and the meshes untouched) when the payload does not fit these surfaces and lights.
bool read_entry(std::string_view payload, LightBake& bake, const std::vector<BakeSurface>& surfaces,
                std::size_t light_count, BakeStats& stats) {
    disk_cache::Reader r(payload);
    BakedAtlas atlas;
    std::uint64_t lists = 0;
    if (!r.value(stats) || !r.value(atlas.width) || !r.value(atlas.height) ||
        !r.values(atlas.base, kMaxCount) || !r.value(lists) || lists != light_count)
        return false;
    atlas.shares.resize(light_count);
    for (auto& s : atlas.shares)
        if (!r.values(s, kMaxCount)) return false;
    if (!r.value(lists) || lists > light_count) return false;
    atlas.bounce_shares.resize(lists);
    for (auto& s : atlas.bounce_shares)
        if (!r.values(s, kMaxCount)) return false;
    if (!r.values(atlas.light_color, kMaxCount) || !r.values(atlas.light_on, kMaxCount)) return false;
    std::vector<std::vector<Vec2>> uvs(surfaces.size());
    for (std::size_t i = 0; i < surfaces.size(); ++i)
        if (!r.values(uvs[i], kMaxCount) || uvs[i].size() != surfaces[i].mesh->vertices.size()) return false;
    if (!r.at_end() || !bake.adopt(std::move(atlas), light_count)) return false;
    for (std::size_t i = 0; i < surfaces.size(); ++i)
        for (std::size_t v = 0; v < uvs[i].size(); ++v) surfaces[i].mesh->vertices[v].lightmap_uv = uvs[i][v];
    return true;
}
} // namespace

std::uint64_t light_bake_key(const std::vector<BakeSurface>& surfaces, const Environment& environment,
                             const std::vector<Light>& lights, const BakeSettings& settings) {
    disk_cache::Hasher h;
    h.value(kLightBakeVersion);
    h.value(settings.texel_size).value(settings.max_texels).value(settings.atlas_width);
    h.value(settings.bounce_samples).value(settings.indirect_stride).value(settings.bounce_distance);
    h.value(settings.ao_samples).value(settings.ao_radius).value(settings.seed);
    // settings.threads is left out: the result does not depend on it (test_light_bake.cpp).
    h.value(environment);
    h.value(lights.size());
    for (const Light& l : lights) hash_light(h, l);
    h.value(surfaces.size());
    for (const BakeSurface& s : surfaces) {
        h.value(s.blocks_sun);
        if (s.albedo)
            h.values(*s.albedo);
        else
            h.value(std::size_t{0});
        // Every vertex field but lightmap_uv, which bake() writes: a mesh baked before keys as a fresh one.
        h.value(s.mesh->vertices.size());
        for (const Vertex& v : s.mesh->vertices) h.bytes(&v, offsetof(Vertex, lightmap_uv));
        h.values(s.mesh->indices).values(s.mesh->polygon_sizes).values(s.mesh->solid_sizes);
    }
    return h.digest();
}

namespace {
// The cached bake restored into `bake` (and the meshes' coordinates): true; else false and `key` set.
bool restore(LightBake& bake, const std::vector<BakeSurface>& surfaces, const Environment& environment,
             const std::vector<Light>& lights, const BakeSettings& settings, const disk_cache::Store& store,
             BakeStats& stats, std::uint64_t& key) {
    const auto start = std::chrono::steady_clock::now();
    key = light_bake_key(surfaces, environment, lights, settings);
    if (auto payload = store.load(kKind, key)) {
        if (read_entry(*payload, bake, surfaces, lights.size(), stats)) {
            stats.bake_ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            startup::mark("light bake (from the cache)");
            return true;
        }
        log::info(store.file(kKind, key).string(), ": cache entry does not fit this level's bake, baking it");
    }
    return false;
}
} // namespace

BakeStats bake_cached(LightBake& bake, const std::vector<BakeSurface>& surfaces,
                      const Environment& environment, const std::vector<Light>& lights,
                      const BakeSettings& settings, const disk_cache::Store& store) {
    if (!store.enabled()) return bake.bake(surfaces, environment, lights, settings);
    BakeStats stats;
    std::uint64_t key = 0;
    if (restore(bake, surfaces, environment, lights, settings, store, stats, key)) return stats;
    stats = bake.bake(surfaces, environment, lights, settings);
    (void)store.save(kKind, key, write_entry(bake, lightmap_uvs(surfaces), stats));
    startup::mark("light bake (baked, cached)");
    return stats;
}

std::optional<LightBakeSlot> restore_or_layout(LightBake& bake, const std::vector<BakeSurface>& surfaces,
                                               const Environment& environment,
                                               const std::vector<Light>& lights, const BakeSettings& settings,
                                               const disk_cache::Store& store, BakeStats& stats) {
    LightBakeSlot slot;
    if (store.enabled() && restore(bake, surfaces, environment, lights, settings, store, stats, slot.key))
        return std::nullopt;
    stats = bake.layout(surfaces, settings);
    slot.uvs = lightmap_uvs(surfaces);
    startup::mark("light bake (laid out, not in the cache)");
    return slot;
}

bool store_bake(const LightBake& bake, const BakeStats& stats, const LightBakeSlot& slot,
                const disk_cache::Store& store) {
    if (!store.enabled() || stats.cancelled) return false;
    return store.save(kKind, slot.key, write_entry(bake, slot.uvs, stats));
}

} // namespace ks::render
