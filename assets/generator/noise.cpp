#include "noise.h"

#include <algorithm>
#include <cmath>

namespace ks::assetgen {

std::uint32_t hash_u32(std::int32_t x, std::int32_t y, std::uint32_t seed) {
    // A few rounds of integer mixing (from the "lowbias32" family); fast and well spread.
    std::uint32_t h = static_cast<std::uint32_t>(x) * 0x8da6b343u ^
                      static_cast<std::uint32_t>(y) * 0xd8163841u ^ seed * 0xcb1ab31fu;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return h;
}

float hash01(std::int32_t x, std::int32_t y, std::uint32_t seed) {
    return static_cast<float>(hash_u32(x, y, seed) >> 8) * (1.0f / 16777216.0f);
}

namespace {
float smooth(float t) {
    return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}

struct Lattice {
    int x0, y0, x1, y1;
    float tx, ty;
};
Lattice lattice(float x, float y, int px, int py) {
    const float fx = std::floor(x), fy = std::floor(y);
    const int ix = static_cast<int>(fx), iy = static_cast<int>(fy);
    return {wrap_index(ix, px),
            wrap_index(iy, py),
            wrap_index(ix + 1, px),
            wrap_index(iy + 1, py),
            x - fx,
            y - fy};
}

float gradient_dot(int ix, int iy, std::uint32_t seed, float dx, float dy) {
    // Eight gradient directions chosen by hash; unit length along axes, 1/sqrt2 on diagonals.
    static constexpr float kGx[8] = {1, -1, 0, 0, 0.7071068f, -0.7071068f, 0.7071068f, -0.7071068f};
    static constexpr float kGy[8] = {0, 0, 1, -1, 0.7071068f, 0.7071068f, -0.7071068f, -0.7071068f};
    const std::uint32_t g = hash_u32(ix, iy, seed) & 7u;
    return kGx[g] * dx + kGy[g] * dy;
}
} // namespace

float value_noise(float x, float y, int period_x, int period_y, std::uint32_t seed) {
    const Lattice l = lattice(x, y, period_x, period_y);
    const float sx = smooth(l.tx), sy = smooth(l.ty);
    const float a = hash01(l.x0, l.y0, seed), b = hash01(l.x1, l.y0, seed);
    const float c = hash01(l.x0, l.y1, seed), d = hash01(l.x1, l.y1, seed);
    const float top = a + (b - a) * sx, bottom = c + (d - c) * sx;
    return top + (bottom - top) * sy;
}

float perlin_noise(float x, float y, int period_x, int period_y, std::uint32_t seed) {
    const Lattice l = lattice(x, y, period_x, period_y);
    const float sx = smooth(l.tx), sy = smooth(l.ty);
    const float a = gradient_dot(l.x0, l.y0, seed, l.tx, l.ty);
    const float b = gradient_dot(l.x1, l.y0, seed, l.tx - 1.0f, l.ty);
    const float c = gradient_dot(l.x0, l.y1, seed, l.tx, l.ty - 1.0f);
    const float d = gradient_dot(l.x1, l.y1, seed, l.tx - 1.0f, l.ty - 1.0f);
    const float top = a + (b - a) * sx, bottom = c + (d - c) * sx;
    return (top + (bottom - top) * sy) * 1.41421356f;
}

WorleyDistances worley_noise(float x, float y, int period_x, int period_y, std::uint32_t seed) {
    const float fx = std::floor(x), fy = std::floor(y);
    const int ix = static_cast<int>(fx), iy = static_cast<int>(fy);
    WorleyDistances out{1e9f, 1e9f, 0};
    for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) {
            const int cx = wrap_index(ix + i, period_x), cy = wrap_index(iy + j, period_y);
            const float px = static_cast<float>(i) + hash01(cx, cy, seed) - (x - fx);
            const float py = static_cast<float>(j) + hash01(cx, cy, seed ^ 0x9e3779b9u) - (y - fy);
            const float d = std::sqrt(px * px + py * py);
            if (d < out.f1) {
                out.f2 = out.f1;
                out.f1 = d;
                out.cell_id = hash_u32(cx, cy, seed ^ 0x85ebca6bu);
            } else if (d < out.f2) {
                out.f2 = d;
            }
        }
    return out;
}

Field fractal_noise(int width, int height, NoiseKind kind, int period, int octaves, std::uint32_t seed,
                    float gain) {
    Field field(width, height);
    const int period_y = std::max(1, period * height / width);
    float amplitude_sum = 0.0f;
    for (float a = 1.0f, o = 0; o < static_cast<float>(octaves); ++o, a *= gain) amplitude_sum += a;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            float sum = 0.0f, amplitude = 1.0f;
            int px = period, py = period_y;
            for (int o = 0; o < octaves; ++o) {
                const float u =
                    (static_cast<float>(x) + 0.5f) * static_cast<float>(px) / static_cast<float>(width);
                const float v =
                    (static_cast<float>(y) + 0.5f) * static_cast<float>(py) / static_cast<float>(height);
                const std::uint32_t s = seed + static_cast<std::uint32_t>(o) * 1013u;
                const float n = kind == NoiseKind::Value ? value_noise(u, v, px, py, s)
                                                         : perlin_noise(u, v, px, py, s) * 0.5f + 0.5f;
                sum += n * amplitude;
                amplitude *= gain;
                px *= 2;
                py *= 2;
            }
            field.at(x, y) = std::clamp(sum / amplitude_sum, 0.0f, 1.0f);
        }
    return field;
}

Field cellular_noise(int width, int height, int period, std::uint32_t seed) {
    Field field(width, height);
    const int period_y = std::max(1, period * height / width);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float u =
                (static_cast<float>(x) + 0.5f) * static_cast<float>(period) / static_cast<float>(width);
            const float v =
                (static_cast<float>(y) + 0.5f) * static_cast<float>(period_y) / static_cast<float>(height);
            field.at(x, y) = std::clamp(worley_noise(u, v, period, period_y, seed).f1, 0.0f, 1.0f);
        }
    return field;
}

} // namespace ks::assetgen
