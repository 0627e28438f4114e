#pragma once
// Designers' models read through assimp (glTF 2.0 .gltf/.glb, OBJ with its MTL, FBX) into a plain mesh: no
// OpenGL, no node hierarchy (every node's transform is baked into its meshes' vertices), the file's units and
// up axis turned into the level's (one metre is one level unit, +Y up). Bad files are refused as an Error
// that names the file and what is wrong; nothing here throws or aborts on bad input (docs/models.md).
#include "core/math.h"
#include "core/result.h"
#include "geometry/aabb.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace ks::modelio {

// Texture files named by a material, as paths relative to the model file's folder (as the file writes them),
// or "*N" for the texture inside the file at ImportedModel::images[N] (a .glb's images, an FBX's embedded
// media). Empty: none.
struct MaterialTextures {
    std::string base_color;
    std::string normal;
    std::string metal_rough; // glTF's metallicRoughness (B metal, G rough); OBJ's map_Pm/map_Pr if any
    std::string emissive;
};

struct ImportedMaterial {
    std::string name;
    Vec4 base_color{1.0f};
    float metallic = 0.0f;
    float roughness = 1.0f;
    Vec3 emissive{0.0f};
    // glTF's doubleSided (assimp's AI_MATKEY_TWOSIDED); true where the file cannot say (OBJ, most FBX).
    bool double_sided = true;
    MaterialTextures textures;
};

// One mesh of the file placed by its node (a mesh two nodes use appears twice): triangles only.
struct ImportedMesh {
    std::vector<Vec3> positions; // level units, +Y up
    std::vector<Vec3> normals;   // unit length, one per position
    std::vector<Vec2> uvs;       // one per position (0 where the file has none); v = 0 is the image's top
    std::vector<std::uint32_t> indices;
    int material = 0; // index into ImportedModel::materials (there is always at least one)
};

// One coarser level of detail of a model (modelio/model_lod.h): each mesh simplified by meshoptimizer to
// about `ratio` of its triangles, its vertices the ones the simplified triangles still use.
struct ModelLod {
    float ratio = 1.0f;               // the fraction of the triangles asked for
    std::size_t triangle_count = 0;   // what the simplifier reached (all meshes)
    float error = 0.0f;               // meshoptimizer's largest deviation from the full model, in model units
    std::vector<ImportedMesh> meshes; // ImportedMesh::material as in the full model; a mesh gone to nothing
                                      // is left out
};

// A texture stored inside the model file, decoded to 8-bit RGBA, top row first (modelio's
// embedded_textures.h; stb_image for PNG/JPEG/..., assimp's raw texels as they are).
struct EmbeddedImage {
    std::string name; // as the material named it ("*0", or an FBX's file name), for messages
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba; // width * height * 4 bytes; empty for a texture no material uses
    std::uint64_t hash = 0;         // of the size and pixels: a changed file gives a new texture-cache key
};

struct ImportedModel {
    std::filesystem::path path;
    std::vector<ImportedMesh> meshes;
    std::vector<ModelLod> lods; // the coarser levels, finest first (level 0 is `meshes`); empty until
                                // build_lods (import_cached builds them)
    std::vector<ImportedMaterial> materials;
    std::vector<EmbeddedImage> images; // one per texture inside the file, indexed by a material's "*N"
    geometry::Aabb bounds;
    std::size_t triangle_count = 0;
    float unit_scale = 1.0f; // what the file's units were multiplied by to become level units
    std::string axes;        // how the up axis was read, for messages: "glTF: +Y up, metres", ...
};

struct ImportLimits {
    std::size_t max_triangles = 1'000'000; // after node instancing: a prop, not a scanned city
    std::uintmax_t max_file_bytes = std::uintmax_t{256} << 20;
    float max_extent = 1.0e4f;  // level units along any axis: the level's own extent
    float min_extent = 1.0e-4f; // the largest side must be at least this: a model with no size is a mistake
    std::uint64_t max_texture_pixels = std::uint64_t{4096} * 4096; // per embedded texture (64 MiB as RGBA)
};

// The extensions import_model reads, lower case with the dot.
const std::vector<std::string>& supported_extensions();
bool has_supported_extension(const std::filesystem::path& path);

// Reads `path`. An Error (its `where` is the file) for a missing, empty or too large file, an unsupported
// extension, a file assimp cannot read (truncated, corrupt, a glTF whose buffer is missing), a mesh with a
// non-finite vertex, no triangles at all, more than limits.max_triangles, a size outside the limits, a
// material texture file that is missing, an embedded texture the file does not hold or that does not decode
// (or has more than limits.max_texture_pixels pixels).
Result<ImportedModel> import_model(const std::filesystem::path& path, const ImportLimits& limits = {});

} // namespace ks::modelio
