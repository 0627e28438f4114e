#pragma once
// Turns the fields a material recipe paints (colour, height, roughness, metallic) into its PBR maps.
#include "output.h"
#include "surface_ops.h"

namespace ks::assetgen {

struct MaterialFields {
    Image color;     // sRGB base colour
    Field height;    // 0..1, also the source of the normal map and of cavity occlusion
    Field roughness; // 0..1
    Field metallic;  // 0..1
    float normal_strength = 4.0f;
    int cavity_radius = 4;
    float cavity_strength = 3.0f;
    bool keep_height = false;      // also write <name>_height.png
    std::optional<Image> emissive; // sRGB
};

MaterialMaps build_material(const MaterialFields& fields);
// A convenience for recipes: a fresh set of fields of one size with constant starting values.
MaterialFields blank_material(int size, Color color, float roughness, float metallic);

} // namespace ks::assetgen
