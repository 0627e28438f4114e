// The simulation control console the player must reach: footprint 2.94 (x) x 5.34 (z), 4 tall, the big
// screen facing local -X (material `screen_emissive`), a sloped button desk and a red shutdown button.
#include "catalog.h"
#include "material_builder.h"
#include "model_kit.h"
#include "noise.h"
#include "screen_ui.h"

#include <algorithm>
#include <cmath>

namespace ks::assetgen {
namespace {
constexpr float kHalfX = 1.47f, kHalfZ = 2.67f, kPanelHeight = 4.0f;

// Console housing: blue-grey enamel over steel, panel seams with screws, louvred vents, wear and dirt.
MaterialMaps console_paint() {
    constexpr int n = 512;
    MaterialFields m = blank_material(n, srgb(88, 100, 112), 0.5f, 0.0f);
    const Field broad = fractal_noise(n, n, NoiseKind::Perlin, 4, 5, 501);
    const Field fine = fractal_noise(n, n, NoiseKind::Value, 128, 2, 502);
    const Field seams = panel_seams(n, n, {0.0f, 256.0f}, {0.0f, 340.0f}, 4.0f);
    Field vents(n, n), screws(n, n), wear(n, n);
    for (int k = 0; k < 8; ++k)
        fill_rounded_rect(vents, Vec2f(300, 40.0f + static_cast<float>(k) * 28.0f),
                          Vec2f(470, 54.0f + static_cast<float>(k) * 28.0f), 7.0f,
                          Stroke{1.0f, Paint::Max, 5.0f});
    for (Vec2f p : {Vec2f(12, 12), Vec2f(244, 12), Vec2f(12, 328), Vec2f(244, 328), Vec2f(268, 12),
                    Vec2f(500, 12), Vec2f(268, 328), Vec2f(500, 328), Vec2f(12, 352), Vec2f(244, 352),
                    Vec2f(268, 352), Vec2f(500, 352)})
        add_bolt(m.height, p, 5.0f, 0.1f, &screws, true);
    Rng rng(0xC0A5u);
    add_scratches(wear, rng, 70, 8.0f, 50.0f, 1.5f);
    const Field dirt = grime(n, n, cavity_occlusion(seams, 5, 1.0f), 503, 0.5f);
    for (size_t i = 0; i < m.color.pixels.size(); ++i) {
        Color c = mix(srgb(80, 92, 104), srgb(104, 116, 128), broad.values[i] * 0.7f + fine.values[i] * 0.3f);
        c = mix(c, srgb(150, 156, 160), wear.values[i] * 0.7f);
        c = mix(c, srgb(56, 52, 46), dirt.values[i] * 0.5f);
        c = mix(c, srgb(24, 26, 30), std::max(seams.values[i], vents.values[i] * 0.9f));
        c = mix(c, srgb(170, 170, 170), screws.values[i] * 0.8f);
        m.color.pixels[i] = c;
        m.height.values[i] += -seams.values[i] * 0.25f - vents.values[i] * 0.3f - wear.values[i] * 0.02f;
        m.roughness.values[i] = 0.42f + fine.values[i] * 0.12f + dirt.values[i] * 0.2f;
        m.metallic.values[i] = std::max(wear.values[i], screws.values[i]);
    }
    m.normal_strength = 5.0f;
    return build_material(m);
}

Material display_material(const std::string& name, const std::string& stem) {
    Material m;
    m.name = name;
    m.base_color = vec4(1.0f);
    m.roughness = 0.12f;
    m.metallic = 0.0f;
    m.basecolor_texture = stem + "_basecolor";
    m.emissive_texture = stem + "_emissive";
    m.emissive = vec3(1.0f);
    return m;
}
} // namespace

Result<void> make_control_panel(Output& out) {
    KS_ASSETGEN_TRY(out.material("control_panel", console_paint()));
    const Display screen = simulation_control_screen(out.font());
    KS_ASSETGEN_TRY(out.texture("screen_basecolor", screen.basecolor, PngChannels::Rgb));
    KS_ASSETGEN_TRY(out.texture("screen_emissive", screen.emissive, PngChannels::Rgb));
    const Display desk = button_desk(out.font());
    KS_ASSETGEN_TRY(out.texture("control_desk_basecolor", desk.basecolor, PngChannels::Rgb));
    KS_ASSETGEN_TRY(out.texture("control_desk_emissive", desk.emissive, PngChannels::Rgb));

    // Built again under each coarser Detail for the levels of detail (Output::model_levels).
    const auto build = [&] {
        Model model("control_panel");
        const int body = model.add_material(textured("panel_body", "control_panel", vec4(1.0f), 1.0f, 1.0f));
        const int trim =
            model.add_material(textured("panel_trim", "metal", vec4(0.2f, 0.21f, 0.23f, 1.0f), 1.0f, 1.0f));
        const int screen_mat = model.add_material(display_material("screen_emissive", "screen"));
        const int desk_mat = model.add_material(display_material("desk_emissive", "control_desk"));
        const int button_mat = model.add_material(
            plain("shutdown_button", vec3(0.8f, 0.05f, 0.03f), 0.0f, 0.3f, vec3(0.9f, 0.05f, 0.02f)));
        const int hazard_mat =
            model.add_material(plain("hazard_yellow", vec3(0.95f, 0.72f, 0.05f), 0.0f, 0.5f));
        const int lamp = model.add_material(
            plain("panel_lamp", vec3(0.2f, 0.6f, 0.7f), 0.0f, 0.3f, vec3(0.3f, 0.85f, 1.0f)));

        const int root = model.add_node("control_panel", -1);
        Node& n = model.node(root);
        const float uv = 0.5f;
        const float tower_front = 0.25f; // x of the tower's screen face
        // Tower at the back holding the screen, with a cap that overhangs a little.
        n.part(body).append(
            rounded_box(vec3(kHalfX - tower_front, kPanelHeight - 0.12f, 2 * kHalfZ), 0.06f, 1, uv),
            at(vec3((kHalfX + tower_front) * 0.5f, (kPanelHeight - 0.12f) * 0.5f, 0)));
        n.part(trim).append(rounded_box(vec3(kHalfX - tower_front + 0.04f, 0.12f, 2 * kHalfZ), 0.04f, 1, uv),
                            at(vec3((kHalfX + tower_front) * 0.5f - 0.02f, kPanelHeight - 0.06f, 0)));
        n.part(lamp).append(rounded_box(vec3(0.03f, 0.05f, 2 * kHalfZ - 0.4f), 0.01f, 1),
                            at(vec3(tower_front - 0.005f, kPanelHeight - 0.2f, 0)));
        // Screen bezel and the screen, 4.4 x 2.1, facing -X.
        n.part(trim).append(rounded_box(vec3(0.08f, 2.3f, 4.6f), 0.05f, 2, uv),
                            at(vec3(tower_front - 0.02f, 2.65f, 0)));
        Mesh glass = rounded_box(vec3(0.02f, 2.1f, 4.4f), 0.0f, 0, 1.0f, UvMode::PerFace);
        n.part(screen_mat).append(glass, at(vec3(tower_front - 0.065f, 2.65f, 0)));
        // Lower cabinet in front of the tower, with a kick plate.
        const float cab_top = 1.0f;
        n.part(body).append(rounded_box(vec3(kHalfX + tower_front, cab_top, 2 * kHalfZ - 0.1f), 0.05f, 1, uv),
                            at(vec3((tower_front - kHalfX) * 0.5f, cab_top * 0.5f, 0)));
        n.part(trim).append(
            rounded_box(vec3(kHalfX + tower_front - 0.1f, 0.12f, 2 * kHalfZ - 0.2f), 0.02f, 1, uv),
            at(vec3((tower_front - kHalfX) * 0.5f - 0.02f, 0.06f, 0)));
        // Sloped desk: a wedge rising toward the tower, topped by the button desk display.
        const float slope_front = -kHalfX, slope_back = tower_front, rise = 0.38f;
        n.part(body).append(extrude({{slope_front, cab_top},
                                     {slope_back, cab_top},
                                     {slope_back, cab_top + rise},
                                     {slope_front, cab_top + 0.08f}},
                                    2 * kHalfZ - 0.1f, uv),
                            mat4(1.0f));
        const float angle = std::atan2(rise - 0.08f, slope_back - slope_front);
        const float desk_len = std::hypot(rise - 0.08f, slope_back - slope_front);
        const mat4 desk_frame =
            at(vec3((slope_front + slope_back) * 0.5f, cab_top + (0.08f + rise) * 0.5f + 0.005f, 0)) *
            glm::rotate(mat4(1.0f), angle, vec3(0, 0, 1));
        // The desk display: its +Y face carries the map; uv rotated so the labels read from the -X side.
        Mesh desk_panel = rounded_box(vec3(desk_len - 0.3f, 0.02f, 3.0f), 0.0f, 0, 1.0f, UvMode::PerFace);
        for (Vertex& v : desk_panel.vertices)
            v.uv =
                vec2(1.0f - (v.position.z / 3.0f + 0.5f), 1.0f - (v.position.x / (desk_len - 0.3f) + 0.5f));
        desk_panel.compute_tangents();
        n.part(desk_mat).append(desk_panel, desk_frame * at(vec3(0, 0.01f, -0.7f)));
        // The shutdown button: hazard collar, guard ring, big red mushroom cap.
        const mat4 button_at = desk_frame * at(vec3(0.05f, 0.02f, 1.65f));
        n.part(hazard_mat).append(cylinder(0.42f, 0.04f, 32, 0.01f), button_at);
        n.part(trim).append(tube(0.34f, 0.3f, 0.1f, 32), button_at);
        n.part(button_mat)
            .append(lathe({{0.0f, 0.0f},
                           {0.22f, 0.0f},
                           {0.22f, 0.1f},
                           {0.28f, 0.12f},
                           {0.29f, 0.17f},
                           {0.22f, 0.23f},
                           {0.0f, 0.24f}}),
                    button_at);
        // Side handles and a hazard edge on the desk front.
        n.part(hazard_mat)
            .append(rounded_box(vec3(0.06f, 0.06f, 2 * kHalfZ - 0.2f), 0.02f, 1),
                    at(vec3(-kHalfX + 0.03f, cab_top + 0.05f, 0)));
        for (float z : {-1.0f, 1.0f})
            n.part(trim).append(rounded_box(vec3(1.0f, 0.08f, 0.06f), 0.03f, 1),
                                at(vec3(0.85f, 2.0f, z * (kHalfZ - 0.02f))));
        return model;
    };
    return out.model_levels(build);
}

} // namespace ks::assetgen
