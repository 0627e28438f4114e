#include "gltf_writer.h"

#include "core/files.h"

#include <cmath>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

namespace ks::assetgen {
using nlohmann::json;

int Model::add_material(Material material) {
    materials_.push_back(std::move(material));
    return static_cast<int>(materials_.size() - 1);
}

int Model::add_node(const std::string& name, int parent, vec3 translation, quat rotation) {
    Node n;
    n.name = name;
    n.parent = parent;
    n.translation = translation;
    n.rotation = rotation;
    nodes_.push_back(std::move(n));
    return static_cast<int>(nodes_.size() - 1);
}

int Model::find_node(const std::string& name) const {
    for (size_t i = 0; i < nodes_.size(); ++i)
        if (nodes_[i].name == name) return static_cast<int>(i);
    return -1;
}

size_t Model::triangle_count() const {
    size_t n = 0;
    for (const Node& node : nodes_)
        for (const auto& [material, mesh] : node.parts) n += mesh.triangle_count();
    return n;
}

std::pair<vec3, vec3> Model::bounds() const {
    vec3 lo(INFINITY), hi(-INFINITY);
    for (size_t i = 0; i < nodes_.size(); ++i) {
        const mat4 world = world_transform(static_cast<int>(i));
        for (const auto& [material, mesh] : nodes_[i].parts)
            for (const Vertex& v : mesh.vertices) {
                const vec3 p = vec3(world * vec4(v.position, 1.0f));
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
    }
    return {lo, hi};
}

float Model::deviation() const {
    float worst = 0.0f;
    for (size_t i = 0; i < nodes_.size(); ++i) {
        const float stretch = largest_stretch(glm::mat3(world_transform(static_cast<int>(i))));
        for (const auto& [material, mesh] : nodes_[i].parts)
            worst = std::max(worst, mesh.deviation * stretch);
    }
    return worst;
}

mat4 Model::world_transform(int index) const {
    mat4 m(1.0f);
    for (int i = index; i >= 0; i = nodes_[static_cast<size_t>(i)].parent) {
        const Node& n = nodes_[static_cast<size_t>(i)];
        m = trs(n.translation) * glm::mat4_cast(n.rotation) * glm::scale(mat4(1.0f), n.scale) * m;
    }
    return m;
}

namespace {
// Factors and transforms are rounded to 6 decimals so the JSON reads cleanly ("0.3", not "0.30000001").
double tidy(float v) {
    const double r = std::round(static_cast<double>(v) * 1e6) / 1e6;
    return r == 0.0 ? 0.0 : r; // no "-0.0"
}
json tidy_array(const float* v, int n) {
    json a = json::array();
    for (int i = 0; i < n; ++i) a.push_back(tidy(v[i]));
    return a;
}

class BufferBuilder {
  public:
    json views = json::array(), accessors = json::array();
    std::vector<std::uint8_t> bytes;

    int add_view(const void* data, size_t size, int target) {
        while (bytes.size() % 4 != 0) bytes.push_back(0);
        const size_t offset = bytes.size();
        bytes.resize(offset + size);
        std::memcpy(bytes.data() + offset, data, size);
        views.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", size}, {"target", target}});
        return static_cast<int>(views.size() - 1);
    }

    int add_accessor(int view, int component_type, size_t count, const char* type,
                     json extra = json::object()) {
        json a = {{"bufferView", view}, {"componentType", component_type}, {"count", count}, {"type", type}};
        a.update(extra);
        accessors.push_back(std::move(a));
        return static_cast<int>(accessors.size() - 1);
    }
};

constexpr int kFloat = 5126, kUShort = 5123, kUInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

json encode_primitive(BufferBuilder& buffer, const Mesh& mesh, int material) {
    const size_t n = mesh.vertices.size();
    std::vector<float> pos, nrm, tan, uv;
    pos.reserve(n * 3);
    nrm.reserve(n * 3);
    tan.reserve(n * 4);
    uv.reserve(n * 2);
    vec3 lo(INFINITY), hi(-INFINITY);
    for (const Vertex& v : mesh.vertices) {
        pos.insert(pos.end(), {v.position.x, v.position.y, v.position.z});
        nrm.insert(nrm.end(), {v.normal.x, v.normal.y, v.normal.z});
        tan.insert(tan.end(), {v.tangent.x, v.tangent.y, v.tangent.z, v.tangent.w});
        uv.insert(uv.end(), {v.uv.x, v.uv.y});
        lo = glm::min(lo, v.position);
        hi = glm::max(hi, v.position);
    }
    // Bounds are written exactly (not tidied): glTF requires them to match the data.
    auto exact = [](vec3 v) { return json::array({double(v.x), double(v.y), double(v.z)}); };
    json attributes;
    attributes["POSITION"] = buffer.add_accessor(buffer.add_view(pos.data(), pos.size() * 4, kArrayBuffer),
                                                 kFloat, n, "VEC3", {{"min", exact(lo)}, {"max", exact(hi)}});
    attributes["NORMAL"] =
        buffer.add_accessor(buffer.add_view(nrm.data(), nrm.size() * 4, kArrayBuffer), kFloat, n, "VEC3");
    attributes["TANGENT"] =
        buffer.add_accessor(buffer.add_view(tan.data(), tan.size() * 4, kArrayBuffer), kFloat, n, "VEC4");
    attributes["TEXCOORD_0"] =
        buffer.add_accessor(buffer.add_view(uv.data(), uv.size() * 4, kArrayBuffer), kFloat, n, "VEC2");
    int indices;
    if (n <= 65535) {
        std::vector<std::uint16_t> idx(mesh.indices.begin(), mesh.indices.end());
        indices = buffer.add_accessor(buffer.add_view(idx.data(), idx.size() * 2, kElementArrayBuffer),
                                      kUShort, idx.size(), "SCALAR");
    } else {
        indices = buffer.add_accessor(
            buffer.add_view(mesh.indices.data(), mesh.indices.size() * 4, kElementArrayBuffer), kUInt,
            mesh.indices.size(), "SCALAR");
    }
    return {{"attributes", attributes}, {"indices", indices}, {"material", material}, {"mode", 4}};
}
} // namespace

GltfFiles encode_gltf(const Model& model, const std::string& texture_folder) {
    json doc;
    doc["asset"] = {{"version", "2.0"}, {"generator", "ks_assetgen (Killswitch asset generator)"}};
    BufferBuilder buffer;

    // Textures: one image and one texture per distinct name, all sharing a repeating, mipmapped sampler.
    std::map<std::string, int> texture_index;
    json images = json::array(), textures = json::array();
    auto texture = [&](const std::string& name) {
        auto [it, added] = texture_index.emplace(name, static_cast<int>(textures.size()));
        if (added) {
            images.push_back({{"uri", texture_folder + name + ".png"}, {"name", name}});
            textures.push_back({{"source", static_cast<int>(images.size() - 1)}, {"sampler", 0}});
        }
        return json{{"index", it->second}};
    };

    json materials = json::array();
    for (const Material& m : model.materials()) {
        json pbr = {{"baseColorFactor", tidy_array(&m.base_color.x, 4)},
                    {"metallicFactor", tidy(m.metallic)},
                    {"roughnessFactor", tidy(m.roughness)}};
        if (!m.basecolor_texture.empty()) pbr["baseColorTexture"] = texture(m.basecolor_texture);
        json mat = {{"name", m.name}, {"pbrMetallicRoughness", pbr}};
        if (!m.orm_texture.empty()) {
            mat["pbrMetallicRoughness"]["metallicRoughnessTexture"] = texture(m.orm_texture);
            mat["occlusionTexture"] = texture(m.orm_texture);
        }
        if (!m.normal_texture.empty()) {
            json t = texture(m.normal_texture);
            t["scale"] = tidy(m.normal_scale);
            mat["normalTexture"] = t;
        }
        if (m.emissive != vec3(0.0f)) mat["emissiveFactor"] = tidy_array(&m.emissive.x, 3);
        if (!m.emissive_texture.empty()) mat["emissiveTexture"] = texture(m.emissive_texture);
        if (m.double_sided) mat["doubleSided"] = true;
        materials.push_back(std::move(mat));
    }

    json nodes = json::array(), meshes = json::array(), roots = json::array();
    const auto& model_nodes = model.nodes();
    for (size_t i = 0; i < model_nodes.size(); ++i) {
        const Node& n = model_nodes[i];
        json node = {{"name", n.name}};
        if (n.translation != vec3(0.0f)) node["translation"] = tidy_array(&n.translation.x, 3);
        if (n.rotation != quat(1.0f, 0.0f, 0.0f, 0.0f)) {
            const float r[4] = {n.rotation.x, n.rotation.y, n.rotation.z, n.rotation.w};
            node["rotation"] = tidy_array(r, 4);
        }
        if (n.scale != vec3(1.0f)) node["scale"] = tidy_array(&n.scale.x, 3);
        json children = json::array();
        for (size_t c = 0; c < model_nodes.size(); ++c)
            if (model_nodes[c].parent == static_cast<int>(i)) children.push_back(c);
        if (!children.empty()) node["children"] = children;
        json primitives = json::array();
        for (const auto& [material, mesh] : n.parts)
            if (!mesh.indices.empty()) primitives.push_back(encode_primitive(buffer, mesh, material));
        if (!primitives.empty()) {
            node["mesh"] = meshes.size();
            meshes.push_back({{"name", n.name}, {"primitives", primitives}});
        }
        nodes.push_back(std::move(node));
        if (n.parent < 0) roots.push_back(i);
    }

    doc["scene"] = 0;
    doc["scenes"] = json::array({{{"name", model.name()}, {"nodes", roots}}});
    doc["nodes"] = nodes;
    if (!meshes.empty()) doc["meshes"] = meshes;
    if (!materials.empty()) doc["materials"] = materials;
    if (!textures.empty()) {
        doc["textures"] = textures;
        doc["images"] = images;
        doc["samplers"] =
            json::array({{{"magFilter", 9729}, {"minFilter", 9987}, {"wrapS", 10497}, {"wrapT", 10497}}});
    }
    while (buffer.bytes.size() % 4 != 0) buffer.bytes.push_back(0);
    doc["buffers"] = json::array({{{"uri", model.name() + ".bin"}, {"byteLength", buffer.bytes.size()}}});
    doc["bufferViews"] = buffer.views;
    doc["accessors"] = buffer.accessors;
    return {doc.dump(1) + "\n", std::move(buffer.bytes)};
}

Result<void> write_gltf(const Model& model, const std::filesystem::path& folder) {
    const GltfFiles files = encode_gltf(model);
    if (auto r = files::write_atomic(
            folder / (model.name() + ".bin"),
            std::string_view(reinterpret_cast<const char*>(files.bin.data()), files.bin.size()));
        !r)
        return r.error();
    return files::write_atomic(folder / (model.name() + ".gltf"), files.json);
}

} // namespace ks::assetgen
