// The player's rifle: about 1.0 long, origin at the pistol grip, barrel along -Z, a `muzzle` empty at the
// barrel tip. Like the reference's: orange and grey enamelled steel, dark polymer furniture, bare steel
// where it wears or moves, and printed markings; a holographic sight on a top rail.
#include "catalog.h"
#include "model_kit.h"
#include "rifle_materials.h"

#include <algorithm>
#include <cmath>

namespace ks::assetgen {
namespace {

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
    KS_ASSETGEN_TRY(out.material("rifle_orange", rifle_paint(srgb(222, 112, 22), srgb(240, 140, 44), 301)));
    KS_ASSETGEN_TRY(out.material("rifle_grey", rifle_paint(srgb(118, 121, 126), srgb(140, 143, 148), 302)));
    KS_ASSETGEN_TRY(out.material("rifle_polymer", rifle_polymer()));
    KS_ASSETGEN_TRY(out.texture("rifle_decals_basecolor", rifle_decals(out.font()), PngChannels::Rgb));
    Model model("rifle");
    const float uv = 4.0f; // one texture repeat per 0.25 units
    const int orange = model.add_material(textured("rifle_orange", "rifle_orange", vec4(1.0f), 1.0f, 1.0f));
    const int grey = model.add_material(textured("rifle_grey", "rifle_grey", vec4(1.0f), 1.0f, 1.0f));
    const int polymer =
        model.add_material(textured("rifle_polymer", "rifle_polymer", vec4(1.0f), 1.0f, 1.0f));
    const int steel = model.add_material(plain("rifle_steel", vec3(0.62f, 0.63f, 0.65f), 0.85f, 0.32f));
    Material decal_material = plain("rifle_decal", vec3(1.0f), 0.0f, 0.5f);
    decal_material.basecolor_texture = "rifle_decals_basecolor";
    const int decal = model.add_material(decal_material);
    const int lens = model.add_material(
        plain("rifle_lens", vec3(0.05f, 0.1f, 0.12f), 0.0f, 0.05f, vec3(0.05f, 0.25f, 0.3f)));
    const int sight = model.add_material(plain("rifle_sight", vec3(0.92f), 0.0f, 0.5f, vec3(0.25f)));
    const int root = model.add_node("rifle", -1);
    Node& r = model.node(root);
    auto box = [&](int material, vec3 size, vec3 centre, float radius = 0.004f) {
        r.part(material).append(rounded_box(size, radius, 1, uv), at(centre));
    };
    auto decal_pair = [&](vec3 size, vec3 centre, int row) {
        r.part(decal).append(rifle_decal_plate(size, row), at(centre));
    };

    // Receiver: grey upper and lower halves, orange side armour and top cover, charging handle, ejection
    // port.
    box(grey, vec3(0.075f, 0.07f, 0.40f), vec3(0, 0.085f, -0.06f), 0.012f);
    box(grey, vec3(0.07f, 0.06f, 0.30f), vec3(0, 0.025f, -0.04f), 0.012f);
    box(orange, vec3(0.083f, 0.046f, 0.22f), vec3(0, 0.088f, -0.07f), 0.01f);
    box(orange, vec3(0.062f, 0.012f, 0.10f), vec3(0, 0.123f, 0.075f), 0.005f);
    box(steel, vec3(0.03f, 0.02f, 0.04f), vec3(0, 0.12f, 0.14f), 0.005f);
    box(steel, vec3(0.07f, 0.012f, 0.014f), vec3(0, 0.125f, 0.155f), 0.004f);
    box(polymer, vec3(0.006f, 0.024f, 0.05f), vec3(0.04f, 0.095f, 0.08f), 0.002f);
    decal_pair(vec3(0.0846f, 0.026f, 0.13f), vec3(0, 0.089f, -0.08f), 0);
    // Fire selector: its legend on both sides of the lower receiver, a steel lever on the left.
    decal_pair(vec3(0.0716f, 0.014f, 0.075f), vec3(0, 0.033f, 0.055f), 1);
    box(steel, vec3(0.004f, 0.008f, 0.03f), vec3(-0.0375f, 0.033f, 0.03f), 0.002f);
    r.part(steel).append(cylinder(0.007f, 0.004f, 12), at(vec3(-0.036f, 0.033f, 0.03f)) * y_to_x() *
                                                           glm::rotate(mat4(1.0f), kPiF, vec3(0, 0, 1)));
    decal_pair(vec3(0.0716f, 0.012f, 0.08f), vec3(0, 0.008f, 0.02f), 3);
    // Top rail with cross slots over the receiver.
    box(steel, vec3(0.045f, 0.012f, 0.30f), vec3(0, 0.128f, -0.11f), 0.003f);
    for (int k = 0; k < 10; ++k)
        box(steel, vec3(0.05f, 0.01f, 0.012f), vec3(0, 0.139f, 0.02f - static_cast<float>(k) * 0.028f), 0.0f);

    // Handguard: grey octagonal shroud, orange side rails, polymer vent inserts on top and below.
    LatheOptions shroud;
    shroud.u_repeats = 1.0f;
    shroud.v_scale = uv;
    shroud.crease_degrees = 30.0f;
    r.part(grey).append(cylinder(0.042f, 0.34f, 8, 0.01f, shroud),
                        at(vec3(0, 0.08f, -0.26f)) * y_to_minus_z() *
                            glm::rotate(mat4(1.0f), kPiF / 8.0f, vec3(0, 1, 0)));
    box(orange, vec3(0.09f, 0.024f, 0.26f), vec3(0, 0.08f, -0.43f), 0.008f);
    for (int k = 0; k < 6; ++k)
        for (float y : {0.12f, 0.04f})
            box(polymer, vec3(0.03f, 0.006f, 0.028f), vec3(0, y, -0.33f - static_cast<float>(k) * 0.045f),
                0.003f);
    for (int k = 0; k < 4; ++k) // steel screws holding the side rails
        for (float side : {-1.0f, 1.0f})
            r.part(steel).append(
                cylinder(0.004f, 0.004f, 8),
                at(vec3(side * 0.045f, 0.08f, -0.34f - static_cast<float>(k) * 0.06f)) *
                    (side > 0 ? y_to_x() : glm::rotate(mat4(1.0f), kPiF / 2.0f, vec3(0, 0, 1))));
    // Barrel, a stack of cooling fins, front sight, slotted muzzle brake.
    r.part(steel).append(cylinder(0.013f, 0.2f, 12), at(vec3(0, 0.08f, -0.58f)) * y_to_minus_z());
    for (int k = 0; k < 5; ++k)
        r.part(steel).append(cylinder(0.027f, 0.006f, 16, 0.0015f),
                             at(vec3(0, 0.08f, -0.625f - static_cast<float>(k) * 0.016f)) * y_to_minus_z());
    box(grey, vec3(0.032f, 0.03f, 0.03f), vec3(0, 0.105f, -0.6f), 0.005f);
    box(steel, vec3(0.006f, 0.036f, 0.006f), vec3(0, 0.135f, -0.6f), 0.001f);
    box(sight, vec3(0.008f, 0.008f, 0.008f), vec3(0, 0.155f, -0.6f), 0.002f);
    LatheOptions brake;
    brake.segments = 12;
    brake.v_scale = uv;
    r.part(steel).append(
        lathe({{0.0f, 0.0f}, {0.021f, 0.0f}, {0.021f, 0.05f}, {0.017f, 0.058f}, {0.0f, 0.058f}}, brake),
        at(vec3(0, 0.08f, -0.72f)) * y_to_minus_z());
    for (int k = 0; k < 3; ++k)
        box(polymer, vec3(0.044f, 0.008f, 0.006f), vec3(0, 0.08f, -0.735f - static_cast<float>(k) * 0.012f),
            0.0f);

    // Magazine (curved) with its cell label and a steel floor plate; pistol grip, trigger guard, trigger.
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
    r.part(steel).append(
        side_profile({{-0.2f, -0.172f}, {-0.145f, -0.198f}, {-0.14f, -0.21f}, {-0.205f, -0.18f}}, 0.056f),
        mat4(1.0f));
    decal_pair(vec3(0.052f, 0.03f, 0.038f), vec3(0, -0.035f, -0.12f), 2);
    r.part(polymer).append(side_profile({{0.02f, 0.0f},
                                         {-0.04f, 0.0f},
                                         {-0.015f, -0.06f},
                                         {0.005f, -0.15f},
                                         {0.055f, -0.15f},
                                         {0.04f, -0.06f}},
                                        0.04f),
                           mat4(1.0f));
    box(steel, vec3(0.008f, 0.005f, 0.07f), vec3(0, -0.045f, -0.05f), 0.002f);
    box(steel, vec3(0.006f, 0.035f, 0.006f), vec3(0, -0.02f, -0.045f), 0.002f);

    // Stock: grey buffer tube, orange comb with the caution label, polymer lower strut and butt, rubber pad.
    r.part(grey).append(cylinder(0.024f, 0.22f, 16, 0.004f, shroud), at(vec3(0, 0.085f, 0.11f)) * y_to_z());
    r.part(orange).append(
        side_profile({{0.12f, 0.124f}, {0.12f, 0.075f}, {0.36f, 0.08f}, {0.36f, 0.128f}}, 0.044f),
        mat4(1.0f));
    decal_pair(vec3(0.046f, 0.034f, 0.15f), vec3(0, 0.104f, 0.25f), 2);
    r.part(polymer).append(
        side_profile({{0.12f, 0.0f}, {0.12f, 0.05f}, {0.35f, -0.02f}, {0.35f, -0.065f}}, 0.036f), mat4(1.0f));
    r.part(grey).append(
        side_profile({{0.32f, 0.122f}, {0.32f, -0.06f}, {0.365f, -0.07f}, {0.365f, 0.122f}}, 0.044f),
        mat4(1.0f));
    box(polymer, vec3(0.05f, 0.2f, 0.02f), vec3(0, 0.028f, 0.37f), 0.008f);

    // Holographic sight: polymer base, grey side walls, orange hood, lens pane and a rear window, plus a
    // folding rear sight with a luminous post.
    box(polymer, vec3(0.04f, 0.012f, 0.09f), vec3(0, 0.15f, -0.05f), 0.003f);
    for (float side : {-1.0f, 1.0f})
        box(grey, vec3(0.007f, 0.042f, 0.08f), vec3(side * 0.022f, 0.175f, -0.05f), 0.003f);
    box(orange, vec3(0.052f, 0.009f, 0.085f), vec3(0, 0.2f, -0.05f), 0.004f);
    box(lens, vec3(0.037f, 0.034f, 0.003f), vec3(0, 0.176f, -0.085f), 0.0f);
    box(lens, vec3(0.037f, 0.034f, 0.003f), vec3(0, 0.176f, -0.015f), 0.0f);
    box(steel, vec3(0.03f, 0.014f, 0.02f), vec3(0, 0.148f, 0.06f), 0.003f);
    box(steel, vec3(0.007f, 0.03f, 0.006f), vec3(0, 0.168f, 0.06f), 0.001f);
    box(sight, vec3(0.009f, 0.009f, 0.007f), vec3(0, 0.186f, 0.06f), 0.002f);

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
