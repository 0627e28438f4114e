// A render material from a model file's material (model_material.h).
#include "render/model_material.h"

namespace ks::render {

Material make_model_material(const modelio::ImportedMaterial& src, const std::filesystem::path& dir,
                             TextureCache& textures, const MapSource& maps) {
    Material mat;
    mat.name = src.name;
    mat.base_factor = src.base_color;
    mat.emissive_factor = src.emissive;
    mat.metallic = src.metallic;
    mat.roughness = src.roughness;
    mat.double_sided = src.double_sided;
    auto map = [&](const std::string& name, ColorSpace space) -> unsigned {
        if (name.empty()) return 0u;
        const Texture& t = maps(name, space);
        if (t.placeholder) mat.placeholder = true;
        return t.id;
    };
    const modelio::MaterialTextures& names = src.textures;
    mat.base_map = map(names.base_color, ColorSpace::Srgb);
    mat.normal_map = map(names.normal, ColorSpace::Linear);
    mat.orm_map = map(names.metal_rough, ColorSpace::Linear);
    mat.emissive_map = map(names.emissive, ColorSpace::Srgb);
    if (mat.base_map && mat.orm_map && !mat.placeholder && names.base_color[0] != '*' &&
        names.metal_rough[0] != '*') {
        const TextureCache::OccludedBase& packed =
            textures.get_occluded_base(dir / names.base_color, dir / names.metal_rough);
        mat.fast_base_map = packed.id;
        mat.fast_metallic = packed.mean_metallic;
        mat.fast_metal_in_alpha = packed.id != 0 && packed.metal_in_alpha;
    }
    return mat;
}

} // namespace ks::render
