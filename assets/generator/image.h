#pragma once
// Texture images as float grids: a Field is one channel (heights, masks, roughness), an Image is RGBA.
// Coordinates wrap, so everything painted on them tiles seamlessly. Values are 0..1; colours in an Image
// are authored in the space the file will hold (sRGB for base colour and emissive, linear otherwise).
#include "core/result.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace ks::assetgen {

using Color = glm::vec4;

inline int wrap_index(int i, int n) {
    int r = i % n;
    return r < 0 ? r + n : r;
}

struct Field {
    int width = 0, height = 0;
    std::vector<float> values;

    Field() = default;
    Field(int w, int h, float fill = 0.0f) : width(w), height(h), values(static_cast<size_t>(w) * h, fill) {}

    float& at(int x, int y) {
        return values[static_cast<size_t>(wrap_index(y, height)) * width + wrap_index(x, width)];
    }
    float at(int x, int y) const {
        return values[static_cast<size_t>(wrap_index(y, height)) * width + wrap_index(x, width)];
    }
    // Bilinear sample at texel-space coordinates (wrapping).
    float sample(float x, float y) const;
};

struct Image {
    int width = 0, height = 0;
    std::vector<Color> pixels;

    Image() = default;
    Image(int w, int h, Color fill = Color(0, 0, 0, 1))
        : width(w), height(h), pixels(static_cast<size_t>(w) * h, fill) {}

    Color& at(int x, int y) {
        return pixels[static_cast<size_t>(wrap_index(y, height)) * width + wrap_index(x, width)];
    }
    const Color& at(int x, int y) const {
        return pixels[static_cast<size_t>(wrap_index(y, height)) * width + wrap_index(x, width)];
    }
    Color sample(float x, float y) const; // bilinear, wrapping
};

// Per-pixel colour from a ramp: t in 0..1 mapped between two colours.
Color mix(const Color& a, const Color& b, float t);
// Paints `color` over the image where `coverage` (0..1) says, keeping alpha at 1.
void blend(Image& image, const Field& coverage, const Color& color, float opacity = 1.0f);
// An image whose RGB all come from one field (a grey texture).
Image grey(const Field& field);
// Packs three fields into RGB (ORM: occlusion, roughness, metallic).
Image pack_rgb(const Field& r, const Field& g, const Field& b);

enum class PngChannels { Grey = 1, Rgb = 3, Rgba = 4 };
// Quantises to 8 bits (round to nearest) and encodes with stb_image_write, which is deterministic.
std::vector<std::uint8_t> to_bytes(const Image& image, PngChannels channels);
Result<void> write_png(const std::filesystem::path& path, const Image& image, PngChannels channels);
// A box-filtered downscale by an integer factor (for contact sheets and previews).
Image downscale(const Image& image, int factor);

} // namespace ks::assetgen
