#include "render/model.h"

#include "core/log.h"
#include "modelio/assimp_material.h"
#include "modelio/assimp_readers.h"
#include "modelio/model_lod.h"
#include "render/model_material.h"
#include "render/scene.h"
#include "render/texture_cache.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace ks::render {

int Model::find_node(std::string_view name) const {
    for (size_t i = 0; i < nodes.size(); ++i)
        if (nodes[i].name == name) return static_cast<int>(i);
    return -1;
}

std::vector<std::string> Model::node_names() const {
    std::vector<std::string> names;
    names.reserve(nodes.size());
    for (const auto& n : nodes) names.push_back(n.name);
    return names;
}

ModelPose Model::rest_pose() const {
    ModelPose pose;
    pose.local.reserve(nodes.size());
    for (const auto& n : nodes) pose.local.push_back(n.local);
    return pose;
}

void Model::node_transforms(const Mat4& root, const ModelPose& pose, std::vector<Mat4>& out) const {
    out.resize(nodes.size());
    for (size_t i = 0; i < nodes.size(); ++i) {
        const Mat4& local = i < pose.local.size() ? pose.local[i] : nodes[i].local;
        out[i] = nodes[i].parent < 0 ? root * local : out[static_cast<size_t>(nodes[i].parent)] * local;
    }
}

void Model::emit(const Mat4& root, const ModelPose& pose, std::vector<Mat4>& scratch,
                 std::vector<MeshInstance>& out, float emissive_scale, bool casts_shadow) const {
    node_transforms(root, pose, scratch);
    for (size_t i = 0; i < nodes.size(); ++i)
        for (int m : nodes[i].meshes) {
            MeshInstance inst;
            inst.mesh = meshes[static_cast<size_t>(m)].gpu.get();
            inst.material = &materials[static_cast<size_t>(meshes[static_cast<size_t>(m)].material)];
            inst.world = scratch[i];
            inst.emissive_scale = emissive_scale;
            inst.casts_shadow = casts_shadow;
            out.push_back(inst);
        }
}

void Model::emit(const Mat4& root, std::vector<Mat4>& scratch, std::vector<MeshInstance>& out,
                 float emissive_scale, bool casts_shadow) const {
    // The rest pose without building a ModelPose: node_transforms falls back to each node's rest transform.
    static const ModelPose kRest;
    emit(root, kRest, scratch, out, emissive_scale, casts_shadow);
}

const Model& ModelLevels::level(int index) const {
    return *levels[static_cast<std::size_t>(std::clamp(index, 0, static_cast<int>(levels.size()) - 1))];
}

float model_pixels(const Model& model, const Mat4& root, const geometry::Camera& view, int viewport_height) {
    const geometry::Aabb box = geometry::transform_aabb(model.bounds, root);
    const float diagonal = glm::length(box.max - box.min);
    if (view.ortho_height > 0.0f) return diagonal / view.ortho_height * static_cast<float>(viewport_height);
    const float distance = glm::length(box.center() - view.position) - 0.5f * diagonal;
    if (distance <= 0.0f) return std::numeric_limits<float>::infinity();
    return diagonal / (2.0f * distance * std::tan(0.5f * view.fov_y)) * static_cast<float>(viewport_height);
}

int pick_model_level(const ModelLevels& levels, const Mat4& root, const geometry::Camera& view,
                     int viewport_height, int current) {
    if (levels.levels.size() < 2) return 0;
    return modelio::pick_lod(levels.relative_errors, model_pixels(levels.full(), root, view, viewport_height),
                             current);
}

namespace {
Mat4 to_mat4(const aiMatrix4x4& m) {
    Mat4 r;
    for (int c = 0; c < 4; ++c)
        for (int rr = 0; rr < 4; ++rr) r[c][rr] = m[rr][c]; // assimp is row-major
    return r;
}

Material convert_material(const aiMaterial* src, const std::filesystem::path& dir, TextureCache& textures) {
    return make_model_material(modelio::read_material(*src), dir, textures,
                               [&](const std::string& name, ColorSpace space) -> const Texture& {
                                   return textures.get(dir / name, space);
                               });
}
} // namespace

std::unique_ptr<Model> placeholder_model(const std::filesystem::path& path, TextureCache& textures,
                                         int& next_id) {
    auto model = std::make_unique<Model>();
    model->path = path.string();
    model->placeholder = true;
    Material mat;
    mat.name = "placeholder";
    mat.base_map = textures.placeholder().id;
    mat.roughness = 0.8f;
    mat.placeholder = true;
    mat.id = next_id++;
    model->materials.push_back(mat);
    MeshData cube = unit_cube();
    for (auto& v : cube.vertices) v.position.y += 0.5f; // origin at the bottom centre like every model
    model->meshes.push_back({std::make_unique<GpuMesh>(cube), 0});
    ModelNode root;
    root.name = path.stem().string();
    root.meshes = {0};
    model->nodes.push_back(root);
    model->bounds = cube.bounds();
    return model;
}

std::unique_ptr<Model> load_model(const std::filesystem::path& path, TextureCache& textures,
                                  int& next_material_id) {
    Assimp::Importer importer;
    modelio::keep_extension_readers(importer, path); // a damaged file goes to no other format's reader
    const unsigned flags = aiProcess_Triangulate | aiProcess_GenSmoothNormals | aiProcess_CalcTangentSpace |
                           aiProcess_JoinIdenticalVertices | aiProcess_ValidateDataStructure;
    const aiScene* scene = importer.ReadFile(path.string(), flags);
    if (!scene || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !scene->mRootNode) {
        log::warn(path.string(), ": cannot load model (", importer.GetErrorString(),
                  "); drawing a magenta-checker cube instead (regenerate assets with ks_assetgen)");
        return placeholder_model(path, textures, next_material_id);
    }
    auto model = std::make_unique<Model>();
    model->path = path.string();
    const auto dir = path.parent_path();
    for (unsigned i = 0; i < scene->mNumMaterials; ++i) {
        Material m = convert_material(scene->mMaterials[i], dir, textures);
        m.id = next_material_id++;
        if (m.placeholder) model->placeholder = true;
        model->materials.push_back(std::move(m));
    }
    if (model->materials.empty()) {
        Material m;
        m.id = next_material_id++;
        model->materials.push_back(m);
    }
    for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
        const aiMesh* src = scene->mMeshes[i];
        MeshData data;
        data.vertices.resize(src->mNumVertices);
        for (unsigned v = 0; v < src->mNumVertices; ++v) {
            Vertex& dst = data.vertices[v];
            dst.position = Vec3(src->mVertices[v].x, src->mVertices[v].y, src->mVertices[v].z);
            dst.normal = src->mNormals ? Vec3(src->mNormals[v].x, src->mNormals[v].y, src->mNormals[v].z)
                                       : Vec3(0, 1, 0);
            // assimp hands texture coordinates over with v = 0 at the image's bottom (its glTF importer
            // flips glTF's v, OBJ's is bottom-up already); our textures are uploaded top row first (the
            // world's maps are made that way), so v is turned back. The tangent frame below keeps assimp's
            // bitangent, which still points up the image as glTF's normal maps expect.
            dst.uv = src->mTextureCoords[0]
                         ? Vec2(src->mTextureCoords[0][v].x, 1.0f - src->mTextureCoords[0][v].y)
                         : Vec2(0);
            if (src->mTangents && src->mBitangents) {
                Vec3 t(src->mTangents[v].x, src->mTangents[v].y, src->mTangents[v].z);
                Vec3 b(src->mBitangents[v].x, src->mBitangents[v].y, src->mBitangents[v].z);
                float w = glm::dot(glm::cross(dst.normal, t), b) < 0.0f ? -1.0f : 1.0f;
                dst.tangent = Vec4(t, w);
            } else {
                dst.tangent = Vec4(1, 0, 0, 1);
            }
        }
        data.indices.reserve(src->mNumFaces * 3);
        for (unsigned f = 0; f < src->mNumFaces; ++f)
            if (src->mFaces[f].mNumIndices == 3)
                data.indices.insert(data.indices.end(), src->mFaces[f].mIndices, src->mFaces[f].mIndices + 3);
        int material =
            src->mMaterialIndex < model->materials.size() ? static_cast<int>(src->mMaterialIndex) : 0;
        model->meshes.push_back({std::make_unique<GpuMesh>(data), material});
    }
    std::function<void(const aiNode*, int)> walk = [&](const aiNode* node, int parent) {
        ModelNode n;
        n.name = node->mName.C_Str();
        n.parent = parent;
        n.local = to_mat4(node->mTransformation);
        for (unsigned m = 0; m < node->mNumMeshes; ++m)
            n.meshes.push_back(static_cast<int>(node->mMeshes[m]));
        int index = static_cast<int>(model->nodes.size());
        model->nodes.push_back(std::move(n));
        for (unsigned c = 0; c < node->mNumChildren; ++c) walk(node->mChildren[c], index);
    };
    // glTF files get a synthetic root from assimp when the scene has one top node; keep it, it is identity.
    walk(scene->mRootNode, -1);
    std::vector<Mat4> world;
    model->node_transforms(Mat4(1.0f), model->rest_pose(), world);
    model->bounds = geometry::Aabb::empty();
    for (size_t i = 0; i < model->nodes.size(); ++i)
        for (int m : model->nodes[i].meshes)
            model->bounds = geometry::merge(
                model->bounds,
                geometry::transform_aabb(model->meshes[static_cast<size_t>(m)].gpu->bounds(), world[i]));
    if (!model->bounds.valid()) model->bounds = {Vec3(-0.5f), Vec3(0.5f)};
    return model;
}

} // namespace ks::render
