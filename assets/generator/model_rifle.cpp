// The player's rifle: about 1.0 long, origin at the pistol grip, barrel along -Z, a `muzzle` empty at the
// barrel tip. Gunmetal receiver and barrel, polymer furniture, optic on a top rail.
#include "catalog.h"
#include "material_builder.h"
#include "model_kit.h"
#include "noise.h"

#include <algorithm>
#include <cmath>

namespace ks::assetgen {
namespace {

// Worn gunmetal: dark parkerised finish, brushed streaks, edge wear and scratches showing bright steel.
MaterialMaps gunmetal() {
    constexpr int n = 512;
    MaterialFields m = blank_material(n, srgb(52, 54, 58), 0.5f, 0.9f);
    const Field grain = fractal_noise(n, n, NoiseKind::Value, 128, 3, 201);
    const Field blotch = fractal_noise(n, n, NoiseKind::Perlin, 6, 5, 202);
    Field scratches(n, n), stipple(n, n);
    Rng rng(0x61F1Eu);
    add_scratches(scratches, rng, 160, 6.0f, 60.0f, 1.2f);
    // Stippled grip texture in the lower half (the polymer parts use the same map).
    for (int j = 0; j < 64; ++j)
        for (int i = 0; i < 64; ++i) {
            const float jitter = hash01(i, j, 203) * 3.0f;
            add_bolt(stipple,
                     Vec2f(static_cast<float>(i) * 8.0f + jitter, static_cast<float>(j) * 8.0f + 4.0f), 2.2f,
                     0.15f);
        }
    for (size_t i = 0; i < m.color.pixels.size(); ++i) {
        const float s = scratches.values[i], b = blotch.values[i];
        Color c = mix(srgb(40, 42, 46), srgb(70, 72, 78), grain.values[i] * 0.6f + b * 0.4f);
        c = mix(c, srgb(150, 152, 156), s * 0.8f);
        m.color.pixels[i] = c;
        m.height.values[i] = 0.5f + stipple.values[i] * 0.3f + grain.values[i] * 0.02f - s * 0.03f;
        m.roughness.values[i] = 0.45f + b * 0.2f - s * 0.25f;
        m.metallic.values[i] = 0.75f + s * 0.25f;
    }
    m.normal_strength = 3.0f;
    m.cavity_radius = 2;
    return build_material(m);
}

// Side profiles are drawn as (z, y) outlines (z forward is negative), extruded along x.
Mesh side_profile(const std::vector<vec2>& zy, float thickness) {
    std::vector<vec2> outline = zy;
    // extrude() wants counter-clockwise in its (x, y) plane; after swap_xz its x becomes our z.
    float area = 0.0f;
    for (size_t i = 0; i < outline.size(); ++i) {
        const vec2 a = outline[i], b = outline[(i + 1) % outline.size()];
        area += a.x * b.y - b.x * a.y;
    }
    if (area < 0.0f) std::reverse(outline.begin(), outline.end());
    Mesh m;
    m.append(extrude(outline, thickness, 4.0f), swap_xz());
    return m;
}
} // namespace

Result<void> make_rifle(Output& out) {
    KS_ASSETGEN_TRY(out.material("rifle", gunmetal()));
    Model model("rifle");
    const float uv = 4.0f; // one texture repeat per 0.25 units
    const int metal = model.add_material(textured("rifle_metal", "rifle", vec4(1.0f), 1.0f, 1.0f));
    const int polymer =
        model.add_material(textured("rifle_polymer", "rifle", vec4(0.45f, 0.45f, 0.42f, 1.0f), 0.1f, 1.0f));
    const int lens = model.add_material(
        plain("rifle_lens", vec3(0.05f, 0.1f, 0.12f), 0.0f, 0.05f, vec3(0.05f, 0.25f, 0.3f)));
    const int accent = model.add_material(plain("rifle_accent", vec3(0.85f, 0.45f, 0.1f), 0.0f, 0.4f));
    const int root = model.add_node("rifle", -1);
    Node& r = model.node(root);

    // Receiver: upper and lower halves, ejection port, charging handle.
    r.part(metal).append(rounded_box(vec3(0.075f, 0.07f, 0.40f), 0.012f, 1, uv), at(vec3(0, 0.085f, -0.06f)));
    r.part(metal).append(rounded_box(vec3(0.07f, 0.06f, 0.30f), 0.012f, 1, uv), at(vec3(0, 0.025f, -0.04f)));
    r.part(polymer).append(rounded_box(vec3(0.005f, 0.025f, 0.07f)), at(vec3(0.038f, 0.09f, -0.04f)));
    r.part(metal).append(rounded_box(vec3(0.03f, 0.02f, 0.04f), 0.005f, 1, uv), at(vec3(0, 0.12f, 0.12f)));
    // Top rail with cross slots.
    r.part(metal).append(rounded_box(vec3(0.045f, 0.012f, 0.62f), 0.003f, 1, uv), at(vec3(0, 0.126f, -0.2f)));
    for (int k = 0; k < 20; ++k)
        r.part(metal).append(rounded_box(vec3(0.05f, 0.01f, 0.012f)),
                             at(vec3(0, 0.137f, 0.09f - static_cast<float>(k) * 0.03f)));
    // Handguard: octagonal shroud with vent slots, around the barrel.
    LatheOptions shroud;
    shroud.u_repeats = 1.0f;
    shroud.v_scale = uv;
    shroud.crease_degrees = 30.0f;
    r.part(metal).append(cylinder(0.042f, 0.34f, 8, 0.01f, shroud),
                         at(vec3(0, 0.08f, -0.26f)) * y_to_minus_z() *
                             glm::rotate(mat4(1.0f), kPiF / 8.0f, vec3(0, 1, 0)));
    for (int k = 0; k < 6; ++k)
        for (float side : {-1.0f, 1.0f})
            r.part(polymer).append(rounded_box(vec3(0.006f, 0.018f, 0.035f), 0.003f, 1),
                                   at(vec3(side * 0.040f, 0.08f, -0.31f - static_cast<float>(k) * 0.05f)));
    // Barrel, front sight block and muzzle brake.
    r.part(metal).append(cylinder(0.013f, 0.18f, 12), at(vec3(0, 0.08f, -0.58f)) * y_to_minus_z());
    r.part(metal).append(rounded_box(vec3(0.03f, 0.05f, 0.03f), 0.005f, 1, uv), at(vec3(0, 0.11f, -0.62f)));
    LatheOptions brake;
    brake.segments = 12;
    brake.v_scale = uv;
    r.part(metal).append(
        lathe({{0.0f, 0.0f}, {0.021f, 0.0f}, {0.021f, 0.05f}, {0.017f, 0.058f}, {0.0f, 0.058f}}, brake),
        at(vec3(0, 0.08f, -0.72f)) * y_to_minus_z());
    for (int k = 0; k < 3; ++k)
        r.part(polymer).append(rounded_box(vec3(0.044f, 0.008f, 0.006f)),
                               at(vec3(0, 0.08f, -0.735f - static_cast<float>(k) * 0.012f)));

    // Magazine (curved), pistol grip, trigger guard, trigger.
    r.part(polymer).append(side_profile({{-0.08f, 0.0f},
                                         {-0.135f, 0.0f},
                                         {-0.148f, -0.06f},
                                         {-0.168f, -0.12f},
                                         {-0.198f, -0.175f},
                                         {-0.145f, -0.2f},
                                         {-0.118f, -0.145f},
                                         {-0.1f, -0.085f},
                                         {-0.09f, -0.03f}},
                                        0.05f),
                           mat4(1.0f));
    r.part(polymer).append(side_profile({{0.02f, 0.0f},
                                         {-0.04f, 0.0f},
                                         {-0.015f, -0.06f},
                                         {0.005f, -0.15f},
                                         {0.055f, -0.15f},
                                         {0.04f, -0.06f}},
                                        0.04f),
                           mat4(1.0f));
    r.part(metal).append(rounded_box(vec3(0.008f, 0.005f, 0.07f), 0.002f, 1, uv),
                         at(vec3(0, -0.045f, -0.05f)));
    r.part(metal).append(rounded_box(vec3(0.006f, 0.035f, 0.006f), 0.002f, 1, uv),
                         at(vec3(0, -0.02f, -0.045f)));
    // Stock: a skeleton of three struts (comb, lower strut, butt) around a triangular opening.
    r.part(polymer).append(
        side_profile({{0.12f, 0.118f}, {0.12f, 0.075f}, {0.36f, 0.08f}, {0.36f, 0.122f}}, 0.04f), mat4(1.0f));
    r.part(polymer).append(
        side_profile({{0.12f, 0.0f}, {0.12f, 0.05f}, {0.35f, -0.02f}, {0.35f, -0.065f}}, 0.036f), mat4(1.0f));
    r.part(polymer).append(
        side_profile({{0.32f, 0.122f}, {0.32f, -0.06f}, {0.365f, -0.07f}, {0.365f, 0.122f}}, 0.044f),
        mat4(1.0f));
    r.part(metal).append(rounded_box(vec3(0.05f, 0.19f, 0.02f), 0.008f, 1, uv), at(vec3(0, 0.025f, 0.37f)));
    r.part(accent).append(rounded_box(vec3(0.047f, 0.012f, 0.1f), 0.003f, 1), at(vec3(0, 0.116f, 0.28f)));
    // Optic: tube with bells and lenses on two rings.
    LatheOptions scope;
    scope.segments = 16;
    scope.v_scale = uv;
    const std::vector<vec2> tube_profile = {{0.0f, 0.0f},    {0.026f, 0.0f},  {0.028f, 0.01f},
                                            {0.028f, 0.04f}, {0.018f, 0.06f}, {0.018f, 0.16f},
                                            {0.024f, 0.18f}, {0.024f, 0.22f}, {0.0f, 0.22f}};
    r.part(metal).append(lathe(tube_profile, scope), at(vec3(0, 0.18f, 0.05f)) * y_to_minus_z());
    for (float z : {-0.02f, -0.11f})
        r.part(metal).append(rounded_box(vec3(0.03f, 0.04f, 0.018f), 0.004f, 1, uv), at(vec3(0, 0.152f, z)));
    r.part(metal).append(cylinder(0.008f, 0.02f, 10), at(vec3(0, 0.197f, -0.07f)));
    r.part(lens).append(cylinder(0.021f, 0.002f, 16), at(vec3(0, 0.18f, -0.171f)) * y_to_minus_z());
    r.part(lens).append(cylinder(0.016f, 0.002f, 16), at(vec3(0, 0.18f, 0.051f)) * y_to_z());

    // Built at a comfortable modelling size; scaled so muzzle to butt is 1.0 like the convention asks.
    const float scale = 1.0f / 1.16f;
    for (auto& [material, mesh] : r.parts) {
        Mesh scaled;
        scaled.append(mesh, glm::scale(mat4(1.0f), vec3(scale)));
        mesh = std::move(scaled);
    }
    model.add_node("muzzle", root, vec3(0, 0.08f, -0.78f) * scale);
    return out.model(model);
}

} // namespace ks::assetgen
