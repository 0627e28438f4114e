#pragma once
// Shared pieces for the model recipes: material presets and placement helpers.
#include "gltf_writer.h"
#include "shapes.h"

#include <glm/gtc/matrix_transform.hpp>

namespace ks::assetgen {

inline constexpr float kPiF = 3.14159265358979f;

// A material whose maps are the PNG set <stem>_basecolor/_normal/_orm (factors multiply the maps).
Material textured(const std::string& name, const std::string& stem, vec4 tint = vec4(1.0f),
                  float metallic = 1.0f, float roughness = 1.0f);
// A material with factors only (small parts that need no texture).
Material plain(const std::string& name, vec3 srgb_color, float metallic, float roughness,
               vec3 emissive = vec3(0.0f));
// Converts an sRGB colour to the linear factor glTF expects.
vec3 linear_from_srgb(vec3 c);

// Maps a shape built along +y (lathes, cylinders) onto the +z (or -z, or +x) axis.
mat4 y_to_z();
mat4 y_to_minus_z();
mat4 y_to_x();
// Swaps x and z: outlines drawn in (z, y) and extruded along z become side profiles extruded along x.
mat4 swap_xz();
inline mat4 at(vec3 p) {
    return glm::translate(mat4(1.0f), p);
}

} // namespace ks::assetgen
