// Pickups: 0.8 cubes centred on their origin (root node `pickup`), bevelled, with the same icon on every
// face and a glowing trim in the pickup's colour: health (red cross on white, green trim), ammo (brass
// rounds on olive, amber trim), shield (blue shield on navy, blue trim).
#include "catalog.h"
#include "material_builder.h"
#include "model_kit.h"
#include "noise.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace ks::assetgen {
namespace {
constexpr int kPickupSize = 256;

struct PickupStyle {
    std::string name;
    Color body, icon, trim;
    std::uint32_t seed;
    std::function<void(Field&)> draw_icon; // icon coverage, centred in the face
};

void cross_icon(Field& f) {
    fill_rounded_rect(f, Vec2f(104, 58), Vec2f(152, 198), 8.0f, Stroke{1.0f, Paint::Max, 2.0f});
    fill_rounded_rect(f, Vec2f(58, 104), Vec2f(198, 152), 8.0f, Stroke{1.0f, Paint::Max, 2.0f});
}

void bullets_icon(Field& f) {
    for (int k = 0; k < 3; ++k) {
        const float x = 88.0f + static_cast<float>(k) * 40.0f;
        fill_rounded_rect(f, Vec2f(x - 14, 110), Vec2f(x + 14, 196), 3.0f,
                          Stroke{1.0f, Paint::Max, 2.0f}); // casing
        fill_polygon(f, {{x - 13, 106}, {x + 13, 106}, {x + 9, 82}, {x, 62}, {x - 9, 82}},
                     Stroke{1.0f, Paint::Max, 2.0f});
        fill_rounded_rect(f, Vec2f(x - 16, 186), Vec2f(x + 16, 196), 2.0f, Stroke{0.7f, Paint::Set}); // rim
        draw_line(f, Vec2f(x - 14, 108), Vec2f(x + 14, 108), 2.0f, Stroke{0.6f, Paint::Set});         // crimp
    }
}

void shield_icon(Field& f) {
    std::vector<Vec2f> outline;
    // Flat top with rounded shoulders, curving to a point at the bottom.
    outline.push_back({70, 70});
    outline.push_back({128, 56});
    outline.push_back({186, 70});
    for (int k = 0; k <= 10; ++k) {
        const float t = static_cast<float>(k) / 10.0f;
        outline.push_back({186.0f - 58.0f * t * t, 70.0f + 130.0f * t});
    }
    for (int k = 9; k >= 1; --k) {
        const float t = static_cast<float>(k) / 10.0f;
        outline.push_back({70.0f + 58.0f * t * t, 70.0f + 130.0f * t});
    }
    fill_polygon(f, outline, Stroke{1.0f, Paint::Max, 3.0f});
    // An inner chevron cut into the shield.
    fill_polygon(f, {{96, 104}, {128, 124}, {160, 104}, {160, 124}, {128, 150}, {96, 124}},
                 Stroke{0.35f, Paint::Set});
}

MaterialMaps pickup_maps(const PickupStyle& s) {
    MaterialFields m = blank_material(kPickupSize, s.body, 0.35f, 0.0f);
    const Field noise = fractal_noise(kPickupSize, kPickupSize, NoiseKind::Perlin, 4, 4, s.seed);
    Field frame(kPickupSize, kPickupSize), trim(kPickupSize, kPickupSize), icon(kPickupSize, kPickupSize),
        scratches(kPickupSize, kPickupSize);
    // Raised outer frame (the bevel band and a little more), with a glowing groove inside it.
    fill_rounded_rect(frame, Vec2f(0, 0), Vec2f(kPickupSize, kPickupSize), 0.0f);
    fill_rounded_rect(frame, Vec2f(30, 30), Vec2f(kPickupSize - 30, kPickupSize - 30), 10.0f,
                      Stroke{0.0f, Paint::Set, 4.0f});
    fill_rounded_rect(trim, Vec2f(34, 34), Vec2f(kPickupSize - 34, kPickupSize - 34), 12.0f);
    fill_rounded_rect(trim, Vec2f(41, 41), Vec2f(kPickupSize - 41, kPickupSize - 41), 8.0f,
                      Stroke{0.0f, Paint::Set});
    s.draw_icon(icon);
    Rng rng(s.seed);
    add_scratches(scratches, rng, 30, 5.0f, 25.0f, 1.0f);
    Image emissive(kPickupSize, kPickupSize, Color(0, 0, 0, 1));
    for (size_t i = 0; i < m.color.pixels.size(); ++i) {
        Color c = mix(s.body * 0.9f, s.body, noise.values[i]);
        c = mix(c, s.body * 0.55f, frame.values[i]);
        c = mix(c, s.trim, trim.values[i]);
        c = mix(c, s.icon, icon.values[i]);
        c = mix(c, srgb(190, 190, 190), scratches.values[i] * 0.4f * (1.0f - icon.values[i]));
        c.a = 1.0f;
        m.color.pixels[i] = c;
        m.height.values[i] = 0.5f + frame.values[i] * 0.15f + icon.values[i] * 0.1f - trim.values[i] * 0.06f;
        m.roughness.values[i] =
            0.35f + noise.values[i] * 0.1f + frame.values[i] * 0.1f - icon.values[i] * 0.1f;
        m.metallic.values[i] = frame.values[i] * 0.6f + scratches.values[i] * 0.4f;
        const glm::vec3 glow =
            glm::vec3(s.trim) * trim.values[i] + glm::vec3(s.icon) * icon.values[i] * 0.35f;
        emissive.pixels[i] = Color(glm::min(glow, glm::vec3(1.0f)), 1.0f);
    }
    m.emissive = emissive;
    m.normal_strength = 3.0f;
    m.cavity_radius = 3;
    return build_material(m);
}
} // namespace

Result<void> make_pickups(Output& out) {
    const std::vector<PickupStyle> styles = {
        {"pickup_health", srgb(232, 232, 226), srgb(214, 24, 30), srgb(60, 240, 110), 701, cross_icon},
        {"pickup_ammo", srgb(84, 92, 56), srgb(232, 170, 60), srgb(255, 170, 30), 702, bullets_icon},
        {"pickup_shield", srgb(30, 46, 84), srgb(90, 170, 255), srgb(70, 160, 255), 703, shield_icon},
    };
    for (const PickupStyle& s : styles) {
        KS_ASSETGEN_TRY(out.material(s.name, pickup_maps(s)));
        const auto build = [&] {
            Model model(s.name);
            Material mat = textured(s.name, s.name, vec4(1.0f), 1.0f, 1.0f);
            mat.emissive_texture = s.name + "_emissive";
            mat.emissive = vec3(1.0f);
            const int material = model.add_material(mat);
            const int root = model.add_node("pickup", -1);
            model.node(root).part(material).append(rounded_box(vec3(0.8f), 0.06f, 2, 1.0f, UvMode::PerFace));
            return model;
        };
        KS_ASSETGEN_TRY(out.model_levels(build));
    }
    return ok();
}

} // namespace ks::assetgen
