#pragma once
// A small glTF 2.0 writer: a node hierarchy with TRS, one mesh per node holding one primitive per material
// (POSITION, NORMAL, TANGENT, TEXCOORD_0, indices), metallic-roughness materials whose textures are PNGs
// referenced by relative URI, and one external .bin buffer.
#include "mesh.h"

#include "core/result.h"

#include <deque>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace ks::assetgen {

struct Material {
    std::string name;
    vec4 base_color{1.0f};
    float metallic = 0.0f;
    float roughness = 1.0f;
    vec3 emissive{0.0f};
    // Texture names without folder or extension ("robot_basecolor"); empty for none. The ORM texture is
    // used both as metallicRoughnessTexture (G, B) and occlusionTexture (R).
    std::string basecolor_texture, normal_texture, orm_texture, emissive_texture;
    float normal_scale = 1.0f;
    bool double_sided = false;
};

struct Node {
    std::string name;
    int parent = -1;
    vec3 translation{0.0f};
    quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    vec3 scale{1.0f};
    std::map<int, Mesh> parts; // material index -> geometry in this node's frame

    Mesh& part(int material) { return parts[material]; }
};

class Model {
  public:
    explicit Model(std::string name) : name_(std::move(name)) {}

    int add_material(Material material);
    // A node at `translation` (and rotation) relative to `parent` (-1 for a root).
    int add_node(const std::string& name, int parent, vec3 translation = vec3(0.0f),
                 quat rotation = quat(1.0f, 0.0f, 0.0f, 0.0f));
    Node& node(int index) { return nodes_[static_cast<size_t>(index)]; }
    int find_node(const std::string& name) const;

    const std::string& name() const { return name_; }
    void set_name(std::string name) { name_ = std::move(name); }
    const std::deque<Node>& nodes() const { return nodes_; }
    const std::vector<Material>& materials() const { return materials_; }
    size_t triangle_count() const;
    // Axis-aligned bounds of all geometry in the root frame (min, max).
    std::pair<vec3, vec3> bounds() const;
    // The largest of its meshes' deviations (Mesh::deviation), in the root frame: how far this model, built
    // at a coarser Detail, may lie from itself built in full.
    float deviation() const;
    // The node's transform relative to the model root (parents applied).
    mat4 world_transform(int node) const;

  private:
    std::string name_;
    std::deque<Node> nodes_; // a deque: references from node() stay valid while more nodes are added
    std::vector<Material> materials_;
};

struct GltfFiles {
    std::string json;              // the .gltf text
    std::vector<std::uint8_t> bin; // the .bin buffer it references as "<name>.bin"
};
// Encodes the model; texture URIs are `texture_folder + name + ".png"`.
GltfFiles encode_gltf(const Model& model, const std::string& texture_folder = "../textures/");
// Writes <folder>/<name>.gltf and <folder>/<name>.bin atomically.
Result<void> write_gltf(const Model& model, const std::filesystem::path& folder);

} // namespace ks::assetgen
