#include "image.h"

#include "core/files.h"

#include <algorithm>
#include <cmath>
#include <stb_image_write.h>

namespace ks::assetgen {

float Field::sample(float x, float y) const {
    const float fx = std::floor(x), fy = std::floor(y);
    const int x0 = static_cast<int>(fx), y0 = static_cast<int>(fy);
    const float tx = x - fx, ty = y - fy;
    const float top = at(x0, y0) + (at(x0 + 1, y0) - at(x0, y0)) * tx;
    const float bottom = at(x0, y0 + 1) + (at(x0 + 1, y0 + 1) - at(x0, y0 + 1)) * tx;
    return top + (bottom - top) * ty;
}

Color Image::sample(float x, float y) const {
    const float fx = std::floor(x), fy = std::floor(y);
    const int x0 = static_cast<int>(fx), y0 = static_cast<int>(fy);
    const float tx = x - fx, ty = y - fy;
    const Color top = mix(at(x0, y0), at(x0 + 1, y0), tx);
    const Color bottom = mix(at(x0, y0 + 1), at(x0 + 1, y0 + 1), tx);
    return mix(top, bottom, ty);
}

Color mix(const Color& a, const Color& b, float t) {
    return a + (b - a) * t;
}

void blend(Image& image, const Field& coverage, const Color& color, float opacity) {
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        const float a = std::clamp(coverage.values[i] * opacity * color.a, 0.0f, 1.0f);
        Color& p = image.pixels[i];
        p = Color(glm::vec3(p) + (glm::vec3(color) - glm::vec3(p)) * a, p.a);
    }
}

Image grey(const Field& field) {
    Image image(field.width, field.height);
    for (size_t i = 0; i < field.values.size(); ++i) {
        const float v = field.values[i];
        image.pixels[i] = Color(v, v, v, 1.0f);
    }
    return image;
}

Image pack_rgb(const Field& r, const Field& g, const Field& b) {
    Image image(r.width, r.height);
    for (size_t i = 0; i < r.values.size(); ++i)
        image.pixels[i] = Color(r.values[i], g.values[i], b.values[i], 1.0f);
    return image;
}

namespace {
std::uint8_t quantise(float v) {
    if (!(v >= 0.0f)) return 0; // also maps NaN to 0 rather than to undefined behaviour
    if (v >= 1.0f) return 255;
    return static_cast<std::uint8_t>(v * 255.0f + 0.5f);
}

void append_bytes(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(context);
    auto* bytes = static_cast<std::uint8_t*>(data);
    out->insert(out->end(), bytes, bytes + size);
}
} // namespace

std::vector<std::uint8_t> to_bytes(const Image& image, PngChannels channels) {
    const int n = static_cast<int>(channels);
    std::vector<std::uint8_t> bytes(image.pixels.size() * static_cast<size_t>(n));
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        const Color& p = image.pixels[i];
        std::uint8_t* out = &bytes[i * static_cast<size_t>(n)];
        if (n == 1) {
            out[0] = quantise(p.r);
        } else {
            for (int c = 0; c < n; ++c) out[c] = quantise(p[c]);
        }
    }
    return bytes;
}

Result<void> write_png(const std::filesystem::path& path, const Image& image, PngChannels channels) {
    const std::vector<std::uint8_t> bytes = to_bytes(image, channels);
    const int n = static_cast<int>(channels);
    std::vector<std::uint8_t> encoded;
    // Level 9 keeps the committed files small; stb's encoder has no timestamps or other varying state.
    stbi_write_png_compression_level = 9;
    if (!stbi_write_png_to_func(append_bytes, &encoded, image.width, image.height, n, bytes.data(),
                                image.width * n))
        return Error("PNG encoding failed", Location{path.string()}, "the image must be non-empty");
    return files::write_atomic(
        path, std::string_view(reinterpret_cast<const char*>(encoded.data()), encoded.size()));
}

Image downscale(const Image& image, int factor) {
    if (factor <= 1) return image;
    Image out(image.width / factor, image.height / factor);
    const float norm = 1.0f / static_cast<float>(factor * factor);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            Color sum(0.0f);
            for (int j = 0; j < factor; ++j)
                for (int i = 0; i < factor; ++i) sum += image.at(x * factor + i, y * factor + j);
            out.at(x, y) = sum * norm;
        }
    return out;
}

} // namespace ks::assetgen
