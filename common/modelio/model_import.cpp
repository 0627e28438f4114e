#include "modelio/model_import.h"

#include "modelio/assimp_material.h"
#include "modelio/assimp_readers.h"
#include "modelio/embedded_textures.h"
#include "modelio/fbx_checks.h"
#include "modelio/glb_container.h"
#include "modelio/obj_checks.h"
#include "modelio/scene_conventions.h"

#include <assimp/DefaultLogger.hpp>
#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <system_error>
#include <utility>

namespace ks::modelio {

namespace {

Error file_error(const std::filesystem::path& path, std::string what, std::string fix = {}) {
    return Error(std::move(what), Location(path.string()), std::move(fix));
}

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

Mat4 to_mat4(const aiMatrix4x4& m) {
    Mat4 r;
    for (int c = 0; c < 4; ++c)
        for (int row = 0; row < 4; ++row) r[c][row] = m[static_cast<unsigned>(row)][static_cast<unsigned>(c)];
    return r;
}

Result<void> check_file(const std::filesystem::path& path, const ImportLimits& limits) {
    if (!has_supported_extension(path))
        return file_error(path, "\"" + path.extension().string() + "\" is not a model format the game reads",
                          "export it as .glb, .gltf, .obj or .fbx");
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        return file_error(path, "no such model file", "put the file in assets/models or your models folder");
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) return file_error(path, "cannot read the file's size: " + ec.message());
    if (size == 0) return file_error(path, "the file is empty", "export the model again");
    if (size > limits.max_file_bytes)
        return file_error(path,
                          "the file is " + std::to_string(size >> 20) + " MiB, more than the " +
                              std::to_string(limits.max_file_bytes >> 20) + " MiB a model may be",
                          "simplify the model (Blender: Decimate modifier)");
    return ok();
}

// Every node's world transform (in the file's coordinates) with the meshes it places: iterative, so a file
// with absurdly deep nodes cannot exhaust the stack.
struct PlacedMesh {
    unsigned mesh = 0;
    Mat4 world{1.0f};
};

std::vector<PlacedMesh> placed_meshes(const aiScene& scene) {
    std::vector<PlacedMesh> out;
    std::vector<std::pair<const aiNode*, Mat4>> stack{{scene.mRootNode, Mat4(1.0f)}};
    while (!stack.empty()) {
        auto [node, parent] = stack.back();
        stack.pop_back();
        const Mat4 world = parent * to_mat4(node->mTransformation);
        for (unsigned i = 0; i < node->mNumMeshes; ++i) out.push_back({node->mMeshes[i], world});
        for (unsigned c = 0; c < node->mNumChildren; ++c) stack.emplace_back(node->mChildren[c], world);
    }
    return out;
}

std::size_t file_triangles(const aiScene& scene, const std::vector<PlacedMesh>& placed) {
    std::size_t total = 0;
    for (const PlacedMesh& p : placed)
        if (p.mesh < scene.mNumMeshes) total += scene.mMeshes[p.mesh]->mNumFaces;
    return total;
}

Result<ImportedMesh> bake_mesh(const aiMesh& src, const Mat4& to_level, bool mirrored,
                               const std::filesystem::path& path, unsigned material_count) {
    ImportedMesh mesh;
    mesh.material = src.mMaterialIndex < material_count ? static_cast<int>(src.mMaterialIndex) : 0;
    const Mat3 normal_matrix = glm::transpose(glm::inverse(Mat3(to_level)));
    mesh.positions.reserve(src.mNumVertices);
    for (unsigned v = 0; v < src.mNumVertices; ++v) {
        const Vec3 p(src.mVertices[v].x, src.mVertices[v].y, src.mVertices[v].z);
        if (!is_finite(p))
            return file_error(path,
                              "mesh \"" + std::string(src.mName.C_Str()) +
                                  "\" has a vertex that is not a number (vertex " + std::to_string(v) + ")",
                              "clean up the mesh in the modelling tool and export it again");
        const Vec3 placed = Vec3(to_level * Vec4(p, 1.0f));
        if (!is_finite(placed))
            return file_error(path, "mesh \"" + std::string(src.mName.C_Str()) +
                                        "\" is placed at an infinite position");
        mesh.positions.push_back(placed);
        Vec3 n = src.mNormals ? Vec3(src.mNormals[v].x, src.mNormals[v].y, src.mNormals[v].z) : Vec3(0, 1, 0);
        n = normal_matrix * n;
        const float len = glm::length(n);
        mesh.normals.push_back(std::isfinite(len) && len > 1e-12f ? n / len : Vec3(0, 1, 0));
        // assimp hands v over bottom-up (its glTF reader flips glTF's, OBJ's and FBX's are bottom-up);
        // turned back to the project's top-down convention (docs/assets.md), as render/model.cpp does.
        mesh.uvs.push_back(src.mTextureCoords[0]
                               ? Vec2(src.mTextureCoords[0][v].x, 1.0f - src.mTextureCoords[0][v].y)
                               : Vec2(0.0f));
    }
    mesh.indices.reserve(static_cast<std::size_t>(src.mNumFaces) * 3);
    for (unsigned f = 0; f < src.mNumFaces; ++f) {
        const aiFace& face = src.mFaces[f];
        if (face.mNumIndices != 3) continue; // points and lines: not surfaces
        const unsigned a = face.mIndices[0], b = face.mIndices[mirrored ? 2 : 1],
                       c = face.mIndices[mirrored ? 1 : 2];
        if (a >= src.mNumVertices || b >= src.mNumVertices || c >= src.mNumVertices)
            return file_error(path, "mesh \"" + std::string(src.mName.C_Str()) +
                                        "\" names a vertex it does not have");
        mesh.indices.insert(mesh.indices.end(), {a, b, c});
    }
    return mesh;
}

// A texture the file names must exist beside it (embedded ones, "*N", are inside the file and already
// decoded).
Result<void> check_textures(const ImportedModel& model) {
    const auto dir = model.path.parent_path();
    for (const ImportedMaterial& m : model.materials)
        for (const std::string* t :
             {&m.textures.base_color, &m.textures.normal, &m.textures.metal_rough, &m.textures.emissive}) {
            if (t->empty() || (*t)[0] == '*') continue;
            std::error_code ec;
            if (!std::filesystem::is_regular_file(dir / *t, ec))
                return file_error(
                    model.path,
                    "material \"" + m.name + "\" names the texture \"" + *t + "\", which is missing",
                    "copy the texture next to the model, or export as .glb with the textures inside");
        }
    return ok();
}

Result<void> check_size(const ImportedModel& model, const ImportLimits& limits) {
    const Vec3 extent = model.bounds.max - model.bounds.min;
    const float largest = std::max({extent.x, extent.y, extent.z});
    if (!(largest <= limits.max_extent))
        return file_error(model.path,
                          "the model is " + std::to_string(largest) + " units across, more than the " +
                              std::to_string(limits.max_extent) + " a model may be",
                          "check the export's units and scale (" + model.axes + ")");
    if (!(largest >= limits.min_extent))
        return file_error(model.path, "the model has no size (" + std::to_string(largest) + " units across)",
                          "check the export's units and scale (" + model.axes + ")");
    return ok();
}

} // namespace

const std::vector<std::string>& supported_extensions() {
    static const std::vector<std::string> kExtensions{".glb", ".gltf", ".obj", ".fbx"};
    return kExtensions;
}

bool has_supported_extension(const std::filesystem::path& path) {
    const std::string ext = lower(path.extension().string());
    const auto& all = supported_extensions();
    return std::find(all.begin(), all.end(), ext) != all.end();
}

Result<ImportedModel> import_model(const std::filesystem::path& path, const ImportLimits& limits) {
    if (Result<void> file = check_file(path, limits); !file) return file.error();
    const std::string ext = lower(path.extension().string());
    if (ext == ".glb")
        if (Result<void> container = check_glb_container(path); !container) return container.error();
    if (ext == ".fbx" || ext == ".obj") {
        std::ifstream in(path, std::ios::binary);
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (Result<void> checked = ext == ".fbx" ? check_fbx_file(text, path) : check_obj_file(text, path);
            !checked)
            return checked.error();
    }
    Assimp::Importer importer;
    keep_extension_readers(importer, path);
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    // Read first, count, then post-process: a file with millions of faces is refused before any work on them.
    const aiScene* raw = importer.ReadFile(path.string(), aiProcess_ValidateDataStructure);
    if (!raw || !raw->mRootNode)
        return file_error(path, "cannot read the model: " + std::string(importer.GetErrorString()),
                          "the file may be truncated or not what its extension says; export it again");
    if (raw->mFlags & AI_SCENE_FLAGS_INCOMPLETE)
        return file_error(path, "the file holds no complete scene (no meshes)", "export the model's meshes");
    if (const std::size_t raw_faces = file_triangles(*raw, placed_meshes(*raw));
        raw_faces > limits.max_triangles)
        return file_error(path,
                          "the model has " + std::to_string(raw_faces) + " faces, more than the " +
                              std::to_string(limits.max_triangles) + " a model may have",
                          "simplify it (Blender: Decimate modifier)");
    const aiScene* scene =
        importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_SortByPType |
                                     aiProcess_GenSmoothNormals | aiProcess_JoinIdenticalVertices);
    if (!scene)
        return file_error(path, "cannot prepare the model: " + std::string(importer.GetErrorString()));
    Result<SceneBasis> basis = scene_basis(*scene, path);
    if (!basis) return basis.error();

    ImportedModel model;
    model.path = path;
    model.unit_scale = basis->unit_scale;
    model.axes = basis->axes;
    for (unsigned i = 0; i < scene->mNumMaterials; ++i)
        model.materials.push_back(read_material(*scene->mMaterials[i]));
    if (model.materials.empty()) model.materials.emplace_back();
    if (Result<void> embedded = load_embedded_textures(*scene, model, limits); !embedded)
        return embedded.error();
    const std::vector<PlacedMesh> placed = placed_meshes(*scene);
    if (std::size_t n = file_triangles(*scene, placed); n > limits.max_triangles)
        return file_error(path,
                          "the model has " + std::to_string(n) + " triangles, more than the " +
                              std::to_string(limits.max_triangles) + " a model may have",
                          "simplify it (Blender: Decimate modifier)");
    model.bounds = geometry::Aabb::empty();
    for (const PlacedMesh& p : placed) {
        if (p.mesh >= scene->mNumMeshes)
            return file_error(path, "a node names a mesh the file does not have");
        const Mat4 to_level = basis->to_level * p.world;
        const bool mirrored = basis->mirrored != (glm::determinant(Mat3(p.world)) < 0.0f);
        Result<ImportedMesh> mesh = bake_mesh(*scene->mMeshes[p.mesh], to_level, mirrored, path,
                                              static_cast<unsigned>(model.materials.size()));
        if (!mesh) return mesh.error();
        if (mesh->indices.empty()) continue;
        for (const Vec3& v : mesh->positions) model.bounds.grow({v, v});
        model.triangle_count += mesh->indices.size() / 3;
        model.meshes.push_back(std::move(*mesh));
    }
    if (model.triangle_count == 0)
        return file_error(path, "the model has no triangles",
                          "export the model's meshes, not only empties or curves");
    if (Result<void> size = check_size(model, limits); !size) return size.error();
    if (Result<void> textures = check_textures(model); !textures) return textures.error();
    return model;
}

} // namespace ks::modelio
