// Light fixtures: the standing spotlight (`floor_light`, 4 tall, head tilted 30 degrees down along -Z) and
// the hanging ceiling lamp (`top_light`, origin at the ceiling, 2 deep). Lenses use the material
// `light_emissive`, which the renderer scales with the light's on/off state; `light_origin` marks where
// the light itself sits.
#include "catalog.h"
#include "material_builder.h"
#include "model_kit.h"
#include "noise.h"

#include <algorithm>
#include <cmath>

namespace ks::assetgen {
namespace {

// A Fresnel lens seen face-on: concentric rings, brightest at the centre, as an emissive map that also
// serves as the lens colour.
Image lens_pattern() {
    constexpr int n = 128;
    Image image(n, n);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const float dx = (static_cast<float>(x) + 0.5f) / n - 0.5f,
                        dy = (static_cast<float>(y) + 0.5f) / n - 0.5f;
            const float r = std::sqrt(dx * dx + dy * dy) * 2.0f;
            const float ring = 0.5f + 0.5f * std::cos(r * 40.0f);
            const float v = std::clamp(1.0f - r * 0.35f, 0.0f, 1.0f) * (0.82f + 0.18f * ring);
            image.at(x, y) = Color(v, v * 0.97f, v * 0.9f, 1.0f);
        }
    return image;
}

Material lens_material() {
    Material m;
    m.name = "light_emissive";
    m.base_color = vec4(1.0f);
    m.metallic = 0.0f;
    m.roughness = 0.15f;
    m.basecolor_texture = "light_lens_emissive";
    m.emissive_texture = "light_lens_emissive";
    m.emissive = vec3(1.0f, 0.96f, 0.86f);
    return m;
}

// Lathe uvs map the whole cap of a disc to one ring of the lens map; planar uvs read better.
Mesh lens_disc(float radius, int segments) {
    Mesh m = cylinder(radius, 0.01f, segments);
    for (Vertex& v : m.vertices) v.uv = vec2(v.position.x, v.position.z) / (2.0f * radius) + vec2(0.5f);
    m.compute_tangents();
    return m;
}
} // namespace

Result<void> make_floor_light(Output& out) {
    KS_ASSETGEN_TRY(out.texture("light_lens_emissive", lens_pattern(), PngChannels::Rgb));
    // Built again under each coarser Detail for the levels of detail (Output::model_levels).
    const auto build = [&] {
        Model model("floor_light");
        const int body =
            model.add_material(textured("lamp_body", "metal", vec4(0.16f, 0.17f, 0.18f, 1.0f), 1.0f, 1.0f));
        const int paint = model.add_material(plain("lamp_paint", vec3(0.85f, 0.6f, 0.1f), 0.3f, 0.45f));
        const int rubber = model.add_material(plain("lamp_rubber", vec3(0.05f), 0.0f, 0.9f));
        const int lens = model.add_material(lens_material());

        const int root = model.add_node("floor_light", -1);
        Node& stand = model.node(root);
        // Tripod: three splayed legs with feet, a hub, a telescoping pole.
        for (int k = 0; k < 3; ++k) {
            const float a = static_cast<float>(k) * 2.0f * kPiF / 3.0f + kPiF / 6.0f;
            const vec3 dir(std::cos(a), 0, std::sin(a));
            const vec3 foot = dir * 1.1f + vec3(0, 0.05f, 0), hub(0, 1.3f, 0);
            const vec3 leg = hub - foot;
            const float len = glm::length(leg);
            const vec3 axis = glm::normalize(glm::cross(vec3(0, 1, 0), leg));
            const float tilt = std::acos(glm::dot(vec3(0, 1, 0), leg / len));
            stand.part(body).append(cylinder(0.04f, len, 8), at(foot) * glm::rotate(mat4(1.0f), tilt, axis));
            stand.part(rubber).append(cylinder(0.09f, 0.06f, 12, 0.015f), at(foot - vec3(0, 0.05f, 0)));
            // Braces from the legs to the pole.
            const vec3 mid = foot + leg * 0.45f, collar(0, 0.75f, 0);
            const vec3 brace = collar - mid;
            const vec3 baxis = glm::normalize(glm::cross(vec3(0, 1, 0), brace));
            stand.part(body).append(
                cylinder(0.018f, glm::length(brace), 6),
                at(mid) * glm::rotate(mat4(1.0f), std::acos(glm::dot(vec3(0, 1, 0), glm::normalize(brace))),
                                      baxis));
        }
        stand.part(paint).append(cylinder(0.11f, 0.22f, 16, 0.03f), at(vec3(0, 1.2f, 0)));
        stand.part(body).append(cylinder(0.06f, 2.1f, 12), at(vec3(0, 1.3f, 0)));
        stand.part(body).append(cylinder(0.045f, 0.9f, 12), at(vec3(0, 3.0f, 0)));
        stand.part(paint).append(cylinder(0.08f, 0.12f, 14, 0.02f), at(vec3(0, 2.95f, 0)));
        stand.part(body).append(cylinder(0.05f, 0.06f, 12), at(vec3(0, 0.72f, 0)));
        // Yoke holding the head.
        stand.part(paint).append(rounded_box(vec3(0.1f, 0.06f, 0.62f), 0.02f, 1),
                                 at(vec3(0, 3.6f, 0)) * glm::rotate(mat4(1.0f), kPiF / 2, vec3(0, 1, 0)));
        for (float x : {-0.29f, 0.29f})
            stand.part(paint).append(rounded_box(vec3(0.05f, 0.3f, 0.08f), 0.015f, 1), at(vec3(x, 3.75f, 0)));

        // Lamp head: a can aimed along its local -Z, tilted 30 degrees down; pivot on the yoke at 3.8.
        const int head =
            model.add_node("lamp_head", root, vec3(0, 3.8f, 0), glm::angleAxis(-kPiF / 6.0f, vec3(1, 0, 0)));
        Node& h = model.node(head);
        LatheOptions can;
        can.segments = 24;
        can.crease_degrees = 30.0f;
        // Profile along the can's axis (lathe y = -Z): back cap, body, front bezel lip that shades the lens.
        h.part(paint).append(lathe({{0.0f, -0.2f},
                                    {0.16f, -0.2f},
                                    {0.2f, -0.14f},
                                    {0.22f, 0.12f},
                                    {0.25f, 0.16f},
                                    {0.25f, 0.2f},
                                    {0.2f, 0.2f},
                                    {0.2f, 0.14f}},
                                   can),
                             y_to_minus_z());
        h.part(body).append(tube(0.255f, 0.235f, 0.04f, 24), at(vec3(0, 0, -0.2f)) * y_to_minus_z());
        for (int k = 0; k < 5; ++k) // cooling fins on the back
            h.part(body).append(cylinder(0.17f - static_cast<float>(k) * 0.01f, 0.015f, 20),
                                at(vec3(0, 0, 0.2f + static_cast<float>(k) * 0.03f)) * y_to_z());
        for (float x : {-0.24f, 0.24f})
            h.part(body).append(cylinder(0.045f, 0.05f, 12),
                                at(vec3(x, 0, 0)) * y_to_x() * at(vec3(0, -0.025f, 0)));
        h.part(lens).append(lens_disc(0.2f, 28), at(vec3(0, 0, -0.145f)) * y_to_minus_z());
        model.add_node("light_origin", head, vec3(0, 0, -0.16f));
        return model;
    };
    return out.model_levels(build);
}

Result<void> make_top_light(Output& out) {
    if (!out.has_written_texture("light_lens_emissive"))
        KS_ASSETGEN_TRY(out.texture("light_lens_emissive", lens_pattern(), PngChannels::Rgb));
    // Built again under each coarser Detail for the levels of detail (Output::model_levels).
    const auto build = [&] {
        Model model("top_light");
        const int shade_mat = model.add_material(plain("lamp_shade", vec3(0.25f, 0.48f, 0.4f), 0.5f, 0.35f));
        const int body =
            model.add_material(textured("lamp_body", "metal", vec4(0.3f, 0.31f, 0.33f, 1.0f), 1.0f, 1.0f));
        const int lens = model.add_material(lens_material());
        const int root = model.add_node("top_light", -1);
        Node& n = model.node(root);
        // Ceiling canopy, two chains of links, the industrial dome shade (3 wide like the reference's lamp).
        n.part(body).append(cylinder(0.3f, 0.08f, 20, 0.02f), at(vec3(0, -0.08f, 0)));
        n.part(body).append(cylinder(0.025f, 1.0f, 8), at(vec3(0, -1.08f, 0)));
        for (int k = 0; k < 8; ++k)
            n.part(body).append(torus(0.045f, 0.01f, 10, 6),
                                at(vec3(0, -0.15f - static_cast<float>(k) * 0.11f, 0)) *
                                    glm::rotate(mat4(1.0f), kPiF / 2 + (k % 2) * kPiF / 2, vec3(1, 0, 0)) *
                                    glm::rotate(mat4(1.0f), (k % 2) * kPiF / 2, vec3(0, 0, 1)));
        n.part(body).append(cylinder(0.12f, 0.18f, 16, 0.03f), at(vec3(0, -1.25f, 0)));
        LatheOptions dome;
        dome.segments = 36;
        dome.crease_degrees = 25.0f;
        // Outer skin from the rim up to the neck, then the inner skin back down (a shade with thickness).
        n.part(shade_mat).append(lathe({{1.5f, -1.92f},
                                        {1.52f, -1.88f},
                                        {1.3f, -1.72f},
                                        {0.8f, -1.45f},
                                        {0.35f, -1.3f},
                                        {0.14f, -1.26f},
                                        {0.12f, -1.3f},
                                        {0.33f, -1.34f},
                                        {0.78f, -1.49f},
                                        {1.28f, -1.76f},
                                        {1.47f, -1.9f},
                                        {1.5f, -1.92f}},
                                       dome),
                                 mat4(1.0f));
        n.part(body).append(torus(1.5f, 0.025f, 36, 6), at(vec3(0, -1.91f, 0)));
        // Diffuser bowl under the bulb.
        LatheOptions bowl;
        bowl.segments = 28;
        n.part(lens).append(lathe({{0.0f, -1.98f},
                                   {0.25f, -1.95f},
                                   {0.42f, -1.85f},
                                   {0.5f, -1.7f},
                                   {0.45f, -1.6f},
                                   {0.0f, -1.6f}},
                                  bowl),
                            mat4(1.0f));
        model.add_node("light_origin", root, vec3(0, -1.85f, 0));
        return model;
    };
    return out.model_levels(build);
}

} // namespace ks::assetgen
