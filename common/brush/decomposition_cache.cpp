#include "brush/decomposition_cache.h"

#include "brush/convex_hull.h"
#include "brush/plane.h"

namespace ks::brush {
namespace {

constexpr const char* kKind = "hulls";

std::string write(const ConvexDecomposition& d) {
    disk_cache::Writer w;
    w.value(d.hull_volume);
    w.value(d.voxel_volume);
    w.value(d.parts);
    w.value(static_cast<std::uint64_t>(d.hulls.size()));
    for (const std::vector<DVec3>& hull : d.hulls) w.values(hull);
    return std::move(w.data());
}

// nullopt unless the payload is whole and every hull has at least 4 finite points.
std::optional<ConvexDecomposition> read(std::string_view payload) {
    disk_cache::Reader r(payload);
    ConvexDecomposition d;
    std::uint64_t count = 0;
    if (!r.value(d.hull_volume) || !r.value(d.voxel_volume) || !r.value(d.parts) || !r.value(count) ||
        count < 1 || count > static_cast<std::uint64_t>(kMaxDecompositionHulls))
        return std::nullopt;
    d.hulls.resize(static_cast<std::size_t>(count));
    for (std::vector<DVec3>& hull : d.hulls) {
        if (!r.values(hull, kMaxHullPoints) || hull.size() < 4) return std::nullopt;
        for (const DVec3& p : hull)
            if (!is_finite(p)) return std::nullopt;
    }
    if (!r.at_end()) return std::nullopt;
    return d;
}

} // namespace

std::uint64_t decomposition_cache_key(std::span<const DVec3> vertices,
                                      std::span<const std::array<std::uint32_t, 3>> triangles,
                                      const DecompositionOptions& options) {
    disk_cache::Hasher h;
    h.value(kDecompositionCacheVersion);
    h.value(options.max_hulls).value(options.resolution).value(options.tolerance).value(options.max_excess);
    h.value(vertices.size()).bytes(vertices.data(), vertices.size_bytes());
    h.value(triangles.size()).bytes(triangles.data(), triangles.size_bytes());
    return h.digest();
}

Result<ConvexDecomposition> decompose_convex_cached(std::span<const DVec3> vertices,
                                                    std::span<const std::array<std::uint32_t, 3>> triangles,
                                                    const DecompositionOptions& options,
                                                    const disk_cache::Store& store) {
    const std::uint64_t key = store.enabled() ? decomposition_cache_key(vertices, triangles, options) : 0;
    if (store.enabled())
        if (std::optional<disk_cache::Payload> payload = store.load(kKind, key))
            if (std::optional<ConvexDecomposition> hit = read(*payload)) return std::move(*hit);
    Result<ConvexDecomposition> made = decompose_convex(vertices, triangles, options);
    if (made && store.enabled()) store.save(kKind, key, write(*made));
    return made;
}

} // namespace ks::brush
