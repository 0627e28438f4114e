// The enemy robot: a blocky industrial machine on a four-wheeled base, 3.0 tall. It faces local +X; its
// right arm is on +Z. Node origins are joint pivots; arms hang along -y at rest (see docs/assets.md).
#include "catalog.h"
#include "material_builder.h"
#include "model_kit.h"
#include "noise.h"

#include <algorithm>
#include <cmath>

namespace ks::assetgen {
namespace {

// Painted industrial-yellow steel with panel seams, rivets, chipped edges showing bare metal and grime.
// Tiled in world units (one repeat per unit) over the body parts.
MaterialMaps robot_paint() {
    constexpr int n = 512;
    MaterialFields m = blank_material(n, srgb(222, 160, 36), 0.42f, 0.0f);
    const Field broad = fractal_noise(n, n, NoiseKind::Perlin, 4, 5, 101);
    const Field fine = fractal_noise(n, n, NoiseKind::Value, 96, 2, 102);
    const Field seams = panel_seams(n, n, {0.0f, 320.0f}, {0.0f, 192.0f}, 4.0f);
    Field rivets(n, n), wear(n, n);
    for (float x : {0.0f, 320.0f})
        for (int k = 0; k < 16; ++k)
            add_bolt(m.height, Vec2f(x + 9.0f, 16.0f + static_cast<float>(k) * 32.0f), 4.0f, 0.1f, &rivets);
    for (float y : {0.0f, 192.0f})
        for (int k = 0; k < 16; ++k)
            add_bolt(m.height, Vec2f(16.0f + static_cast<float>(k) * 32.0f, y + 9.0f), 4.0f, 0.1f, &rivets);
    Rng rng(0x2060Du);
    add_scratches(wear, rng, 90, 8.0f, 50.0f, 2.0f);
    // Chips: paint flaked off in blotches where broad noise peaks.
    const Field chips = threshold(fractal_noise(n, n, NoiseKind::Perlin, 16, 4, 103), 0.68f, 0.72f);
    const Field cavity = cavity_occlusion(seams, 5, 1.0f);
    const Field dirt = grime(n, n, cavity, 104, 0.6f);
    for (size_t i = 0; i < m.color.pixels.size(); ++i) {
        const float bare = std::clamp(std::max(wear.values[i], chips.values[i]), 0.0f, 1.0f);
        Color paint =
            mix(srgb(206, 142, 28), srgb(236, 176, 48), broad.values[i] * 0.7f + fine.values[i] * 0.3f);
        paint = mix(paint, srgb(96, 76, 44), dirt.values[i] * 0.6f);
        const Color steel = mix(srgb(120, 120, 122), srgb(176, 176, 180), fine.values[i]);
        Color c = mix(paint, steel, bare);
        c = mix(c, srgb(40, 34, 26), seams.values[i] * 0.8f);
        c = mix(c, srgb(150, 150, 150), rivets.values[i] * 0.7f);
        m.color.pixels[i] = c;
        m.height.values[i] += -seams.values[i] * 0.25f - bare * 0.03f + fine.values[i] * 0.01f;
        m.roughness.values[i] = 0.38f + fine.values[i] * 0.1f + dirt.values[i] * 0.25f - bare * 0.05f;
        m.metallic.values[i] = std::max(bare, rivets.values[i]);
    }
    m.normal_strength = 5.0f;
    return build_material(m);
}

// One wheel (tyre with tread blocks, hub and bolts), axis along z, centred at its origin.
Mesh wheel(float radius, float width) {
    // A tyre: rounded shoulders, open toward the axle where the hub covers it.
    const float h = width * 0.5f, b = width * 0.22f, inner = radius * 0.55f;
    LatheOptions o;
    o.segments = 16;
    o.crease_degrees = 50.0f;
    Mesh w;
    w.append(
        lathe({{inner, -h}, {radius - b, -h}, {radius, -h + b}, {radius, h - b}, {radius - b, h}, {inner, h}},
              o),
        y_to_z());
    return w;
}
// Decal atlas (256 x 256): the top half a hazard-striped plate, the bottom half the unit number plate.
Image robot_decals(const Font& font) {
    constexpr int n = 256;
    Field plate(n, n), stripes(n, n), ink(n, n), frame(n, n);
    fill_rounded_rect(plate, Vec2f(0, 0), Vec2f(n, n), 0.0f);
    hazard_stripes(stripes, Vec2f(0, 0), Vec2f(n, 128), 40.0f);
    for (float y0 : {0.0f, 128.0f}) {
        fill_rounded_rect(frame, Vec2f(0, y0), Vec2f(n, y0 + 128), 0.0f);
        fill_rounded_rect(frame, Vec2f(6, y0 + 6), Vec2f(n - 6, y0 + 122), 4.0f, Stroke{0.0f, Paint::Set});
    }
    font.draw_centred(ink, "K-07", Vec2f(128, 192), 84.0f);
    Image image(n, n, srgb(236, 182, 40));
    blend(image, stripes, srgb(24, 22, 20));
    blend(image, ink, srgb(24, 22, 20));
    blend(image, frame, srgb(40, 36, 30));
    return image;
}

// Appends a painted part; its uvs are shifted by where it sits, so the seams and rivets of the tiled paint
// map do not line up through the centre of every part.
void add_painted(Mesh& dst, Mesh part, const mat4& place) {
    const vec3 p(place[3]);
    part.transform_uvs(vec2(1.0f), vec2(0.31f + p.x * 0.37f + p.z * 0.53f, 0.17f - p.y * 0.5f));
    dst.append(part, place);
}

// The robot's geometry at the thread's Detail (shapes.h): its levels of detail are this run again.
Model robot_model() {
    Model model("robot");
    const int paint = model.add_material(textured("robot_paint", "robot", vec4(1.0f), 1.0f, 1.0f));
    // Body parts tile the paint map once per 2 units so panel seams stay sparse on small parts.
    const float uv = 0.5f;
    const int dark = model.add_material(textured("robot_joint", "metal", vec4(vec3(0.5f), 1.0f), 0.5f, 1.0f));
    // The tyres are open toward the axle (the hub covers it from the side): seen from below, their inside
    // shows, so the renderer must not cull their back faces.
    Material rubber_material = plain("robot_rubber", vec3(0.07f), 0.0f, 0.88f);
    rubber_material.double_sided = true;
    const int rubber = model.add_material(rubber_material);
    const int visor = model.add_material(
        plain("robot_visor", vec3(0.15f, 0.02f, 0.02f), 0.0f, 0.2f, vec3(1.0f, 0.12f, 0.04f)));
    const int steel = model.add_material(plain("robot_steel", vec3(0.72f), 1.0f, 0.3f));
    Material decal_material = plain("robot_decal", vec3(1.0f), 0.0f, 0.5f);
    decal_material.basecolor_texture = "robot_decals_basecolor";
    const int decal = model.add_material(decal_material);
    // A thin plate whose +X face shows one half of the decal atlas (top: hazard stripes, bottom: number).
    auto decal_plate = [](vec3 size, bool number) {
        Mesh m = rounded_box(size, 0.0f, 0, 1.0f, UvMode::PerFace);
        m.transform_uvs(vec2(1.0f, 0.5f), vec2(0.0f, number ? 0.5f : 0.0f));
        return m;
    };

    const int root = model.add_node("robot", -1);
    // Base: chassis with four wheels; pivot at axle height.
    const float axle = 0.3f;
    const int base = model.add_node("wheel_base", root, vec3(0, axle, 0));
    Mesh& base_paint = model.node(base).part(paint);
    add_painted(base_paint, rounded_box(vec3(1.15f, 0.34f, 0.92f), 0.07f, 1, uv), at(vec3(0, 0.12f, 0)));
    add_painted(base_paint, rounded_box(vec3(0.55f, 0.14f, 0.62f), 0.04f, 1, uv), at(vec3(-0.08f, 0.34f, 0)));
    Mesh& base_dark = model.node(base).part(dark);
    for (float z : {-0.47f, 0.47f}) // fenders over the wheels
        base_dark.append(rounded_box(vec3(1.2f, 0.06f, 0.16f)), at(vec3(0, 0.33f, z * 1.12f)));
    base_dark.append(rounded_box(vec3(0.08f, 0.16f, 0.7f), 0.03f, 1), at(vec3(0.6f, 0.05f, 0))); // bumper
    base_dark.append(cylinder(0.22f, 0.18f, 14, 0.03f), at(vec3(0, 0.38f, 0)));                  // waist ring
    model.node(base).part(decal).append(decal_plate(vec3(0.01f, 0.11f, 0.56f), false),
                                        at(vec3(0.645f, 0.05f, 0)));
    Mesh& base_lamp = model.node(base).part(visor);
    for (float z : {-0.3f, 0.3f})
        base_lamp.append(cylinder(0.04f, 0.03f, 12), at(vec3(0.64f, 0.1f, z)) * y_to_x());

    const int wheels = model.add_node("wheels", base);
    for (float x : {-0.36f, 0.36f})
        for (float z : {-0.56f, 0.56f}) {
            const mat4 place = at(vec3(x, 0, z));
            model.node(wheels).part(rubber).append(wheel(axle, 0.2f), place);
            model.node(wheels).part(steel).append(cylinder(0.15f, 0.22f, 12),
                                                  place * at(vec3(0, 0, -0.11f)) * y_to_z());
            for (int b = 0; b < 3; ++b) {
                const float a = static_cast<float>(b) * 2.0f * kPiF / 3.0f;
                model.node(wheels).part(dark).append(
                    cylinder(0.02f, 0.24f, 6),
                    place * at(vec3(std::cos(a) * 0.09f, std::sin(a) * 0.09f, -0.12f)) * y_to_z());
            }
        }

    // Chest: pivot at the waist (world y 0.78).
    const float waist = 0.78f;
    const int chest = model.add_node("chest", base, vec3(0, waist - axle, 0));
    Mesh& chest_paint = model.node(chest).part(paint);
    add_painted(chest_paint, rounded_box(vec3(0.78f, 0.9f, 0.98f), 0.1f, 2, uv),
                at(vec3(0, 0.75f, 0))); // torso
    add_painted(chest_paint, rounded_box(vec3(0.7f, 0.32f, 1.16f), 0.08f, 2, uv),
                at(vec3(-0.02f, 1.28f, 0))); // shoulder yoke
    add_painted(chest_paint, rounded_box(vec3(0.16f, 0.5f, 0.62f), 0.05f, 1, uv),
                at(vec3(-0.42f, 0.78f, 0))); // back pack
    Mesh& chest_dark = model.node(chest).part(dark);
    chest_dark.append(cylinder(0.2f, 0.3f, 14, 0.02f), at(vec3(0, 0.0f, 0))); // spine
    chest_dark.append(rounded_box(vec3(0.06f, 0.38f, 0.5f), 0.02f, 1),
                      at(vec3(0.4f, 0.7f, 0))); // chest plate
    for (int v = 0; v < 5; ++v)                 // vents
        chest_dark.append(rounded_box(vec3(0.04f, 0.03f, 0.42f)),
                          at(vec3(0.445f, 0.56f + static_cast<float>(v) * 0.07f, 0)));
    chest_dark.append(cylinder(0.14f, 0.12f, 16, 0.02f), at(vec3(0, 1.42f, 0))); // neck
    for (float z : {-0.36f, 0.36f})
        chest_dark.append(cylinder(0.035f, 0.3f, 10), at(vec3(-0.52f, 0.6f, z))); // exhaust pipes
    model.node(chest).part(decal).append(decal_plate(vec3(0.01f, 0.12f, 0.24f), true),
                                         at(vec3(0.395f, 1.0f, -0.2f)));
    Mesh& chest_glow = model.node(chest).part(visor);
    chest_glow.append(cylinder(0.06f, 0.03f, 16), at(vec3(0.43f, 1.0f, 0.28f)) * y_to_x()); // status lamp

    // Arms: shoulder pivots at world y 2.06, z = +-0.66; each segment hangs along -y from its pivot.
    const float shoulder_y = 2.06f - waist;
    auto build_arm = [&](const std::string& side, float z, bool gun) {
        const int arm = model.add_node("arm_" + side, chest, vec3(0, shoulder_y, z));
        Mesh& a_dark = model.node(arm).part(dark);
        a_dark.append(cylinder(0.17f, 0.22f, 14, 0.03f), at(vec3(0, 0, -0.11f)) * y_to_z()); // shoulder drum
        add_painted(model.node(arm).part(paint), rounded_box(vec3(0.3f, 0.26f, 0.3f), 0.07f, 1, uv),
                    at(vec3(0, 0.04f, z > 0 ? 0.05f : -0.05f)));
        add_painted(model.node(arm).part(paint), rounded_box(vec3(0.26f, 0.5f, 0.26f), 0.06f, 1, uv),
                    at(vec3(0, -0.36f, 0)));
        a_dark.append(cylinder(0.03f, 0.42f, 8), at(vec3(0.16f, -0.55f, 0))); // hydraulic rod
        const int forearm = model.add_node("forearm_" + side, arm, vec3(0, -0.66f, 0));
        Mesh& f_dark = model.node(forearm).part(dark);
        f_dark.append(cylinder(0.1f, 0.26f, 14, 0.02f), at(vec3(0, 0, -0.13f)) * y_to_z()); // elbow
        add_painted(model.node(forearm).part(paint), rounded_box(vec3(0.29f, 0.46f, 0.29f), 0.07f, 1, uv),
                    at(vec3(0, -0.3f, 0)));
        model.node(forearm).part(steel).append(rounded_box(vec3(0.26f, 0.06f, 0.26f), 0.02f, 1),
                                               at(vec3(0, -0.5f, 0)));
        const int hand = model.add_node("hand_" + side, forearm, vec3(0, -0.56f, 0));
        Mesh& h_dark = model.node(hand).part(dark);
        h_dark.append(rounded_box(vec3(0.16f, 0.12f, 0.16f), 0.03f, 1), at(vec3(0, -0.06f, 0))); // wrist
        for (int f = 0; f < 3; ++f) { // claw fingers
            const float a = static_cast<float>(f) * 2.0f * kPiF / 3.0f;
            h_dark.append(rounded_box(vec3(0.05f, 0.16f, 0.05f)),
                          at(vec3(std::cos(a) * 0.08f, -0.19f, std::sin(a) * 0.08f)) *
                              glm::rotate(mat4(1.0f), 0.25f, vec3(-std::sin(a), 0, std::cos(a))));
        }
        if (gun) {
            // A stubby blaster gripped in the claw, barrel continuing the arm (so it aims where the arm
            // points).
            Mesh& g = model.node(hand).part(dark);
            g.append(rounded_box(vec3(0.2f, 0.36f, 0.17f), 0.04f, 1), at(vec3(0.02f, -0.3f, 0)));
            g.append(rounded_box(vec3(0.08f, 0.2f, 0.1f), 0.02f, 1), at(vec3(0.15f, -0.26f, 0))); // magazine
            model.node(hand).part(steel).append(cylinder(0.05f, 0.2f, 16, 0.01f), at(vec3(0, -0.66f, 0)));
            model.node(hand).part(dark).append(tube(0.07f, 0.04f, 0.08f, 12), at(vec3(0, -0.72f, 0)));
            model.node(hand).part(visor).append(rounded_box(vec3(0.03f, 0.2f, 0.06f), 0.01f, 1),
                                                at(vec3(-0.09f, -0.3f, 0)));
            model.add_node("hand_r_tip", hand, vec3(0, -0.72f, 0));
        }
    };
    build_arm("r", 0.6f, true);
    build_arm("l", -0.6f, false);

    // Head: pivot on the neck (world y 2.32).
    const int head = model.add_node("head", chest, vec3(0, 2.28f - waist, 0));
    Mesh& h_paint = model.node(head).part(paint);
    add_painted(h_paint, rounded_box(vec3(0.56f, 0.44f, 0.6f), 0.1f, 2, uv), at(vec3(-0.02f, 0.27f, 0)));
    Mesh& h_dark = model.node(head).part(dark);
    h_dark.append(rounded_box(vec3(0.1f, 0.2f, 0.56f), 0.05f, 1), at(vec3(0.25f, 0.3f, 0))); // visor housing
    for (int k = 0; k < 3; ++k) // speaker grille under the visor
        h_dark.append(rounded_box(vec3(0.03f, 0.022f, 0.26f)),
                      at(vec3(0.265f, 0.16f - static_cast<float>(k) * 0.04f, 0)));
    for (float z : {-0.31f, 0.31f})
        h_dark.append(cylinder(0.11f, 0.06f, 14, 0.02f),
                      at(vec3(0, 0.27f, z)) * at(vec3(0, 0, -0.03f)) * y_to_z());
    h_dark.append(cylinder(0.018f, 0.2f, 8), at(vec3(-0.12f, 0.42f, 0.18f))); // antenna
    model.node(head).part(visor).append(rounded_box(vec3(0.04f, 0.09f, 0.46f), 0.02f, 1),
                                        at(vec3(0.3f, 0.31f, 0)));
    model.node(head).part(visor).append(capsule(0.035f, 0.1f, 8, 3),
                                        at(vec3(-0.12f, 0.62f, 0.18f))); // beacon; top = 3.0
    return model;
}
} // namespace

Result<void> make_robot(Output& out) {
    KS_ASSETGEN_TRY(out.material("robot", robot_paint()));
    KS_ASSETGEN_TRY(out.texture("robot_decals_basecolor", robot_decals(out.font()), PngChannels::Rgb));
    return out.model_levels(robot_model);
}

} // namespace ks::assetgen
