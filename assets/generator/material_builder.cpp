#include "material_builder.h"

#include <algorithm>

namespace ks::assetgen {

MaterialMaps build_material(const MaterialFields& f) {
    MaterialMaps maps;
    maps.basecolor = f.color;
    maps.normal =
        normal_from_height(f.height, f.normal_strength * static_cast<float>(f.height.width) / 512.0f);
    Field ao = cavity_occlusion(f.height, f.cavity_radius, f.cavity_strength);
    Field rough = f.roughness, metal = f.metallic;
    for (float& v : rough.values) v = std::clamp(v, 0.04f, 1.0f);
    for (float& v : metal.values) v = std::clamp(v, 0.0f, 1.0f);
    maps.orm = pack_rgb(ao, rough, metal);
    maps.emissive = f.emissive;
    if (f.keep_height) {
        Field h = f.height;
        for (float& v : h.values) v = std::clamp(v, 0.0f, 1.0f);
        maps.height = std::move(h);
    }
    return maps;
}

MaterialFields blank_material(int size, Color color, float roughness, float metallic) {
    MaterialFields f;
    f.color = Image(size, size, color);
    f.height = Field(size, size, 0.5f);
    f.roughness = Field(size, size, roughness);
    f.metallic = Field(size, size, metallic);
    return f;
}

} // namespace ks::assetgen
