// Level surface materials for floors and ceilings. Floors repeat every 2 world units by default.
#include "catalog.h"
#include "material_builder.h"
#include "noise.h"

#include <algorithm>
#include <cmath>

namespace ks::assetgen {
namespace {
constexpr int kFloorSize = 512;
}

Result<void> make_surface_tiles(Output& out) {
    MaterialFields m = blank_material(kFloorSize, srgb(180, 180, 176), 0.4f, 0.0f);
    m.keep_height = true;
    constexpr int kTiles = 4; // 0.5-unit tiles on a 2-unit repeat
    const float tile = static_cast<float>(kFloorSize) / kTiles, grout = 5.0f;
    const Field speckle = fractal_noise(kFloorSize, kFloorSize, NoiseKind::Value, 128, 2, 31);
    const Field cloud = fractal_noise(kFloorSize, kFloorSize, NoiseKind::Perlin, 8, 4, 32);
    Field face(kFloorSize, kFloorSize);
    for (int ty = 0; ty < kTiles; ++ty)
        for (int tx = 0; tx < kTiles; ++tx) {
            const Vec2f lo(static_cast<float>(tx) * tile + grout, static_cast<float>(ty) * tile + grout);
            fill_rounded_rect(face, lo, lo + Vec2f(tile - 2 * grout), 4.0f, Stroke{1.0f, Paint::Max, 3.0f});
        }
    Rng rng(0x711E5u);
    Field chips(kFloorSize, kFloorSize), scuffs(kFloorSize, kFloorSize);
    for (int i = 0; i < 10; ++i) {
        // Chipped tile corners.
        const Vec2f c(std::floor(rng.uniform(0, kTiles)) * tile + (rng.chance(0.5f) ? grout : tile - grout),
                      std::floor(rng.uniform(0, kTiles)) * tile + (rng.chance(0.5f) ? grout : tile - grout));
        fill_circle(chips, c, rng.uniform(3.0f, 7.0f), Stroke{1.0f, Paint::Max, 1.0f});
    }
    add_scratches(scuffs, rng, 60, 10.0f, 60.0f, 1.5f);
    const Field dirt = grime(kFloorSize, kFloorSize, cavity_occlusion(face, 4, 1.0f), 33, 0.5f);
    for (int y = 0; y < kFloorSize; ++y)
        for (int x = 0; x < kFloorSize; ++x) {
            const int tx = static_cast<int>(static_cast<float>(x) / tile),
                      ty = static_cast<int>(static_cast<float>(y) / tile);
            const float tint = hash01(tx, ty, 34);
            const float f = face.at(x, y) * (1.0f - chips.at(x, y));
            Color tile_color =
                mix(srgb(196, 196, 190), srgb(160, 162, 160), tint * 0.6f + cloud.at(x, y) * 0.4f);
            tile_color = mix(tile_color, srgb(120, 120, 116), speckle.at(x, y) > 0.8f ? 0.5f : 0.0f);
            const Color grout_color = mix(srgb(92, 88, 82), srgb(70, 66, 60), dirt.at(x, y));
            Color c = mix(grout_color, tile_color, f);
            c = mix(c, srgb(120, 116, 108), scuffs.at(x, y) * 0.25f * f);
            m.color.at(x, y) = c;
            m.height.at(x, y) = 0.4f + f * 0.2f + speckle.at(x, y) * 0.01f;
            m.roughness.at(x, y) = f > 0.5f ? 0.28f + cloud.at(x, y) * 0.15f + scuffs.at(x, y) * 0.3f : 0.9f;
        }
    m.normal_strength = 4.0f;
    return out.material("tiles", build_material(m));
}

Result<void> make_surface_ceiling(Output& out) {
    MaterialFields m = blank_material(kFloorSize, srgb(210, 210, 204), 0.9f, 0.0f);
    m.keep_height = true;
    constexpr int kPanels = 2;
    const float panel = static_cast<float>(kFloorSize) / kPanels, frame = 8.0f;
    const Field cloud = fractal_noise(kFloorSize, kFloorSize, NoiseKind::Perlin, 8, 4, 41);
    Field bar(kFloorSize, kFloorSize), holes(kFloorSize, kFloorSize), vent(kFloorSize, kFloorSize);
    for (int p = 0; p < kPanels; ++p) {
        const float at = static_cast<float>(p) * panel;
        paint_sdf(
            bar, Vec2f(at - frame, 0), Vec2f(at + frame, kFloorSize),
            [&](Vec2f q) { return std::abs(q.x - at) - frame * 0.5f; }, Stroke{});
        paint_sdf(
            bar, Vec2f(0, at - frame), Vec2f(kFloorSize, at + frame),
            [&](Vec2f q) { return std::abs(q.y - at) - frame * 0.5f; }, Stroke{});
    }
    // Acoustic panels perforated on a grid; the panel at (1,1) is a ventilation grille with slats.
    for (int py = 0; py < kPanels; ++py)
        for (int px = 0; px < kPanels; ++px) {
            const Vec2f o(static_cast<float>(px) * panel, static_cast<float>(py) * panel);
            if (px == 1 && py == 1) {
                for (int s = 0; s < 9; ++s) {
                    const float y = o.y + 40.0f + static_cast<float>(s) * 22.0f;
                    fill_rounded_rect(vent, Vec2f(o.x + 36, y), Vec2f(o.x + panel - 36, y + 12), 5.0f,
                                      Stroke{1.0f, Paint::Max, 4.0f});
                }
                continue;
            }
            for (int j = 0; j < 15; ++j)
                for (int i = 0; i < 15; ++i)
                    fill_circle(holes,
                                o + Vec2f(24.0f + static_cast<float>(i) * 15.0f,
                                          24.0f + static_cast<float>(j) * 15.0f),
                                2.2f);
        }
    const Field dirt = grime(kFloorSize, kFloorSize, cavity_occlusion(bar, 6, 1.0f), 42, 0.35f);
    for (size_t i = 0; i < m.color.pixels.size(); ++i) {
        Color c = mix(srgb(214, 212, 204), srgb(190, 188, 180), cloud.values[i]);
        c = mix(c, srgb(150, 140, 120), dirt.values[i] * 0.5f);
        c = mix(c, srgb(60, 60, 62), holes.values[i] * 0.8f);
        c = mix(c, srgb(40, 42, 44), vent.values[i] * 0.9f);
        c = mix(c, srgb(168, 170, 172), bar.values[i]);
        m.color.pixels[i] = c;
        m.height.values[i] = 0.5f + bar.values[i] * 0.2f - holes.values[i] * 0.12f - vent.values[i] * 0.3f +
                             cloud.values[i] * 0.02f;
        m.roughness.values[i] = 0.92f - bar.values[i] * 0.5f;
        m.metallic.values[i] = bar.values[i] * 0.9f;
    }
    m.normal_strength = 5.0f;
    return out.material("ceiling", build_material(m));
}

Result<void> make_surface_metal(Output& out) {
    MaterialFields m = blank_material(kFloorSize, srgb(150, 152, 156), 0.45f, 1.0f);
    m.keep_height = true;
    // Brushed steel: noise stretched 40:1 along x.
    Field brushed(kFloorSize, kFloorSize);
    for (int y = 0; y < kFloorSize; ++y)
        for (int x = 0; x < kFloorSize; ++x) {
            const float u = (static_cast<float>(x) + 0.5f) * 4.0f / kFloorSize,
                        v = (static_cast<float>(y) + 0.5f) * 160.0f / kFloorSize;
            brushed.at(x, y) =
                value_noise(u, v, 4, 160, 51) * 0.6f + value_noise(u * 4, v * 2, 16, 320, 52) * 0.4f;
        }
    // Diamond plate: raised elongated lozenges in a staggered grid, alternating direction.
    Field plate(kFloorSize, kFloorSize);
    constexpr int kCells = 8;
    const float cell = static_cast<float>(kFloorSize) / kCells;
    for (int j = 0; j < kCells; ++j)
        for (int i = 0; i < kCells; ++i) {
            const Vec2f c((static_cast<float>(i) + 0.5f) * cell, (static_cast<float>(j) + 0.5f) * cell);
            const bool flip = (i + j) % 2 == 1;
            const Vec2f axis = flip ? Vec2f(0.707f, 0.707f) : Vec2f(0.707f, -0.707f);
            const Vec2f side(-axis.y, axis.x);
            const float len = cell * 0.42f, wid = cell * 0.09f;
            const std::vector<Vec2f> diamond = {c + axis * len, c + side * wid, c - axis * len,
                                                c - side * wid};
            fill_polygon(plate, diamond, Stroke{1.0f, Paint::Max, 5.0f});
        }
    Rng rng(0x5EE1u);
    Field scratches(kFloorSize, kFloorSize);
    add_scratches(scratches, rng, 120, 10.0f, 80.0f, 1.2f);
    const Field stain = fractal_noise(kFloorSize, kFloorSize, NoiseKind::Perlin, 4, 5, 53);
    const Field cavity = cavity_occlusion(plate, 6, 1.5f);
    for (size_t i = 0; i < m.color.pixels.size(); ++i) {
        const float s = scratches.values[i], b = brushed.values[i];
        Color c = mix(srgb(118, 120, 124), srgb(168, 170, 174), b * 0.7f + plate.values[i] * 0.3f);
        c = mix(c, srgb(205, 206, 210), s * 0.6f);
        c = mix(c, srgb(84, 76, 66),
                std::clamp((stain.values[i] - 0.55f) * 3.0f, 0.0f, 1.0f) * 0.5f +
                    (1.0f - cavity.values[i]) * 0.6f);
        m.color.pixels[i] = c;
        m.height.values[i] = 0.45f + plate.values[i] * 0.35f + b * 0.01f - s * 0.02f;
        m.roughness.values[i] = 0.5f - plate.values[i] * 0.12f + (1.0f - b) * 0.1f - s * 0.2f +
                                std::clamp(stain.values[i] - 0.55f, 0.0f, 1.0f) * 0.6f;
        m.metallic.values[i] = 1.0f - std::clamp((stain.values[i] - 0.6f) * 2.0f, 0.0f, 0.5f);
    }
    m.normal_strength = 4.0f;
    return out.material("metal", build_material(m));
}

Result<void> make_surface_dojo_floor(Output& out) {
    MaterialFields m = blank_material(kFloorSize, srgb(196, 186, 128), 0.75f, 0.0f);
    m.keep_height = true;
    // Two tatami mats side by side (1 x 2 units each), woven across their width, with cloth borders.
    const float mat_w = kFloorSize / 2.0f, border = 22.0f;
    const Field fibre = fractal_noise(kFloorSize, kFloorSize, NoiseKind::Value, 256, 2, 61);
    const Field fade = fractal_noise(kFloorSize, kFloorSize, NoiseKind::Perlin, 4, 4, 62);
    for (int y = 0; y < kFloorSize; ++y)
        for (int x = 0; x < kFloorSize; ++x) {
            const float lx = std::fmod(static_cast<float>(x), mat_w);
            // Weave: rows of rush 4 px high, each a bundle whose shading rises and falls; warp threads every
            // 16 px.
            const float row = std::sin(static_cast<float>(y) * 3.14159265f / 4.0f);
            const float weave = 0.5f + 0.5f * row * row;
            const float warp = std::abs(std::fmod(lx, 16.0f) - 8.0f) < 0.8f ? 1.0f : 0.0f;
            const float edge = std::min(lx, mat_w - lx);
            const float in_border = std::clamp(border - edge + 0.5f, 0.0f, 1.0f);
            const float gap = std::clamp(2.0f - edge, 0.0f, 1.0f);
            Color straw = mix(srgb(166, 152, 92), srgb(206, 196, 140), weave * 0.6f + fibre.at(x, y) * 0.4f);
            straw = mix(straw, srgb(150, 150, 84), fade.at(x, y) * 0.5f);
            straw = mix(straw, srgb(130, 118, 70), warp * 0.5f);
            // The border cloth: dark green with a fine woven pattern.
            const float cloth_thread = 0.5f + 0.5f * std::sin(static_cast<float>(x + y) * 1.6f);
            const Color cloth =
                mix(srgb(28, 44, 34), srgb(44, 62, 48), cloth_thread * 0.5f + fibre.at(x, y) * 0.5f);
            Color c = mix(straw, cloth, in_border);
            c = mix(c, srgb(30, 26, 20), gap);
            m.color.at(x, y) = c;
            m.height.at(x, y) = 0.55f + weave * 0.04f * (1.0f - in_border) + in_border * 0.03f +
                                fibre.at(x, y) * 0.01f - warp * 0.01f - gap * 0.25f;
            m.roughness.at(x, y) = 0.7f + fibre.at(x, y) * 0.15f - in_border * 0.1f;
        }
    m.normal_strength = 6.0f;
    m.cavity_radius = 2;
    return out.material("dojo_floor", build_material(m));
}

} // namespace ks::assetgen
