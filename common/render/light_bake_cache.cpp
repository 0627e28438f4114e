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
static_assert(sizeof(BakeSettings) == 24, "BakeSettings changed: hash the new field in light_bake_key");
static_assert(sizeof(BakeStats) == 40, "BakeStats changed: store the new field in LightBakeCacheAccess");
static_assert(sizeof(Vertex) == 14 * sizeof(float) && offsetof(Vertex, lightmap_uv) == 12 * sizeof(float),
              "Vertex is hashed as bytes up to lightmap_uv: no padding, lightmap_uv last");
static_assert(sizeof(Environment) == 17 * sizeof(float), "Environment is hashed as bytes: no padding");

void hash_light(disk_cache::Hasher& h, const Light& l) {
    h.value(static_cast<int>(l.type)).value(l.position).value(l.direction).value(l.color);
    h.value(l.intensity).value(l.range).value(l.cos_outer).value(l.cos_inner).value(l.dynamic);
}
} // namespace

// What a finished bake is made of, stored and restored (a friend of LightBake).
struct LightBakeCacheAccess {
    static_assert(sizeof(LightBake) == 2 * sizeof(int) + 7 * sizeof(std::vector<int>) + sizeof(void*),
                  "LightBake gained a member: store it in LightBakeCacheAccess and bump kLightBakeVersion");

    static std::string write(const LightBake& b, const std::vector<BakeSurface>& surfaces,
                             const BakeStats& stats) {
        disk_cache::Writer w;
        w.value(stats);
        w.value(b.width_);
        w.value(b.height_);
        w.values(b.occluders_);
        w.values(b.planes_);
        w.values(b.base_);
        w.value(static_cast<std::uint64_t>(b.shares_.size()));
        for (const auto& s : b.shares_) w.values(s);
        w.values(b.light_color_);
        w.values(b.light_on_);
        std::vector<Vec2> uv;
        for (const BakeSurface& s : surfaces) {
            uv.clear();
            for (const Vertex& v : s.mesh->vertices) uv.push_back(v.lightmap_uv);
            w.values(uv);
        }
        return std::move(w.data());
    }

    // False (and `b` and the meshes untouched) when the payload does not fit these surfaces and lights.
    static bool read(std::string_view payload, LightBake& b, const std::vector<BakeSurface>& surfaces,
                     std::size_t light_count, BakeStats& stats) {
        disk_cache::Reader r(payload);
        LightBake got;
        std::uint64_t share_lists = 0;
        if (!r.value(stats) || !r.value(got.width_) || !r.value(got.height_) ||
            !r.values(got.occluders_, kMaxCount) || !r.values(got.planes_, kMaxCount) ||
            !r.values(got.base_, kMaxCount) || !r.value(share_lists) || share_lists != light_count)
            return false;
        got.shares_.resize(light_count);
        for (auto& s : got.shares_)
            if (!r.values(s, kMaxCount)) return false;
        if (!r.values(got.light_color_, kMaxCount) || !r.values(got.light_on_, kMaxCount)) return false;
        const std::size_t texels =
            static_cast<std::size_t>(std::max(got.width_, 0)) * std::max(got.height_, 0);
        if (got.base_.size() != texels || got.light_color_.size() != light_count ||
            got.light_on_.size() != light_count)
            return false;
        for (const auto& s : got.shares_)
            for (const auto& share : s)
                if (share.texel >= texels) return false;
        std::vector<std::vector<Vec2>> uvs(surfaces.size());
        for (std::size_t i = 0; i < surfaces.size(); ++i)
            if (!r.values(uvs[i], kMaxCount) || uvs[i].size() != surfaces[i].mesh->vertices.size())
                return false;
        if (!r.at_end()) return false;
        for (std::size_t i = 0; i < surfaces.size(); ++i)
            for (std::size_t v = 0; v < uvs[i].size(); ++v)
                surfaces[i].mesh->vertices[v].lightmap_uv = uvs[i][v];
        got.dirty_ = true;
        b = std::move(got);
        return true;
    }
};

std::uint64_t light_bake_key(const std::vector<BakeSurface>& surfaces, const Environment& environment,
                             const std::vector<Light>& lights, const BakeSettings& settings) {
    disk_cache::Hasher h;
    h.value(kLightBakeVersion);
    h.value(settings.texel_size).value(settings.max_texels).value(settings.atlas_width);
    h.value(environment);
    h.value(lights.size());
    for (const Light& l : lights) hash_light(h, l);
    h.value(surfaces.size());
    for (const BakeSurface& s : surfaces) {
        h.value(s.blocks_sun);
        // Every vertex field but lightmap_uv, which bake() writes: a mesh baked before keys as a fresh one.
        h.value(s.mesh->vertices.size());
        for (const Vertex& v : s.mesh->vertices) h.bytes(&v, offsetof(Vertex, lightmap_uv));
        h.values(s.mesh->indices).values(s.mesh->polygon_sizes).values(s.mesh->solid_sizes);
    }
    return h.digest();
}

BakeStats bake_cached(LightBake& bake, const std::vector<BakeSurface>& surfaces,
                      const Environment& environment, const std::vector<Light>& lights,
                      const BakeSettings& settings, const disk_cache::Store& store) {
    if (!store.enabled()) return bake.bake(surfaces, environment, lights, settings);
    const auto start = std::chrono::steady_clock::now();
    const std::uint64_t key = light_bake_key(surfaces, environment, lights, settings);
    if (auto payload = store.load(kKind, key)) {
        BakeStats stats;
        if (LightBakeCacheAccess::read(*payload, bake, surfaces, lights.size(), stats)) {
            stats.bake_ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            startup::mark("light bake (from the cache)");
            return stats;
        }
        log::info(store.file(kKind, key).string(), ": cache entry does not fit this level's bake, baking it");
    }
    const BakeStats stats = bake.bake(surfaces, environment, lights, settings);
    (void)store.save(kKind, key, LightBakeCacheAccess::write(bake, surfaces, stats));
    startup::mark("light bake (baked, cached)");
    return stats;
}

} // namespace ks::render
