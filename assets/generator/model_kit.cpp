#include "model_kit.h"

#include <cmath>

namespace ks::assetgen {

vec3 linear_from_srgb(vec3 c) {
    auto f = [](float v) {
        return v <= 0.04045f ? v / 12.92f
                             : static_cast<float>(std::pow((static_cast<double>(v) + 0.055) / 1.055, 2.4));
    };
    return {f(c.r), f(c.g), f(c.b)};
}

Material textured(const std::string& name, const std::string& stem, vec4 tint, float metallic,
                  float roughness) {
    Material m;
    m.name = name;
    m.base_color = tint;
    m.metallic = metallic;
    m.roughness = roughness;
    m.basecolor_texture = stem + "_basecolor";
    m.normal_texture = stem + "_normal";
    m.orm_texture = stem + "_orm";
    return m;
}

Material plain(const std::string& name, vec3 srgb_color, float metallic, float roughness, vec3 emissive) {
    Material m;
    m.name = name;
    m.base_color = vec4(linear_from_srgb(srgb_color), 1.0f);
    m.metallic = metallic;
    m.roughness = roughness;
    m.emissive = emissive;
    return m;
}

mat4 y_to_z() {
    return glm::rotate(mat4(1.0f), kPiF / 2.0f, vec3(1, 0, 0));
}
mat4 y_to_minus_z() {
    return glm::rotate(mat4(1.0f), -kPiF / 2.0f, vec3(1, 0, 0));
}
mat4 y_to_x() {
    return glm::rotate(mat4(1.0f), -kPiF / 2.0f, vec3(0, 0, 1));
}
mat4 swap_xz() {
    mat4 m(0.0f);
    m[0] = vec4(0, 0, 1, 0); // x -> z
    m[1] = vec4(0, 1, 0, 0);
    m[2] = vec4(1, 0, 0, 0); // z -> x
    m[3] = vec4(0, 0, 0, 1);
    return m;
}

} // namespace ks::assetgen
