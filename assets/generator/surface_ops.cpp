#include "surface_ops.h"

#include "noise.h"

#include <algorithm>
#include <cmath>

namespace ks::assetgen {

Image normal_from_height(const Field& h, float strength) {
    Image out(h.width, h.height);
    for (int y = 0; y < h.height; ++y)
        for (int x = 0; x < h.width; ++x) {
            // Sobel: dx toward +x (right), dy toward +row (down the image).
            const float dx = (h.at(x + 1, y - 1) + 2.0f * h.at(x + 1, y) + h.at(x + 1, y + 1)) -
                             (h.at(x - 1, y - 1) + 2.0f * h.at(x - 1, y) + h.at(x - 1, y + 1));
            const float dy = (h.at(x - 1, y + 1) + 2.0f * h.at(x, y + 1) + h.at(x + 1, y + 1)) -
                             (h.at(x - 1, y - 1) + 2.0f * h.at(x, y - 1) + h.at(x + 1, y - 1));
            // Image "up" is -row, so the slope toward +Y is -dy; the normal leans against the slope.
            const glm::vec3 n = glm::normalize(glm::vec3(-dx * strength / 8.0f, dy * strength / 8.0f, 1.0f));
            out.at(x, y) = Color(n.x * 0.5f + 0.5f, n.y * 0.5f + 0.5f, n.z * 0.5f + 0.5f, 1.0f);
        }
    return out;
}

namespace {
Field box_blur_pass(const Field& in, int radius, bool horizontal) {
    Field out(in.width, in.height);
    const float norm = 1.0f / static_cast<float>(2 * radius + 1);
    const int n = horizontal ? in.width : in.height, lines = horizontal ? in.height : in.width;
    for (int line = 0; line < lines; ++line) {
        auto get = [&](int i) { return horizontal ? in.at(i, line) : in.at(line, i); };
        // Running sum in double so the result does not depend on the summation order's rounding drift.
        double sum = 0.0;
        for (int i = -radius; i <= radius; ++i) sum += get(i);
        for (int i = 0; i < n; ++i) {
            (horizontal ? out.at(i, line) : out.at(line, i)) = static_cast<float>(sum) * norm;
            sum += get(i + radius + 1) - get(i - radius);
        }
    }
    return out;
}
} // namespace

Field blur(const Field& field, int radius) {
    if (radius <= 0) return field;
    Field f = field;
    for (int pass = 0; pass < 2; ++pass) f = box_blur_pass(box_blur_pass(f, radius, true), radius, false);
    return f;
}

Field cavity_occlusion(const Field& height, int radius, float strength) {
    Field blurred = blur(height, radius);
    Field ao(height.width, height.height);
    for (size_t i = 0; i < ao.values.size(); ++i)
        ao.values[i] =
            std::clamp(1.0f - std::max(0.0f, blurred.values[i] - height.values[i]) * strength, 0.0f, 1.0f);
    return ao;
}

Field operator_mix(const Field& a, const Field& b, float t) {
    Field out = a;
    for (size_t i = 0; i < out.values.size(); ++i) out.values[i] += (b.values[i] - a.values[i]) * t;
    return out;
}

void remap(Field& f, float lo, float hi) {
    for (float& v : f.values) v = lo + (hi - lo) * v;
}

void add_scaled(Field& dst, const Field& src, float scale, float offset) {
    for (size_t i = 0; i < dst.values.size(); ++i) dst.values[i] += src.values[i] * scale + offset;
}

void multiply(Field& dst, const Field& src) {
    for (size_t i = 0; i < dst.values.size(); ++i) dst.values[i] *= src.values[i];
}

Field constant_like(const Field& f, float value) {
    return Field(f.width, f.height, value);
}

Field threshold(const Field& f, float edge0, float edge1) {
    Field out = f;
    for (float& v : out.values) {
        const float t = std::clamp((v - edge0) / (edge1 - edge0), 0.0f, 1.0f);
        v = t * t * (3.0f - 2.0f * t);
    }
    return out;
}

void add_bolt(Field& height, Vec2f c, float r, float top, Field* mask, bool hex_slot) {
    const int x0 = static_cast<int>(std::floor(c.x - r)) - 1, x1 = static_cast<int>(std::ceil(c.x + r)) + 1;
    const int y0 = static_cast<int>(std::floor(c.y - r)) - 1, y1 = static_cast<int>(std::ceil(c.y + r)) + 1;
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const Vec2f d = Vec2f(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f) - c;
            const float t = glm::length(d) / r;
            if (t >= 1.0f) continue;
            float dome = top * std::sqrt(1.0f - t * t);
            if (hex_slot) {
                // A hexagonal socket pressed into the head.
                const Vec2f a = glm::abs(d) / (r * 0.45f);
                if (std::max(a.x * 0.866f + a.y * 0.5f, a.y) < 1.0f) dome -= top * 0.5f;
            }
            const float edge = std::clamp((1.0f - t) * r, 0.0f, 1.0f); // anti-aliased rim
            float& h = height.at(x, y);
            h = std::max(h, h + (dome * edge));
            if (mask) mask->at(x, y) = std::max(mask->at(x, y), edge);
        }
}

void add_scratches(Field& mask, Rng& rng, int count, float min_length, float max_length, float width) {
    const auto w = static_cast<float>(mask.width), h = static_cast<float>(mask.height);
    for (int i = 0; i < count; ++i) {
        Vec2f p(rng.uniform(0.0f, w), rng.uniform(0.0f, h));
        const float length = rng.uniform(min_length, max_length);
        float angle = rng.uniform(0.0f, 6.2831853f);
        const float bend = rng.uniform(-0.4f, 0.4f) / std::max(1.0f, length / 10.0f);
        const float strength = rng.uniform(0.35f, 1.0f);
        const int steps = std::max(1, static_cast<int>(length / 6.0f));
        for (int s = 0; s < steps; ++s) {
            const Vec2f q =
                p + Vec2f(std::cos(angle), std::sin(angle)) * (length / static_cast<float>(steps));
            // Scratches taper toward both ends.
            const float taper =
                std::sin(3.14159265f * (static_cast<float>(s) + 0.5f) / static_cast<float>(steps));
            draw_line(mask, p, q, width * (0.4f + 0.6f * taper), Stroke{strength * taper, Paint::Max});
            p = q;
            angle += bend;
        }
    }
}

Field panel_seams(int width, int height, const std::vector<float>& xs, const std::vector<float>& ys,
                  float seam) {
    Field mask(width, height);
    for (float x : xs)
        paint_sdf(
            mask, Vec2f(x - seam, 0), Vec2f(x + seam, static_cast<float>(height)),
            [&](Vec2f p) { return std::abs(p.x - x) - seam * 0.5f; }, Stroke{});
    for (float y : ys)
        paint_sdf(
            mask, Vec2f(0, y - seam), Vec2f(static_cast<float>(width), y + seam),
            [&](Vec2f p) { return std::abs(p.y - y) - seam * 0.5f; }, Stroke{});
    return mask;
}

void hazard_stripes(Field& mask, Vec2f lo, Vec2f hi, float period, float slant) {
    paint_sdf(
        mask, lo, hi,
        [&](Vec2f p) {
            const float box = sdf_rounded_rect(p, lo, hi, 0.0f);
            const float s = p.x + p.y * slant;
            const float m = s - period * std::floor(s / period);                // 0..period
            const float stripe = std::abs(m - period * 0.25f) - period * 0.25f; // dark half of each period
            return std::max(box, stripe / std::sqrt(1.0f + slant * slant));
        },
        Stroke{});
}

Field grime(int width, int height, const Field& cavity, std::uint32_t seed, float amount) {
    Field blotches = fractal_noise(width, height, NoiseKind::Perlin, 4, 5, seed);
    Field streaks(width, height);
    // Vertical streaks: noise stretched along y.
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float u = (static_cast<float>(x) + 0.5f) * 48.0f / static_cast<float>(width);
            const float v = (static_cast<float>(y) + 0.5f) * 2.0f / static_cast<float>(height);
            streaks.at(x, y) = value_noise(u, v, 48, 2, seed ^ 0x51u);
        }
    Field g(width, height);
    for (size_t i = 0; i < g.values.size(); ++i) {
        const float b = std::clamp((blotches.values[i] - 0.45f) * 2.5f, 0.0f, 1.0f);
        const float s = std::clamp((streaks.values[i] - 0.55f) * 2.0f, 0.0f, 1.0f) * 0.5f;
        const float c = 1.0f - cavity.values[i];
        g.values[i] = std::clamp((b * 0.6f + s + c * 2.0f) * amount, 0.0f, 1.0f);
    }
    return g;
}

Color srgb(int r, int g, int b) {
    return Color(static_cast<float>(r) / 255.0f, static_cast<float>(g) / 255.0f,
                 static_cast<float>(b) / 255.0f, 1.0f);
}

} // namespace ks::assetgen
