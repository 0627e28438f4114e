#include "modelio/model_writers.h"

#include "test_support.h"

#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include <cstring>
#include <fstream>
#include <sstream>

namespace ks::test {

namespace {

// The cube's 6 faces, 4 corners each, counter-clockwise seen from outside.
void cube_geometry(float h, std::vector<float>& positions, std::vector<std::uint16_t>& indices) {
    const float faces[6][4][3] = {
        {{h, -h, -h}, {h, h, -h}, {h, h, h}, {h, -h, h}},
        {{-h, -h, h}, {-h, h, h}, {-h, h, -h}, {-h, -h, -h}},
        {{-h, h, -h}, {-h, h, h}, {h, h, h}, {h, h, -h}},
        {{-h, -h, h}, {-h, -h, -h}, {h, -h, -h}, {h, -h, h}},
        {{-h, -h, h}, {h, -h, h}, {h, h, h}, {-h, h, h}},
        {{h, -h, -h}, {-h, -h, -h}, {-h, h, -h}, {h, h, -h}},
    };
    for (int f = 0; f < 6; ++f) {
        for (int c = 0; c < 4; ++c)
            for (int k = 0; k < 3; ++k) positions.push_back(faces[f][c][k]);
        const auto b = static_cast<std::uint16_t>(f * 4);
        for (std::uint16_t i : {0, 1, 2, 0, 2, 3}) indices.push_back(static_cast<std::uint16_t>(b + i));
    }
}

} // namespace

std::filesystem::path write_gltf_cube(const std::filesystem::path& dir, const std::string& name,
                                      const CubeOptions& o) {
    std::vector<float> positions;
    std::vector<std::uint16_t> indices;
    cube_geometry(o.half, positions, indices);
    positions[0] += o.poison;
    const std::size_t pos_bytes = positions.size() * sizeof(float);
    const std::size_t idx_bytes = indices.size() * sizeof(std::uint16_t);
    if (o.write_buffer) {
        std::ofstream bin(dir / (name + ".bin"), std::ios::binary);
        bin.write(reinterpret_cast<const char*>(positions.data()), static_cast<std::streamsize>(pos_bytes));
        bin.write(reinterpret_cast<const char*>(indices.data()), static_cast<std::streamsize>(idx_bytes));
    }
    std::ostringstream j;
    j << R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)";
    j << R"("nodes":[{"mesh":0,"translation":[)" << o.translation.x << "," << o.translation.y << ","
      << o.translation.z << R"(],"scale":[)" << o.node_scale << "," << o.node_scale << "," << o.node_scale
      << "]}],";
    j << R"("meshes":[{"name":"cube","primitives":[{"attributes":{"POSITION":0},"indices":1,"material":0}]}],)";
    j << R"("materials":[{"name":"paint","pbrMetallicRoughness":{"baseColorFactor":[0.8,0.2,0.1,1],)"
      << R"("metallicFactor":0.25,"roughnessFactor":0.5)";
    if (!o.texture.empty()) j << R"(,"baseColorTexture":{"index":0})";
    j << "}}],";
    if (!o.texture.empty()) j << R"("textures":[{"source":0}],"images":[{"uri":")" << o.texture << R"("}],)";
    j << R"("buffers":[{"uri":")" << name << ".bin\",\"byteLength\":" << pos_bytes + idx_bytes << "}],";
    j << R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":)" << pos_bytes
      << R"(},{"buffer":0,"byteOffset":)" << pos_bytes << R"(,"byteLength":)" << idx_bytes << "}],";
    j << R"("accessors":[{"bufferView":0,"componentType":5126,"count":24,"type":"VEC3","min":[)" << -o.half
      << "," << -o.half << "," << -o.half << "],\"max\":[" << o.half << "," << o.half << "," << o.half
      << "]},";
    j << R"({"bufferView":1,"componentType":5123,"count":36,"type":"SCALAR"}]})";
    return write_file(dir / (name + ".gltf"), j.str());
}

std::filesystem::path write_obj_cube(const std::filesystem::path& dir, const std::string& name, float half,
                                     const std::string& texture) {
    std::ostringstream mtl;
    mtl << "newmtl paint\nKd 0.1 0.6 0.3\n";
    if (!texture.empty()) mtl << "map_Kd " << texture << "\n";
    write_file(dir / (name + ".mtl"), mtl.str());
    std::ostringstream obj;
    obj << "mtllib " << name << ".mtl\no cube\n";
    for (int i = 0; i < 8; ++i)
        obj << "v " << (i & 1 ? half : -half) << " " << (i & 2 ? half : -half) << " "
            << (i & 4 ? half : -half) << "\n";
    obj << "usemtl paint\n";
    // Corners numbered 1 + x + 2y + 4z; each face counter-clockwise from outside.
    obj << "f 1 5 7 3\nf 2 4 8 6\nf 1 2 6 5\nf 3 7 8 4\nf 1 3 4 2\nf 5 6 8 7\n";
    return write_file(dir / (name + ".obj"), obj.str());
}

bool convert_with_assimp(const std::filesystem::path& source, const std::filesystem::path& target,
                         const char* format_id) {
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(source.string(), 0);
    if (!scene) return false;
    Assimp::Exporter exporter;
    return exporter.Export(scene, format_id, target.string()) == AI_SUCCESS;
}

} // namespace ks::test
