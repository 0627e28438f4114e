#pragma once
// The building blocks of material textures: height-field features (panels, seams, bolts, tiles, planks,
// scratches), the maps derived from height (Sobel normals, cavity occlusion) and colour helpers.
#include "image.h"
#include "paint.h"

#include "core/random.h"

namespace ks::assetgen {

// Tangent-space normal map from a height field (OpenGL/glTF convention: green = +Y = toward the image top).
// `strength` converts a height difference of 1 across one pixel into slope; larger is bumpier.
Image normal_from_height(const Field& height, float strength);
// Wrapping box blur, applied twice (close to a Gaussian of the same width).
Field blur(const Field& field, int radius);
// Occlusion from the height field: how far a pixel sits below its blurred surroundings.
Field cavity_occlusion(const Field& height, int radius, float strength);

Field operator_mix(const Field& a, const Field& b, float t);
void remap(Field& f, float lo, float hi); // 0..1 → lo..hi
void add_scaled(Field& dst, const Field& src, float scale, float offset = 0.0f);
void multiply(Field& dst, const Field& src);
Field constant_like(const Field& f, float value);
Field threshold(const Field& f, float edge0, float edge1); // smoothstep

// A dome-shaped rivet/bolt head added to the height (and its footprint max-ed into `mask` if given).
void add_bolt(Field& height, Vec2f centre, float radius, float top, Field* mask = nullptr,
              bool hex_slot = false);
// Random thin strokes, bent slightly, written with Paint::Max into `mask` (values 0..1).
void add_scratches(Field& mask, Rng& rng, int count, float min_length, float max_length, float width);
// A panel grid: grooves of `seam` pixels between rectangles; returns the groove mask (1 in the groove).
Field panel_seams(int width, int height, const std::vector<float>& xs, const std::vector<float>& ys,
                  float seam);
// Diagonal stripes inside a rectangle: 1 on the dark stripes, anti-aliased.
void hazard_stripes(Field& mask, Vec2f lo, Vec2f hi, float period, float slant = 1.0f);
// Grime that gathers where `cavity` is high and toward the bottom of the texture (vertical streaks).
Field grime(int width, int height, const Field& cavity, std::uint32_t seed, float amount);

Color srgb(int r, int g, int b); // from 0..255 sRGB bytes

} // namespace ks::assetgen
