#pragma once
// Tileable noise for textures. Every function takes lattice coordinates and a period (in lattice cells)
// after which it repeats, so a texture covering exactly `period` cells wraps without a seam. Hashes are
// integer-only, so the same seed gives the same pattern everywhere.
#include "image.h"

#include <cstdint>

namespace ks::assetgen {

std::uint32_t hash_u32(std::int32_t x, std::int32_t y, std::uint32_t seed);
float hash01(std::int32_t x, std::int32_t y, std::uint32_t seed); // in [0, 1)

float value_noise(float x, float y, int period_x, int period_y, std::uint32_t seed);  // 0..1
float perlin_noise(float x, float y, int period_x, int period_y, std::uint32_t seed); // about -1..1
// Cellular noise: distance to the nearest and second-nearest feature point (one per cell), in cells.
struct WorleyDistances {
    float f1 = 0, f2 = 0;
    std::uint32_t cell_id = 0; // a hash of the nearest point's cell, for per-cell colours
};
WorleyDistances worley_noise(float x, float y, int period_x, int period_y, std::uint32_t seed);

enum class NoiseKind { Value, Perlin };
// Fractal sum of `octaves` layers, each at double the frequency and `gain` times the amplitude, normalised
// to 0..1. `period` is the number of cells across the width at the first octave (height scales with aspect).
Field fractal_noise(int width, int height, NoiseKind kind, int period, int octaves, std::uint32_t seed,
                    float gain = 0.5f);
// F1 Worley over the whole texture, normalised to 0..1 (0 at feature points).
Field cellular_noise(int width, int height, int period, std::uint32_t seed);

} // namespace ks::assetgen
