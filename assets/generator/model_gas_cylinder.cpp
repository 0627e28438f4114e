// The explosive gas cylinder: radius 0.5, height 2, red body with a yellow/black hazard band and a flame
// warning label, a brass valve with a hand wheel on top. Its map wraps once around the body (u) and spans
// its height (v, top of the image at the top).
#include "catalog.h"
#include "material_builder.h"
#include "model_kit.h"
#include "noise.h"

#include <algorithm>
#include <cmath>

namespace ks::assetgen {
namespace {
constexpr int kCylinderSize = 512;
constexpr float kCylinderHeight = 2.0f, kRadius = 0.5f;

// Image row for a height on the cylinder (the map spans y = 0..2 from the bottom row to the top row).
float row_at(float y) {
    return (1.0f - y / kCylinderHeight) * kCylinderSize;
}

// The GHS "flammable" pictogram's flame: a tongue of fire above a base bar, drawn in `size` pixels.
void draw_flame(Field& f, Vec2f centre, float size) {
    static const Vec2f kOutline[] = {{0.0f, -1.0f},    {0.22f, -0.62f}, {0.42f, -0.32f}, {0.5f, 0.0f},
                                     {0.42f, 0.28f},   {0.2f, 0.42f},   {0.0f, 0.46f},   {-0.2f, 0.42f},
                                     {-0.42f, 0.28f},  {-0.5f, 0.02f},  {-0.44f, -0.3f}, {-0.3f, -0.12f},
                                     {-0.26f, -0.46f}, {-0.1f, -0.7f}};
    std::vector<Vec2f> pts;
    for (const Vec2f& p : kOutline) pts.push_back(centre + p * size);
    fill_polygon(f, pts);
    // The cool inner core, cut back out of the flame.
    std::vector<Vec2f> core;
    for (const Vec2f& p : kOutline)
        core.push_back(centre + Vec2f(p.x * 0.45f, 0.2f + (p.y + 0.2f) * 0.4f) * size);
    fill_polygon(f, core, Stroke{0.0f, Paint::Set});
    fill_rounded_rect(f, centre + Vec2f(-0.6f, 0.56f) * size, centre + Vec2f(0.6f, 0.7f) * size, 1.0f);
}

MaterialMaps cylinder_paint(const Font& font) {
    MaterialFields m = blank_material(kCylinderSize, srgb(176, 26, 22), 0.35f, 0.0f);
    const Field broad = fractal_noise(kCylinderSize, kCylinderSize, NoiseKind::Perlin, 4, 5, 601);
    const Field fine = fractal_noise(kCylinderSize, kCylinderSize, NoiseKind::Value, 128, 2, 602);
    Field band(kCylinderSize, kCylinderSize), stripes(kCylinderSize, kCylinderSize),
        label(kCylinderSize, kCylinderSize), ink(kCylinderSize, kCylinderSize),
        flame(kCylinderSize, kCylinderSize), scratches(kCylinderSize, kCylinderSize),
        weld(kCylinderSize, kCylinderSize);
    // Hazard band between heights 1.3 and 1.45 all the way round.
    fill_rounded_rect(band, Vec2f(-10, row_at(1.45f)), Vec2f(kCylinderSize + 10, row_at(1.3f)), 0.0f);
    hazard_stripes(stripes, Vec2f(-10, row_at(1.45f)), Vec2f(kCylinderSize + 10, row_at(1.3f)), 32.0f);
    // Weld seams where the shoulder and foot meet the body.
    for (float y : {1.55f, 0.12f})
        paint_sdf(
            weld, Vec2f(-4, row_at(y) - 4), Vec2f(kCylinderSize + 4, row_at(y) + 4),
            [&](Vec2f p) { return std::abs(p.y - row_at(y)) - 2.0f; }, Stroke{1.0f, Paint::Max, 2.0f});
    // Label on the front (u 0.36..0.64 faces the +Z side at u = 0.5... see lathe uvs), heights 0.55..1.15.
    const Vec2f lo(kCylinderSize * 0.34f, row_at(1.17f)), hi(kCylinderSize * 0.66f, row_at(0.5f));
    fill_rounded_rect(label, lo, hi, 6.0f);
    const Vec2f diamond_c((lo.x + hi.x) * 0.5f, lo.y + 62.0f);
    const float d = 44.0f;
    // GHS-style: a red-bordered diamond holding a black flame.
    fill_polygon(flame, {diamond_c + Vec2f(0, -d), diamond_c + Vec2f(d, 0), diamond_c + Vec2f(0, d),
                         diamond_c + Vec2f(-d, 0)});
    fill_polygon(flame,
                 {diamond_c + Vec2f(0, -d + 7), diamond_c + Vec2f(d - 7, 0), diamond_c + Vec2f(0, d - 7),
                  diamond_c + Vec2f(-d + 7, 0)},
                 Stroke{0.0f, Paint::Set});
    draw_flame(ink, diamond_c + Vec2f(0, 2.0f), 28.0f);
    font.draw_centred(ink, "FLAMMABLE", Vec2f(diamond_c.x, hi.y - 38.0f), 22.0f);
    font.draw_centred(ink, "GAS", Vec2f(diamond_c.x, hi.y - 14.0f), 22.0f);
    Rng rng(0x6A5u);
    add_scratches(scratches, rng, 110, 6.0f, 40.0f, 1.6f);
    const Field dirt = grime(kCylinderSize, kCylinderSize, constant_like(broad, 1.0f), 603, 0.7f);
    for (int y = 0; y < kCylinderSize; ++y)
        for (int x = 0; x < kCylinderSize; ++x) {
            const size_t i = static_cast<size_t>(y) * kCylinderSize + x;
            const float low = std::clamp(
                (static_cast<float>(y) - kCylinderSize * 0.7f) / (kCylinderSize * 0.3f), 0.0f, 1.0f);
            Color c =
                mix(srgb(150, 20, 18), srgb(196, 34, 28), broad.values[i] * 0.7f + fine.values[i] * 0.3f);
            c = mix(c, mix(srgb(240, 184, 20), srgb(22, 20, 18), stripes.values[i]), band.values[i]);
            c = mix(c, srgb(236, 232, 220), label.values[i]);
            c = mix(c, srgb(20, 20, 20), ink.values[i] * label.values[i]);
            c = mix(c, srgb(210, 24, 20), flame.values[i]);
            c = mix(c, srgb(120, 120, 124), scratches.values[i] * 0.75f);
            c = mix(c, srgb(70, 50, 36),
                    std::clamp(dirt.values[i] * 0.4f + low * 0.35f * broad.values[i], 0.0f, 1.0f));
            m.color.pixels[i] = c;
            m.height.values[i] = 0.5f + weld.values[i] * 0.1f + label.values[i] * 0.01f -
                                 scratches.values[i] * 0.03f + fine.values[i] * 0.01f;
            m.roughness.values[i] = 0.32f + broad.values[i] * 0.15f + label.values[i] * 0.3f + low * 0.2f -
                                    scratches.values[i] * 0.1f;
            m.metallic.values[i] = scratches.values[i] * 0.9f;
        }
    m.normal_strength = 4.0f;
    return build_material(m);
}
} // namespace

Result<void> make_gas_cylinder(Output& out) {
    KS_ASSETGEN_TRY(out.material("gas_cylinder", cylinder_paint(out.font())));
    // Built again under each coarser Detail for the levels of detail (Output::model_levels).
    const auto build = [&] {
        Model model("gas_cylinder");
        const int paint =
            model.add_material(textured("gas_cylinder_paint", "gas_cylinder", vec4(1.0f), 1.0f, 1.0f));
        const int brass = model.add_material(plain("brass", vec3(0.85f, 0.66f, 0.3f), 1.0f, 0.3f));
        const int steel =
            model.add_material(textured("valve_steel", "metal", vec4(0.6f, 0.6f, 0.62f, 1.0f), 1.0f, 1.0f));
        const int wheel_mat = model.add_material(plain("valve_wheel", vec3(0.1f, 0.1f, 0.11f), 0.0f, 0.6f));
        const int root = model.add_node("gas_cylinder", -1);
        Node& n = model.node(root);
        LatheOptions body;
        body.segments = 32;
        body.v_by_height = true;
        body.v_scale = 1.0f / kCylinderHeight;
        body.crease_degrees = 30.0f;
        // Foot ring, body, domed shoulder, neck; uv u starts at +Z so the label (u 0.34..0.66) faces -Z...
        // the lathe's u = 0.5 is at angle pi, i.e. the -Z side: rotate by pi so the label faces +Z (the model
        // front).
        std::vector<vec2> profile = {{0.0f, 0.02f}, {0.4f, 0.02f},    {0.43f, 0.0f},   {0.47f, 0.0f},
                                     {0.47f, 0.1f}, {kRadius, 0.12f}, {kRadius, 1.55f}};
        for (int k = 1; k <= 8; ++k) {
            const float a = static_cast<float>(k) / 8.0f * (kPiF / 2.0f) * 0.92f;
            profile.push_back({0.14f + (kRadius - 0.14f) * std::cos(a), 1.55f + 0.27f * std::sin(a)});
        }
        profile.insert(profile.end(), {{0.12f, 1.84f}, {0.0f, 1.84f}});
        n.part(paint).append(lathe(profile, body), glm::rotate(mat4(1.0f), kPiF, vec3(0, 1, 0)));
        // Valve: brass body, side outlet, spindle, hand wheel with spokes, safety cap ring.
        n.part(brass).append(cylinder(0.1f, 0.1f, 16, 0.015f), at(vec3(0, 1.83f, 0)));
        n.part(brass).append(rounded_box(vec3(0.12f, 0.1f, 0.12f), 0.02f, 1),
                             at(vec3(0, 1.97f - 0.05f - 0.03f, 0)));
        n.part(brass).append(cylinder(0.03f, 0.12f, 12, 0.005f), at(vec3(0.05f, 1.9f, 0)) * y_to_x());
        n.part(brass).append(cylinder(0.04f, 0.03f, 12, 0.005f), at(vec3(0.16f, 1.9f, 0)) * y_to_x());
        n.part(steel).append(cylinder(0.018f, 0.06f, 10), at(vec3(0, 1.94f, 0)));
        n.part(wheel_mat).append(torus(0.075f, 0.012f, 20, 6), at(vec3(0, 1.985f, 0)));
        for (int k = 0; k < 3; ++k)
            n.part(wheel_mat).append(rounded_box(vec3(0.15f, 0.012f, 0.016f)),
                                     at(vec3(0, 1.985f, 0)) * glm::rotate(mat4(1.0f),
                                                                          static_cast<float>(k) * kPiF / 3.0f,
                                                                          vec3(0, 1, 0)));
        n.part(steel).append(tube(0.2f, 0.17f, 0.08f, 24), at(vec3(0, 1.76f, 0)));
        return model;
    };
    return out.model_levels(build);
}

} // namespace ks::assetgen
