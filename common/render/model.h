#pragma once
// Models loaded through assimp (glTF 2.0, OBJ) with their node hierarchy kept: game code and animation find
// nodes by name (robot's "arm_r", door's "door_l") and move them through a ModelPose. A missing or corrupt
// file gives a magenta-checker cube and one warning naming the file.
#include "geometry/camera.h"
#include "render/gpu_mesh.h"
#include "render/material.h"

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace ks::render {

class TextureCache;
struct MeshInstance;

struct ModelNode {
    std::string name;
    int parent = -1;         // index into Model::nodes, -1 for the root
    Mat4 local{1.0f};        // rest transform relative to the parent
    std::vector<int> meshes; // indices into Model::meshes
};

struct ModelMesh {
    std::unique_ptr<GpuMesh> gpu;
    int material = 0; // index into Model::materials
};

// Per-instance local transforms of every node (starts as the rest pose).
struct ModelPose {
    std::vector<Mat4> local;
};

class Model {
  public:
    std::string path;
    std::vector<ModelNode> nodes; // parents come before children
    std::vector<ModelMesh> meshes;
    std::vector<Material> materials;
    geometry::Aabb bounds; // of the rest pose, in model space
    bool placeholder = false;

    int find_node(std::string_view name) const;  // -1 when absent
    std::vector<std::string> node_names() const; // in node order: what anim::RigBinding maps a rig onto
    ModelPose rest_pose() const;
    // World transforms of every node for `root` and `pose` into `out` (resized; reuse it to avoid
    // allocating).
    void node_transforms(const Mat4& root, const ModelPose& pose, std::vector<Mat4>& out) const;
    // Appends one MeshInstance per mesh; `emissive_scale` multiplies every emissive material of this
    // instance.
    void emit(const Mat4& root, const ModelPose& pose, std::vector<Mat4>& scratch,
              std::vector<MeshInstance>& out, float emissive_scale = 1.0f, bool casts_shadow = true) const;
    void emit(const Mat4& root, std::vector<Mat4>& scratch, std::vector<MeshInstance>& out,
              float emissive_scale = 1.0f, bool casts_shadow = true) const;
};

// A model drawn at several levels of detail (a designer's model: modelio/model_lod.h; a shipped one: the
// asset generator's, model_lod_list.h), level 0 the full one, every level with the same nodes; each level's
// error as a fraction of the model's size says from what size on screen it may be drawn (modelio::pick_lod).
// One level and error 0 for a model with none.
struct ModelLevels {
    std::vector<std::unique_ptr<Model>> levels;
    std::vector<float> relative_errors;
    const Model& full() const { return *levels.front(); }
    const Model& level(int index) const; // clamped to the levels there are
};

// How many pixels the bounds' diagonal of a model placed at `root` covers on a `viewport_height`-pixel view
// (at its nearest point for a perspective view; infinity when the eye is inside its bounding sphere).
float model_pixels(const Model& model, const Mat4& root, const geometry::Camera& view, int viewport_height);
// The level to draw an instance of `levels` at `root` for that view, given the level it was drawn at last
// (modelio::pick_lod: the coarsest whose error covers at most about a pixel, with hysteresis).
int pick_model_level(const ModelLevels& levels, const Mat4& root, const geometry::Camera& view,
                     int viewport_height, int current);

// The magenta-checker cube (side 1, origin at its bottom centre) drawn for `path` when it cannot load.
std::unique_ptr<Model> placeholder_model(const std::filesystem::path& path, TextureCache& textures,
                                         int& next_material_id);

// Loads `path`; never fails (placeholder on error). Material ids are drawn from `next_material_id`.
std::unique_ptr<Model> load_model(const std::filesystem::path& path, TextureCache& textures,
                                  int& next_material_id);

} // namespace ks::render
