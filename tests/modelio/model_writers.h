#pragma once
// Small model files the modelio tests write themselves: a unit cube as glTF (external .bin buffer), as OBJ
// with its MTL, a .glb with an embedded PNG, and converted by assimp's own exporters to .glb and FBX.
#include "core/math.h"

#include <filesystem>
#include <string>
#include <vector>

namespace ks::test {

struct CubeOptions {
    Vec3 translation{0.0f};   // the node's
    float node_scale = 1.0f;  // the node's uniform scale
    float half = 0.5f;        // the cube's half size in the mesh
    std::string texture;      // base colour texture uri ("" = none)
    bool write_buffer = true; // false: the .bin the glTF names is not written
    float poison = 0.0f;      // added to the first vertex's x (a NaN makes it non-finite)
    bool double_sided =
        false; // the material's doubleSided (written only when true, as glTF's default is false)
};

// Writes `name`.gltf and `name`.bin into `dir`: a cube (24 vertices, 12 triangles) under one node, with a
// material whose base colour factor is (0.8, 0.2, 0.1, 1), metallic 0.25, roughness 0.5. Returns the .gltf.
std::filesystem::path write_gltf_cube(const std::filesystem::path& dir, const std::string& name,
                                      const CubeOptions& options = {});

// Writes `name`.obj and `name`.mtl: a cube of half size `half` with material "paint" (Kd 0.1 0.6 0.3,
// map_Kd `texture` when not empty). Returns the .obj.
std::filesystem::path write_obj_cube(const std::filesystem::path& dir, const std::string& name,
                                     float half = 0.5f, const std::string& texture = {});

struct GlbOptions {
    std::string image;              // the embedded image file's bytes ("" = no texture)
    std::string mime = "image/png"; // the image's mimeType
    int texture_source = 0;         // the texture's image index (1: an image the file does not hold)
};

// Writes `name`.glb: a binary glTF holding a cube of half size 0.5 with UVs (each face the whole image) and
// material "painted" whose base colour texture is options.image, embedded in the file's binary chunk.
std::filesystem::path write_glb_cube(const std::filesystem::path& dir, const std::string& name,
                                     const GlbOptions& options);

// An RGBA image (4 bytes a pixel, top row first) encoded as a PNG file's bytes (stb_image_write).
std::string png_bytes(int width, int height, const std::vector<unsigned char>& rgba);

// Reads `source` with assimp and writes it with assimp's exporter `format_id` ("glb2", "fbx") to `target`;
// false when assimp cannot.
bool convert_with_assimp(const std::filesystem::path& source, const std::filesystem::path& target,
                         const char* format_id);

} // namespace ks::test
