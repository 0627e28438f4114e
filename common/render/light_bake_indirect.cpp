// The light bake's indirect half (light_bake.h): ambient occlusion and one bounce of the direct light,
// gathered by hemisphere rays against the level's solids, on settings.threads threads over the faces.
#include "geometry/ray.h"
#include "render/light_bake.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <thread>

namespace ks::render {

namespace {
// A cosine-weighted direction of sample `s` of `n` in the frame (u, v, normal): a Hammersley point shifted
// by the texel's own offset (Cranley-Patterson rotation), so neighbouring texels' patterns differ (noise,
// not bands) yet every texel's rays depend only on the seed and its index, never on the thread order.
Vec3 hemisphere_direction(int s, int n, const Vec2& offset, const Vec3& u, const Vec3& v,
                          const Vec3& normal) {
    std::uint32_t bits = static_cast<std::uint32_t>(s);
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    float a = (static_cast<float>(s) + 0.5f) / static_cast<float>(n) + offset.x;
    float b = static_cast<float>(bits) * 2.3283064365386963e-10f + offset.y;
    a -= std::floor(a);
    b -= std::floor(b);
    const float r = std::sqrt(a), phi = 2.0f * std::numbers::pi_v<float> * b;
    return u * (r * std::cos(phi)) + v * (r * std::sin(phi)) + normal * std::sqrt(std::max(0.0f, 1.0f - a));
}

// Two uniform numbers in [0, 1) from the seed and a texel's index (a 32-bit integer hash, lowbias32).
Vec2 texel_offset(std::uint32_t seed, std::uint32_t texel) {
    auto hash = [](std::uint32_t x) {
        x ^= x >> 16u;
        x *= 0x7feb352du;
        x ^= x >> 15u;
        x *= 0x846ca68bu;
        x ^= x >> 16u;
        return x;
    };
    const std::uint32_t h1 = hash(texel * 2u + 1u + hash(seed)), h2 = hash(h1 ^ 0x9e3779b9u);
    return Vec2(static_cast<float>(h1 >> 8u), static_cast<float>(h2 >> 8u)) * (1.0f / 16777216.0f);
}
} // namespace

bool LightBake::nearest_hit(const Vec3& from, const Vec3& dir, float length,
                            const std::vector<int>& candidates, int& face, float& t) const {
    const Vec3 inv = geometry::safe_inverse(dir);
    bool hit = false;
    float best = length;
    for (int c : candidates) {
        const Occluder& o = occluders_[static_cast<size_t>(c)];
        float t_box = 0.0f;
        if (!geometry::ray_aabb(from, inv, o.lo, o.hi, best, t_box)) continue;
        // The segment clipped by each face's half-space, as hits() does, keeping the plane it enters by.
        float t0 = 0.0f, t1 = best;
        int entry = -1;
        bool inside = true;
        for (std::uint32_t i = o.first_plane; i < o.first_plane + o.plane_count && inside; ++i) {
            const Vec4& plane = planes_[i];
            const Vec3 n(plane);
            const float outside = glm::dot(n, from) - plane.w, along = glm::dot(n, dir);
            if (std::abs(along) < 1e-12f) {
                inside = outside <= 0.0f;
                continue;
            }
            const float at = -outside / along;
            if (along < 0.0f) {
                if (at > t0) {
                    t0 = at;
                    entry = static_cast<int>(i);
                }
            } else {
                t1 = std::min(t1, at);
            }
            inside = t0 <= t1;
        }
        if (!inside || t0 >= best) continue;
        best = t0;
        face = entry >= 0 ? plane_face_[static_cast<size_t>(entry)] : -1;
        hit = true;
    }
    t = best;
    return hit;
}

// One thread's scratch, reused face after face: the inner loops allocate nothing once it has grown.
struct LightBake::Gather {
    // The pass's inputs and outputs (each face writes its own texels only).
    int ao_samples = 0, bounce_samples = 0, stride = 1;
    float ao_radius = 0.0f, bounce_distance = 0.0f;
    std::uint32_t seed = 0;
    size_t lights = 0;
    const std::vector<std::uint32_t>* first = nullptr;                     // the lamps' direct light, CSR
    const std::vector<std::pair<std::uint32_t, float>>* entries = nullptr; // (light, amount)
    std::vector<Vec3>* ambient = nullptr;
    std::vector<Vec3>* bounce = nullptr;
    // Scratch.
    std::vector<int> near_ao, near_bounce;
    std::vector<Vec3> grid; // per gathering texel: the sun's bounce, then each light's
    std::vector<std::vector<ColorShare>> shares;
    long long rays = 0;
};

void LightBake::gather_face(const Face& f, Gather& g) const {
    const Vec3 n = f.normal;
    if (g.ao_samples > 0) {
        near_occluders(f, g.ao_radius, g.near_ao);
        for (int j = 0; j < f.h; ++j)
            for (int i = 0; i < f.w; ++i) {
                const auto index = static_cast<std::uint32_t>((f.y + j) * width_ + f.x + i);
                const Vec2 offset = texel_offset(g.seed, index);
                int open = 0;
                for (int s = 0; s < g.ao_samples; ++s) {
                    const Vec3 d = hemisphere_direction(s, g.ao_samples, offset, f.u_dir, f.v_dir, n);
                    if (!occluded(points_[index], d, g.ao_radius, false, &g.near_ao)) ++open;
                }
                g.rays += g.ao_samples;
                (*g.ambient)[index] *= static_cast<float>(open) / static_cast<float>(g.ao_samples);
            }
    }
    if (g.bounce_samples == 0) return;
    near_occluders(f, g.bounce_distance, g.near_bounce);
    // The gathering texels: every stride-th along each axis, and the last.
    const int gw = (f.w - 2) / g.stride + 2, gh = (f.h - 2) / g.stride + 2;
    auto grid_texel = [&](int k, int size) { return std::min(k * g.stride, size - 1); };
    const size_t slots = 1 + g.lights;
    g.grid.assign(static_cast<size_t>(gw * gh) * slots, Vec3(0.0f));
    const float weight = 1.0f / static_cast<float>(g.bounce_samples);
    for (int gj = 0; gj < gh; ++gj)
        for (int gi = 0; gi < gw; ++gi) {
            const auto index =
                static_cast<std::uint32_t>((f.y + grid_texel(gj, f.h)) * width_ + f.x + grid_texel(gi, f.w));
            Vec3* out = &g.grid[static_cast<size_t>(gj * gw + gi) * slots];
            const Vec2 offset = texel_offset(g.seed ^ 0x5bd1e995u, index);
            for (int s = 0; s < g.bounce_samples; ++s) {
                const Vec3 d = hemisphere_direction(s, g.bounce_samples, offset, f.u_dir, f.v_dir, n);
                int hit_face = -1;
                float t = 0.0f;
                if (!nearest_hit(points_[index], d, g.bounce_distance, g.near_bounce, hit_face, t) ||
                    hit_face < 0)
                    continue;
                const Face& h = faces_[static_cast<size_t>(hit_face)];
                if (glm::dot(h.normal, d) >= 0.0f) continue; // its back: inside a solid
                const Vec3 q = points_[index] + d * t - h.origin;
                const int hi = std::clamp(
                    static_cast<int>(std::lround(glm::dot(q, h.u_dir) / h.extent.x * (h.w - 1))), 0, h.w - 1);
                const int hj = std::clamp(
                    static_cast<int>(std::lround(glm::dot(q, h.v_dir) / h.extent.y * (h.h - 1))), 0, h.h - 1);
                const auto hit = static_cast<size_t>((h.y + hj) * width_ + h.x + hi);
                const Vec3 a = h.albedo * weight;
                out[0] += a * sun_[hit];
                if (!g.first->empty())
                    for (std::uint32_t e = (*g.first)[hit]; e < (*g.first)[hit + 1]; ++e)
                        out[1 + (*g.entries)[e].first] += a * (*g.entries)[e].second;
            }
            g.rays += g.bounce_samples;
        }
    // Every texel: bilinear between the four gathering texels around it.
    for (int j = 0; j < f.h; ++j)
        for (int i = 0; i < f.w; ++i) {
            const int gi = std::min(i / g.stride, gw - 2), gj = std::min(j / g.stride, gh - 2);
            const float fx = static_cast<float>(i - grid_texel(gi, f.w)) /
                             static_cast<float>(std::max(1, grid_texel(gi + 1, f.w) - grid_texel(gi, f.w)));
            const float fy = static_cast<float>(j - grid_texel(gj, f.h)) /
                             static_cast<float>(std::max(1, grid_texel(gj + 1, f.h) - grid_texel(gj, f.h)));
            const Vec3* c00 = &g.grid[static_cast<size_t>(gj * gw + gi) * slots];
            const Vec3* c10 = c00 + slots;
            const Vec3* c01 = c00 + static_cast<size_t>(gw) * slots;
            const Vec3* c11 = c01 + slots;
            const auto index = static_cast<std::uint32_t>((f.y + j) * width_ + f.x + i);
            for (size_t k = 0; k < slots; ++k) {
                const Vec3 v = glm::mix(glm::mix(c00[k], c10[k], fx), glm::mix(c01[k], c11[k], fx), fy);
                if (k == 0)
                    (*g.bounce)[index] = v;
                else if (v.x + v.y + v.z > 1e-6f)
                    g.shares[k - 1].push_back({index, v});
            }
        }
}

long long LightBake::compute_indirect(const BakeSettings& settings, BakeProgress* progress) {
    const size_t count = points_.size(), lights = shares_.size();
    const int ao_samples = std::max(0, settings.ao_samples),
              bounce_samples = std::max(0, settings.bounce_samples);
    // Each texel's direct light from the lamps, as (light, amount) lists in texel order (CSR), for the
    // bounce rays to read at the texel they hit.
    std::vector<std::uint32_t> first(bounce_samples > 0 && lights > 0 ? count + 1 : 0, 0);
    std::vector<std::pair<std::uint32_t, float>> entries;
    if (!first.empty()) {
        for (const auto& list : shares_)
            for (const Share& s : list) ++first[s.texel + 1];
        for (size_t i = 0; i < count; ++i) first[i + 1] += first[i];
        entries.resize(first[count]);
        std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
        for (size_t k = 0; k < lights; ++k)
            for (const Share& s : shares_[k])
                entries[fill[s.texel]++] = {static_cast<std::uint32_t>(k), s.amount};
    }
    std::vector<Vec3> ambient = ambient_; // the occlusion scales ambient_; the bounce reads the unscaled sun
    std::vector<Vec3> bounce(count, Vec3(0.0f));

    // Faces largest first, handed out one at a time (the last ones are small, so the threads finish
    // together).
    std::vector<int> order(faces_.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        return faces_[size_t(a)].w * faces_[size_t(a)].h > faces_[size_t(b)].w * faces_[size_t(b)].h;
    });
    long long total = 0;
    for (const Face& f : faces_) total += static_cast<long long>(f.w) * f.h;
    std::atomic<size_t> next{0};
    std::atomic<long long> done{0};

    auto work = [&](Gather& g) {
        g.shares.assign(lights, {});
        for (;;) {
            if (progress && progress->cancel.load(std::memory_order_relaxed)) return;
            const size_t item = next.fetch_add(1);
            if (item >= order.size()) return;
            const Face& f = faces_[static_cast<size_t>(order[item])];
            gather_face(f, g);
            const long long d = done.fetch_add(static_cast<long long>(f.w) * f.h) + f.w * f.h;
            if (progress && total > 0)
                progress->done.store(0.1f + 0.9f * static_cast<float>(d) / static_cast<float>(total));
        }
    };
    const bool indirect = ao_samples > 0 || bounce_samples > 0;
    const int threads = indirect ? std::max(1, settings.threads) : 0;
    std::vector<Gather> scratch(static_cast<size_t>(std::max(threads, 1)));
    for (Gather& g : scratch) {
        g.ao_samples = ao_samples;
        g.bounce_samples = bounce_samples;
        g.stride = std::max(1, settings.indirect_stride);
        g.ao_radius = std::max(0.0f, settings.ao_radius);
        g.bounce_distance = std::max(0.0f, settings.bounce_distance);
        g.seed = settings.seed;
        g.lights = lights;
        g.first = &first;
        g.entries = &entries;
        g.ambient = &ambient;
        g.bounce = &bounce;
    }
    {
        std::vector<std::jthread> pool;
        for (int t = 1; t < threads; ++t)
            pool.emplace_back([&, t] { work(scratch[static_cast<size_t>(t)]); });
        if (threads > 0) work(scratch[0]);
    }
    long long rays = 0;
    for (Gather& g : scratch) {
        rays += g.rays;
        for (size_t k = 0; k < g.shares.size(); ++k)
            bounce_shares_[k].insert(bounce_shares_[k].end(), g.shares[k].begin(), g.shares[k].end());
    }
    // Deterministic order whatever the threads' interleaving (the sums are per texel, but keep the lists
    // identical too).
    for (auto& list : bounce_shares_)
        std::sort(list.begin(), list.end(),
                  [](const ColorShare& a, const ColorShare& b) { return a.texel < b.texel; });
    base_.resize(count);
    for (size_t i = 0; i < count; ++i) base_[i] = ambient[i] + sun_[i] + bounce[i];
    ambient_ = std::move(ambient);
    return rays;
}

} // namespace ks::render
