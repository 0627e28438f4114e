// Level surface materials for walls: concrete panels and wooden planks. One texture repeat covers a wall's
// texture_scale (4 world units by default), so 512 px is 128 px per unit.
#include "catalog.h"
#include "material_builder.h"
#include "noise.h"

#include <algorithm>
#include <cmath>

namespace ks::assetgen {
namespace {
constexpr int kWallSize = 512;
}

Result<void> make_surface_concrete(Output& out) {
    MaterialFields m = blank_material(kWallSize, srgb(150, 148, 142), 0.85f, 0.0f);
    m.keep_height = true;
    Rng rng(0xC0C2E7Eu);
    const Field broad = fractal_noise(kWallSize, kWallSize, NoiseKind::Perlin, 4, 6, 11);
    const Field fine = fractal_noise(kWallSize, kWallSize, NoiseKind::Value, 64, 2, 12);
    const Field pores = cellular_noise(kWallSize, kWallSize, 96, 13);
    // Two by two cast panels per repeat (2 units each), separated by grooves.
    const std::vector<float> seams_at = {0.0f, 256.0f};
    const Field seams = panel_seams(kWallSize, kWallSize, seams_at, seams_at, 5.0f);
    Field panel_tint(kWallSize, kWallSize);
    for (int y = 0; y < kWallSize; ++y)
        for (int x = 0; x < kWallSize; ++x) panel_tint.at(x, y) = hash01(x / 256, y / 256, 14) - 0.5f;

    for (size_t i = 0; i < m.height.values.size(); ++i) {
        const float pore = pores.values[i] < 0.12f ? (0.12f - pores.values[i]) * 2.0f : 0.0f;
        m.height.values[i] =
            0.55f + broad.values[i] * 0.06f + fine.values[i] * 0.04f - pore - seams.values[i] * 0.35f;
    }
    // Form-tie holes: the round plugs left by the moulds, four per panel, plus steel bolts at panel corners.
    Field steel(kWallSize, kWallSize);
    for (int py = 0; py < 2; ++py)
        for (int px = 0; px < 2; ++px) {
            const Vec2f o(static_cast<float>(px * 256), static_cast<float>(py * 256));
            for (Vec2f tie : {Vec2f(64, 64), Vec2f(192, 64), Vec2f(64, 192), Vec2f(192, 192)})
                fill_circle(m.height, o + tie, 7.0f, Stroke{0.42f, Paint::Set, 2.0f});
            for (Vec2f bolt : {Vec2f(14, 14), Vec2f(242, 14), Vec2f(14, 242), Vec2f(242, 242)})
                add_bolt(m.height, o + bolt, 6.5f, 0.12f, &steel, true);
        }
    Field chips(kWallSize, kWallSize);
    add_scratches(chips, rng, 40, 6.0f, 40.0f, 2.0f);
    add_scaled(m.height, chips, -0.05f);

    const Field cavity = cavity_occlusion(m.height, 6, 2.5f);
    const Field dirt = grime(kWallSize, kWallSize, cavity, 15, 0.8f);
    const Color light = srgb(168, 166, 160), dark = srgb(118, 116, 110), stain = srgb(82, 74, 62);
    const Color bolt = srgb(120, 122, 126);
    for (size_t i = 0; i < m.color.pixels.size(); ++i) {
        const float t =
            std::clamp(broad.values[i] * 1.3f - 0.15f + panel_tint.values[i] * 0.25f + fine.values[i] * 0.2f,
                       0.0f, 1.0f);
        Color c = mix(dark, light, t);
        c = mix(c, stain, dirt.values[i] * 0.55f);
        c = mix(c, srgb(70, 70, 68), seams.values[i] * 0.6f);
        c = mix(c, bolt, steel.values[i]);
        m.color.pixels[i] = c;
        m.roughness.values[i] =
            0.82f + fine.values[i] * 0.1f - steel.values[i] * 0.4f + dirt.values[i] * 0.05f;
        m.metallic.values[i] = steel.values[i] * 0.85f;
    }
    m.normal_strength = 6.0f;
    return out.material("concrete", build_material(m));
}

Result<void> make_surface_wood(Output& out) {
    MaterialFields m = blank_material(kWallSize, srgb(140, 96, 60), 0.6f, 0.0f);
    m.keep_height = true;
    constexpr int kPlanks = 8; // vertical planks of 0.5 units
    const float plank_w = static_cast<float>(kWallSize) / kPlanks;
    const Field warp = fractal_noise(kWallSize, kWallSize, NoiseKind::Perlin, 4, 4, 21);
    const Field fibre = fractal_noise(kWallSize, kWallSize, NoiseKind::Value, 128, 2, 22);
    Field gaps(kWallSize, kWallSize);
    for (int p = 0; p < kPlanks; ++p) {
        const float x = static_cast<float>(p) * plank_w;
        paint_sdf(
            gaps, Vec2f(x - 3, 0), Vec2f(x + 3, kWallSize), [&](Vec2f q) { return std::abs(q.x - x) - 1.2f; },
            Stroke{});
    }
    const Color a = srgb(164, 112, 66), b = srgb(112, 70, 38), knot = srgb(74, 44, 24);
    for (int y = 0; y < kWallSize; ++y)
        for (int x = 0; x < kWallSize; ++x) {
            const int plank = static_cast<int>(static_cast<float>(x) / plank_w);
            // Each plank is a board cut at a different place from a log: rings vary by offset and frequency;
            // the end joint height differs per plank so the joints do not line up.
            const float offset = hash01(plank, 0, 23) * 40.0f, freq = 0.10f + hash01(plank, 1, 23) * 0.06f;
            const float joint = std::floor(hash01(plank, 2, 23) * 4.0f) * 128.0f + 64.0f;
            const float local_x = static_cast<float>(x) - static_cast<float>(plank) * plank_w;
            const float w = warp.at(x, y) * 14.0f;
            const float rings =
                std::sin((local_x + offset + w + std::sin(static_cast<float>(y) * 0.02f + offset) * 6.0f) *
                         freq * 6.2831853f);
            const float grain = 0.5f + 0.5f * rings;
            const float tint = hash01(plank, 3, 23) * 0.25f;
            Color c = mix(a, b, std::clamp(grain * 0.6f + fibre.at(x, y) * 0.3f + tint, 0.0f, 1.0f));
            const float joint_d = std::abs(static_cast<float>(y) - joint);
            const float joint_mask = std::clamp(2.0f - joint_d, 0.0f, 1.0f);
            c = mix(c, knot, std::max(gaps.at(x, y), joint_mask) * 0.85f);
            m.color.at(x, y) = c;
            m.height.at(x, y) =
                0.6f + grain * 0.03f + fibre.at(x, y) * 0.02f - std::max(gaps.at(x, y), joint_mask) * 0.3f;
            m.roughness.at(x, y) = 0.5f + grain * 0.15f + gaps.at(x, y) * 0.3f;
        }
    // A few knots: dark elliptical swirls.
    Rng rng(0x600Du);
    for (int k = 0; k < 6; ++k) {
        const Vec2f c(rng.uniform(0.0f, kWallSize), rng.uniform(0.0f, kWallSize));
        Field knot_mask(kWallSize, kWallSize);
        fill_circle(knot_mask, c, rng.uniform(4.0f, 8.0f), Stroke{1.0f, Paint::Max, 4.0f});
        blend(m.color, knot_mask, knot, 0.8f);
        add_scaled(m.height, knot_mask, -0.03f);
    }
    m.normal_strength = 5.0f;
    return out.material("wood", build_material(m));
}

} // namespace ks::assetgen
