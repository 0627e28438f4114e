// The rifle's texture sets: two enamel paints (orange and grey) worn through to steel, a stippled polymer,
// and the decal atlas of its markings.
#include "rifle_materials.h"

#include "noise.h"
#include "surface_ops.h"

#include <algorithm>
#include <cmath>

namespace ks::assetgen {
namespace {
constexpr int kSize = 512;

float smooth(float e0, float e1, float x) {
    const float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}
} // namespace

// Painted steel: an even enamel with orange-peel grain and faint mottling, small chips and scratches where
// the paint is gone and bright steel shows (recessed, metallic and smoother), a few stencilled dots.
MaterialMaps rifle_paint(Color paint, Color paint_light, std::uint32_t seed) {
    MaterialFields m = blank_material(kSize, paint, 0.45f, 0.0f);
    const Field peel = fractal_noise(kSize, kSize, NoiseKind::Value, 96, 2, seed + 1);
    const Field mottle = fractal_noise(kSize, kSize, NoiseKind::Perlin, 5, 4, seed + 2);
    const Field chip_noise = fractal_noise(kSize, kSize, NoiseKind::Perlin, 12, 5, seed + 3);
    Field scratches(kSize, kSize);
    Rng rng(seed * 2654435761u + 7u);
    add_scratches(scratches, rng, 70, 8.0f, 70.0f, 1.1f);
    const Color steel = srgb(176, 178, 182), edge = srgb(96, 96, 98);
    for (size_t i = 0; i < m.color.pixels.size(); ++i) {
        // Chips: the high tail of a noise field; a darker primer ring where the paint breaks.
        const float chip = smooth(0.70f, 0.74f, chip_noise.values[i]);
        const float rim = smooth(0.66f, 0.70f, chip_noise.values[i]) - chip;
        const float bare = std::max(chip, scratches.values[i] * 0.9f);
        Color c = mix(paint, paint_light, mottle.values[i] * 0.7f + peel.values[i] * 0.3f);
        c = mix(c, edge, rim * 0.6f);
        c = mix(c, steel, bare);
        m.color.pixels[i] = c;
        m.height.values[i] = 0.6f + peel.values[i] * 0.015f - bare * 0.08f;
        m.roughness.values[i] = 0.42f + mottle.values[i] * 0.12f - bare * 0.12f;
        m.metallic.values[i] = bare;
    }
    m.normal_strength = 2.0f;
    m.cavity_radius = 2;
    m.cavity_strength = 1.5f;
    return build_material(m);
}

// Glass-filled polymer: dark grey with a moulded stipple (the grip and magazine), fine grain and scuffs that
// read lighter.
MaterialMaps rifle_polymer() {
    MaterialFields m = blank_material(kSize, srgb(70, 72, 76), 0.7f, 0.0f);
    const Field grain = fractal_noise(kSize, kSize, NoiseKind::Value, 128, 3, 211);
    const Field blotch = fractal_noise(kSize, kSize, NoiseKind::Perlin, 6, 4, 212);
    Field stipple(kSize, kSize), scuffs(kSize, kSize);
    for (int j = 0; j < 64; ++j)
        for (int i = 0; i < 64; ++i) {
            const float jitter = hash01(i, j, 213) * 3.0f;
            add_bolt(stipple,
                     Vec2f(static_cast<float>(i) * 8.0f + jitter, static_cast<float>(j) * 8.0f + 4.0f), 2.2f,
                     0.15f);
        }
    Rng rng(0x9017Bu);
    add_scratches(scuffs, rng, 40, 10.0f, 50.0f, 1.5f);
    for (size_t i = 0; i < m.color.pixels.size(); ++i) {
        Color c = mix(srgb(58, 60, 64), srgb(84, 86, 90), grain.values[i] * 0.5f + blotch.values[i] * 0.5f);
        c = mix(c, srgb(118, 120, 124), scuffs.values[i] * 0.6f);
        m.color.pixels[i] = c;
        m.height.values[i] = 0.5f + stipple.values[i] * 0.3f + grain.values[i] * 0.02f;
        m.roughness.values[i] = 0.72f + blotch.values[i] * 0.15f - scuffs.values[i] * 0.2f;
    }
    m.normal_strength = 3.0f;
    m.cavity_radius = 2;
    return build_material(m);
}

// 512 x 256, four rows of 512 x 64 (one per plate, placed with rifle_decal_row): the maker's mark, the
// fire-selector legend, the stock's caution label and the serial number with a bar code.
Image rifle_decals(const Font& font) {
    constexpr int w = 512, h = 256, row = 64;
    Field light(w, h), orange(w, h);
    auto y0 = [](int r) { return static_cast<float>(r * row); };
    // Row 0: "KS-7" in orange, "KILLSWITCH ARMS" and a thin rule in light grey on gunmetal.
    font.draw(orange, "KS-7", Vec2f(14, y0(0) + 48), 44.0f);
    font.draw(light, "KILLSWITCH ARMS", Vec2f(150, y0(0) + 30), 20.0f);
    font.draw(light, "PULSE CARBINE  .40 CELL", Vec2f(150, y0(0) + 54), 16.0f);
    fill_rounded_rect(light, Vec2f(150, y0(0) + 36), Vec2f(500, y0(0) + 38), 0.0f);
    // Row 1: fire selector, SAFE / SEMI / AUTO with a dot per mode (the last one orange).
    const char* modes[3] = {"SAFE", "SEMI", "AUTO"};
    for (int k = 0; k < 3; ++k) {
        const float x = 30.0f + static_cast<float>(k) * 165.0f;
        fill_circle(k == 2 ? orange : light, Vec2f(x, y0(1) + 32), 9.0f);
        font.draw(light, modes[k], Vec2f(x + 20, y0(1) + 44), 30.0f);
    }
    // Row 2: the reference's stock label, "CAUTION" over ticks and arrows, on a hazard-striped end.
    hazard_stripes(orange, Vec2f(0, y0(2)), Vec2f(96, y0(2) + row), 24.0f);
    font.draw(light, "CAUTION", Vec2f(112, y0(2) + 30), 26.0f);
    font.draw(light, "ENERGY CELL - DO NOT OPEN", Vec2f(112, y0(2) + 54), 15.0f);
    for (int k = 0; k < 4; ++k) {
        const float x = 400.0f + static_cast<float>(k) * 22.0f;
        draw_line(light, Vec2f(x, y0(2) + 10), Vec2f(x, y0(2) + 52), 3.0f);
        fill_polygon(light, {{x - 7, y0(2) + 46}, {x + 7, y0(2) + 46}, {x, y0(2) + 58}});
    }
    // Row 3: serial number and a bar code from its hash.
    font.draw(light, "SN 0451-2077-KS", Vec2f(14, y0(3) + 42), 26.0f);
    for (int k = 0; k < 44; ++k) {
        const float x = 290.0f + static_cast<float>(k) * 4.8f;
        const float width = 1.2f + 2.4f * hash01(k, 3, 221);
        fill_rounded_rect(light, Vec2f(x, y0(3) + 12), Vec2f(x + width, y0(3) + 52), 0.0f);
    }
    // Every row's plate: gunmetal with a thin bevelled rim.
    Field rim(w, h);
    for (int r = 0; r < 4; ++r) {
        fill_rounded_rect(rim, Vec2f(0, y0(r)), Vec2f(w, y0(r) + row), 0.0f);
        fill_rounded_rect(rim, Vec2f(3, y0(r) + 3), Vec2f(w - 3, y0(r) + row - 3), 3.0f,
                          Stroke{0.0f, Paint::Set});
    }
    Image image(w, h, srgb(62, 64, 68));
    blend(image, rim, srgb(120, 122, 126));
    blend(image, orange, srgb(232, 128, 32));
    blend(image, light, srgb(226, 228, 230));
    return image;
}

Mesh rifle_decal_plate(vec3 size, int row) {
    Mesh m = rounded_box(size, 0.0f, 0, 1.0f, UvMode::PerFace);
    m.transform_uvs(vec2(1.0f, 0.25f), vec2(0.0f, 0.25f * static_cast<float>(row)));
    return m;
}

} // namespace ks::assetgen
