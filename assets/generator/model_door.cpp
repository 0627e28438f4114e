// Sliding double door for a 5 x 5 doorway: leaves `door_l` (+X half) and `door_r` (-X half) of
// 2.36 x 5.36 x 0.14 that slide 2.0 apart, inside a `frame` whose casings (9 wide) leave a slot for them
// and hide them when open.
#include "catalog.h"
#include "material_builder.h"
#include "model_kit.h"
#include "noise.h"

#include <algorithm>
#include <cmath>

namespace ks::assetgen {
namespace {
constexpr int kW = 512, kH = 1024;
constexpr float kLeafW = 2.36f, kLeafH = 5.36f, kLeafD = 0.14f;

// One leaf face: painted steel with a raised rim, seams, a ribbed centre panel, a hazard band at the foot
// and glowing guide strips along both edges (emissive). Symmetric left-right so the mirrored leaf matches.
MaterialMaps door_leaf() {
    MaterialFields m;
    m.color = Image(kW, kH, srgb(74, 86, 100));
    m.height = Field(kW, kH, 0.5f);
    m.roughness = Field(kW, kH, 0.5f);
    m.metallic = Field(kW, kH, 0.3f);
    const Field noise = fractal_noise(kW, kH, NoiseKind::Perlin, 4, 5, 301);
    Field rim(kW, kH), ribs(kW, kH), hazard(kW, kH), band(kW, kH), strips(kW, kH), steel(kW, kH),
        scratches(kW, kH);
    fill_rounded_rect(rim, Vec2f(0, 0), Vec2f(kW, kH), 0.0f);
    fill_rounded_rect(rim, Vec2f(26, 26), Vec2f(kW - 26, kH - 26), 6.0f, Stroke{0.0f, Paint::Set, 6.0f});
    for (float y : {300.0f, 640.0f})
        paint_sdf(
            ribs, Vec2f(0, y - 4), Vec2f(kW, y + 4), [&](Vec2f p) { return std::abs(p.y - y) - 2.0f; },
            Stroke{});
    for (int k = 0; k < 9; ++k) {
        const float y = 350.0f + static_cast<float>(k) * 30.0f;
        fill_rounded_rect(steel, Vec2f(110, y), Vec2f(kW - 110, y + 14), 7.0f,
                          Stroke{1.0f, Paint::Max, 5.0f});
    }
    fill_rounded_rect(band, Vec2f(26, 860), Vec2f(kW - 26, kH - 26), 4.0f);
    hazard_stripes(hazard, Vec2f(26, 860), Vec2f(kW - 26, kH - 26), 90.0f, 1.0f);
    for (float x : {44.0f, static_cast<float>(kW) - 44.0f})
        fill_rounded_rect(strips, Vec2f(x - 6, 90), Vec2f(x + 6, 820), 6.0f);
    for (float x : {14.0f, static_cast<float>(kW) - 14.0f})
        for (int k = 0; k < 20; ++k)
            add_bolt(m.height, Vec2f(x, 30.0f + static_cast<float>(k) * 50.0f), 5.0f, 0.1f, &steel);
    Rng rng(0xD002u);
    add_scratches(scratches, rng, 120, 10.0f, 70.0f, 1.5f);
    const Field cavity = cavity_occlusion(rim, 8, 1.0f);
    const Field dirt = grime(kW, kH, cavity, 302, 0.5f);
    Image emissive(kW, kH, Color(0, 0, 0, 1));
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const size_t i = static_cast<size_t>(y) * kW + x;
            // Dirt collects toward the floor.
            const float low = std::clamp((static_cast<float>(y) - 700.0f) / 324.0f, 0.0f, 1.0f);
            Color c = mix(srgb(64, 76, 90), srgb(86, 98, 112), noise.values[i]);
            c = mix(c, mix(srgb(236, 178, 20), srgb(26, 24, 22), hazard.values[i]), band.values[i]);
            c = mix(c, srgb(140, 144, 150), steel.values[i] * 0.8f);
            c = mix(c, srgb(30, 34, 40), ribs.values[i]);
            c = mix(c, srgb(160, 164, 170), scratches.values[i] * 0.5f);
            c = mix(c, srgb(60, 52, 40),
                    std::clamp(dirt.values[i] * 0.5f + low * 0.25f * noise.values[i], 0.0f, 1.0f));
            c = mix(c, srgb(150, 230, 240), strips.values[i]);
            m.color.pixels[i] = c;
            m.height.values[i] = 0.5f + rim.values[i] * 0.15f + steel.values[i] * 0.08f -
                                 ribs.values[i] * 0.2f - strips.values[i] * 0.05f -
                                 scratches.values[i] * 0.02f;
            m.roughness.values[i] = 0.45f + noise.values[i] * 0.15f + low * 0.15f - steel.values[i] * 0.15f -
                                    scratches.values[i] * 0.2f;
            m.metallic.values[i] = 0.2f + steel.values[i] * 0.7f + scratches.values[i] * 0.6f;
            emissive.pixels[i] = Color(glm::vec3(0.35f, 0.9f, 1.0f) * strips.values[i], 1.0f);
        }
    m.emissive = emissive;
    m.normal_strength = 5.0f;
    return build_material(m);
}
} // namespace

Result<void> make_door(Output& out) {
    KS_ASSETGEN_TRY(out.material("door", door_leaf()));
    // Built again under each coarser Detail for the levels of detail (Output::model_levels).
    const auto build = [&] {
        Model model("door");
        Material leaf_material = textured("door_leaf", "door", vec4(1.0f), 1.0f, 1.0f);
        leaf_material.emissive_texture = "door_emissive";
        leaf_material.emissive = vec3(1.0f);
        const int leaf = model.add_material(leaf_material);
        // Painted steel casings (the diamond-plate relief under a light grey enamel). Bare metal here read as
        // a near-black slab: a dark metallic surface only reflects its surroundings, and the fast path's
        // per-vertex light has little of them to reflect.
        const int frame_mat = model.add_material(textured("door_frame", "metal", vec4(1.0f), 0.0f, 1.0f));
        const int handle_mat = model.add_material(plain("door_handle", vec3(0.7f), 1.0f, 0.25f));
        const int lamp = model.add_material(
            plain("door_lamp", vec3(0.1f, 0.4f, 0.15f), 0.0f, 0.3f, vec3(0.2f, 1.0f, 0.35f)));
        const int stripes = model.add_material(textured("door_frame_hazard", "door", vec4(1.0f), 1.0f, 1.0f));

        const int root = model.add_node("door", -1);
        // Frame: trims in front of and behind the leaves (|z| 0.09..0.3) so the leaves can slide between
        // them.
        const int frame = model.add_node("frame", root);
        Mesh& f = model.node(frame).part(frame_mat);
        for (float zs : {-1.0f, 1.0f}) {
            const float z = zs * 0.195f;
            // Pocket casings (x 2.5..4.5) cover the leaves when they slide open; a raised jamb frames the
            // opening.
            for (float xs : {-1.0f, 1.0f}) {
                f.append(rounded_box(vec3(2.0f, 5.55f, 0.21f), 0.04f, 1, 0.5f),
                         at(vec3(xs * 3.5f, 2.775f, z)));
                f.append(rounded_box(vec3(0.24f, 5.2f, 0.27f), 0.05f, 1, 0.5f),
                         at(vec3(xs * 2.62f, 2.6f, z + zs * 0.03f)));
            }
            f.append(rounded_box(vec3(9.0f, 0.55f, 0.21f), 0.04f, 1, 0.5f), at(vec3(0, 5.275f, z)));
            f.append(rounded_box(vec3(5.48f, 0.24f, 0.27f), 0.05f, 1, 0.5f),
                     at(vec3(0, 5.12f, z + zs * 0.03f)));
            model.node(frame).part(lamp).append(rounded_box(vec3(0.6f, 0.12f, 0.06f), 0.03f, 1),
                                                at(vec3(0, 5.3f, zs * 0.32f)));
            // A hazard-striped sill plate: the leaf map's foot band, uv-placed on this strip.
            Mesh sill = rounded_box(vec3(5.0f, 0.04f, 0.21f), 0.01f, 1, 1.0f, UvMode::PerFace);
            sill.transform_uvs(vec2(0.9f, 0.1f), vec2(0.05f, 0.86f));
            model.node(frame).part(stripes).append(sill, at(vec3(0, 0.02f, z)));
        }
        // Leaves: built once for door_l, mirrored for door_r so the hazard stripes meet as a chevron.
        Mesh leaf_mesh = rounded_box(vec3(kLeafW, kLeafH, kLeafD), 0.02f, 1, 1.0f, UvMode::PerFace);
        Mesh leaf_handles;
        for (float z : {-1.0f, 1.0f})
            leaf_handles.append(rounded_box(vec3(0.07f, 0.9f, 0.05f), 0.02f, 1),
                                at(vec3(-kLeafW * 0.5f + 0.35f, 2.4f - kLeafH * 0.5f, z * 0.085f)));
        const int door_l = model.add_node("door_l", root, vec3(kLeafW * 0.5f, 0, 0));
        model.node(door_l).part(leaf).append(leaf_mesh, at(vec3(0, kLeafH * 0.5f, 0)));
        model.node(door_l).part(handle_mat).append(leaf_handles, at(vec3(0, kLeafH * 0.5f, 0)));
        const int door_r = model.add_node("door_r", root, vec3(-kLeafW * 0.5f, 0, 0));
        const mat4 mirror = glm::scale(mat4(1.0f), vec3(-1, 1, 1));
        model.node(door_r).part(leaf).append(leaf_mesh, mirror * at(vec3(0, kLeafH * 0.5f, 0)));
        model.node(door_r).part(handle_mat).append(leaf_handles, mirror * at(vec3(0, kLeafH * 0.5f, 0)));
        return model;
    };
    return out.model_levels(build);
}

} // namespace ks::assetgen
