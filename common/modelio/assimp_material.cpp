// A model file's material as assimp reads it (assimp_material.h).
#include "modelio/assimp_material.h"

#include <assimp/material.h>

#include <initializer_list>
#include <string>

namespace ks::modelio {

namespace {

std::string texture_of(const aiMaterial& material, std::initializer_list<aiTextureType> types) {
    for (aiTextureType type : types) {
        aiString file;
        if (material.GetTextureCount(type) > 0 && material.GetTexture(type, 0, &file) == AI_SUCCESS)
            return file.C_Str();
    }
    return {};
}

} // namespace

ImportedMaterial read_material(const aiMaterial& src) {
    ImportedMaterial mat;
    aiString name;
    if (src.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) mat.name = name.C_Str();
    aiColor4D base(1, 1, 1, 1);
    if (src.Get(AI_MATKEY_BASE_COLOR, base) == AI_SUCCESS ||
        src.Get(AI_MATKEY_COLOR_DIFFUSE, base) == AI_SUCCESS)
        mat.base_color = Vec4(base.r, base.g, base.b, base.a);
    aiColor3D emissive(0, 0, 0);
    if (src.Get(AI_MATKEY_COLOR_EMISSIVE, emissive) == AI_SUCCESS)
        mat.emissive = Vec3(emissive.r, emissive.g, emissive.b);
    float strength = 1.0f;
    if (src.Get(AI_MATKEY_EMISSIVE_INTENSITY, strength) == AI_SUCCESS) mat.emissive *= strength;
    float f = 0;
    if (src.Get(AI_MATKEY_METALLIC_FACTOR, f) == AI_SUCCESS) mat.metallic = f;
    if (src.Get(AI_MATKEY_ROUGHNESS_FACTOR, f) == AI_SUCCESS) mat.roughness = f;
    int two_sided = 1; // absent (OBJ): both sides, the safe reading
    if (src.Get(AI_MATKEY_TWOSIDED, two_sided) == AI_SUCCESS) mat.double_sided = two_sided != 0;
    mat.textures.base_color = texture_of(src, {aiTextureType_BASE_COLOR, aiTextureType_DIFFUSE});
    mat.textures.normal = texture_of(src, {aiTextureType_NORMALS, aiTextureType_NORMAL_CAMERA});
    // glTF's metallicRoughness texture comes as UNKNOWN from assimp 5.2's glTF 2 reader.
    mat.textures.metal_rough =
        texture_of(src, {aiTextureType_UNKNOWN, aiTextureType_METALNESS, aiTextureType_DIFFUSE_ROUGHNESS});
    mat.textures.emissive = texture_of(src, {aiTextureType_EMISSIVE, aiTextureType_EMISSION_COLOR});
    return mat;
}

} // namespace ks::modelio
