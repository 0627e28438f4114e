#include "modelio/model_writers.h"

#include "test_support.h"

#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include <stb_image_write.h>

#include <cstdint>
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
    j << "}";
    if (o.double_sided) j << R"(,"doubleSided":true)";
    j << "}],";
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

namespace {

template <typename T>
void append_raw(std::string& out, const std::vector<T>& values) {
    out.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

void append_u32(std::string& out, std::uint32_t v) {
    for (int shift = 0; shift < 32; shift += 8) out.push_back(static_cast<char>((v >> shift) & 0xffu));
}

void pad_to_4(std::string& s, char with) {
    while (s.size() % 4 != 0) s.push_back(with);
}

} // namespace

std::filesystem::path write_glb_cube(const std::filesystem::path& dir, const std::string& name,
                                     const GlbOptions& o) {
    std::vector<float> positions;
    std::vector<std::uint16_t> indices;
    cube_geometry(0.5f, positions, indices);
    std::vector<float> uvs;
    for (int f = 0; f < 6; ++f) uvs.insert(uvs.end(), {0, 1, 1, 1, 1, 0, 0, 0});
    std::string bin;
    append_raw(bin, positions);
    const std::size_t uv_at = bin.size();
    append_raw(bin, uvs);
    const std::size_t idx_at = bin.size();
    append_raw(bin, indices);
    pad_to_4(bin, '\0');
    const std::size_t image_at = bin.size();
    bin += o.image;
    const std::size_t bin_length = bin.size();
    pad_to_4(bin, '\0');

    std::ostringstream j;
    j << R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)";
    j << R"("meshes":[{"name":"cube","primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1},)"
      << R"("indices":2,"material":0}]}],)";
    j << R"("materials":[{"name":"painted","pbrMetallicRoughness":{"metallicFactor":0)";
    if (!o.image.empty()) j << R"(,"baseColorTexture":{"index":0})";
    j << "}}],";
    if (!o.image.empty())
        j << R"("textures":[{"source":)" << o.texture_source << R"(}],"images":[{"bufferView":3,"mimeType":")"
          << o.mime << R"("}],)";
    j << R"("buffers":[{"byteLength":)" << bin_length << "}],";
    j << R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":)" << uv_at << "},"
      << R"({"buffer":0,"byteOffset":)" << uv_at << R"(,"byteLength":)" << idx_at - uv_at << "},"
      << R"({"buffer":0,"byteOffset":)" << idx_at << R"(,"byteLength":)" << indices.size() * 2 << "}";
    if (!o.image.empty())
        j << R"(,{"buffer":0,"byteOffset":)" << image_at << R"(,"byteLength":)" << o.image.size() << "}";
    j << "],";
    j << R"("accessors":[{"bufferView":0,"componentType":5126,"count":24,"type":"VEC3",)"
      << R"("min":[-0.5,-0.5,-0.5],"max":[0.5,0.5,0.5]},)"
      << R"({"bufferView":1,"componentType":5126,"count":24,"type":"VEC2"},)"
      << R"({"bufferView":2,"componentType":5123,"count":36,"type":"SCALAR"}]})";
    std::string json = j.str();
    pad_to_4(json, ' ');

    std::string glb = "glTF";
    append_u32(glb, 2);
    append_u32(glb, static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
    append_u32(glb, static_cast<std::uint32_t>(json.size()));
    append_u32(glb, 0x4E4F534Au); // "JSON"
    glb += json;
    append_u32(glb, static_cast<std::uint32_t>(bin.size()));
    append_u32(glb, 0x004E4942u); // "BIN\0"
    glb += bin;
    return write_file(dir / (name + ".glb"), glb);
}

std::string png_bytes(int width, int height, const std::vector<unsigned char>& rgba) {
    std::string out;
    stbi_write_png_to_func(
        [](void* context, void* data, int size) {
            static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                                       static_cast<std::size_t>(size));
        },
        &out, width, height, 4, rgba.data(), width * 4);
    return out;
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
