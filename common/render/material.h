#pragma once
// A metallic-roughness material (glTF's model). Maps left at 0 are absent; the shader then uses the factors.
#include "core/math.h"

#include <string>

namespace ks::render {

struct Material {
    std::string name;
    Vec4 base_factor{1.0f};     // linear rgb, alpha
    Vec3 emissive_factor{0.0f}; // linear
    float metallic = 0.0f;
    float roughness = 1.0f;
    float bump_strength = 0.02f; // height map scale in world units, used when there is no normal map
    unsigned base_map = 0, normal_map = 0, orm_map = 0, emissive_map = 0, height_map = 0;
    // The fast path's level surfaces: base colour x occlusion in one map and the ORM map's mean metalness
    // (TextureCache::get_occluded_base); 0 when not made.
    unsigned fast_base_map = 0;
    float fast_metallic = 0.0f;
    // fast_base_map's alpha holds the ORM map's metalness (the base map was opaque): a fast-path model reads
    // occlusion and metalness from its one base lookup (the fast_model "orm in base" programs).
    bool fast_metal_in_alpha = false;
    bool placeholder = false; // some map failed to load (magenta checker)
    // Both sides of each triangle are seen (glTF's doubleSided; files that cannot say so, OBJ's, are). A
    // single-sided material's back faces are culled where the renderer draws models (RendererSettings::
    // cull_single_sided): they cost llvmpipe setup and binning and are hidden by the front faces anyway.
    bool double_sided = true;
    int id = 0; // unique per material, the renderer's sort key
};

} // namespace ks::render
