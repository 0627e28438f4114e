#include "anim/gltf_rig.h"

#include "anim/rotation.h"
#include "core/files.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <set>

namespace ks::anim {

namespace {

using nlohmann::json;

struct NodeReader {
    const std::string& file;
    std::vector<Error> errors;

    Error error(const std::string& path, const std::string& message) {
        return Error(message, Location(file, 0, 0, path), "fix or regenerate the model (see docs/assets.md)");
    }

    // Reads `count` finite numbers at node[key] into out; absent keys leave out as it is.
    bool numbers(const json& node, const std::string& where, const char* key, std::size_t count, float* out) {
        if (!node.contains(key)) return false;
        const auto& a = node[key];
        const std::string path = where + "." + key;
        if (!a.is_array() || a.size() != count) {
            errors.push_back(
                error(path, std::string(key) + " must be an array of " + std::to_string(count) + " numbers"));
            return false;
        }
        for (std::size_t k = 0; k < count; ++k) {
            if (!a[k].is_number() || !std::isfinite(a[k].get<double>())) {
                errors.push_back(error(path, std::string(key) + " holds a non-finite or non-number value"));
                return false;
            }
            out[k] = a[k].get<float>();
        }
        return true;
    }

    // The rest transform of one glTF node: TRS properties, or a matrix decomposed into them.
    void rest_transform(const json& node, const std::string& where, RigNode& out) {
        float m[16];
        if (numbers(node, where, "matrix", 16, m)) {
            const Mat4 local = glm::make_mat4(m); // glTF matrices are column-major, as glm's
            Mat3 basis(local);
            out.rest_position = Vec3(local[3]);
            out.rest_scale = Vec3(glm::length(basis[0]), glm::length(basis[1]), glm::length(basis[2]));
            for (int c = 0; c < 3; ++c)
                if (out.rest_scale[c] > 0) basis[c] /= out.rest_scale[c];
            out.rest_euler = quat_to_euler_xyz(glm::quat_cast(basis));
            return;
        }
        float t[3] = {0, 0, 0}, q[4] = {0, 0, 0, 1}, s[3] = {1, 1, 1};
        numbers(node, where, "translation", 3, t);
        numbers(node, where, "scale", 3, s);
        if (numbers(node, where, "rotation", 4, q)) {
            const Quat rotation(q[3], q[0], q[1], q[2]); // glTF stores x, y, z, w
            if (!(glm::length(rotation) > 1e-6f))
                errors.push_back(error(where + ".rotation", "rotation is not a unit quaternion"));
            else
                out.rest_euler = quat_to_euler_xyz(rotation);
        }
        out.rest_position = Vec3(t[0], t[1], t[2]);
        out.rest_scale = Vec3(s[0], s[1], s[2]);
    }
};

// Parent index of every glTF node (-1 for roots) from the "children" lists.
std::vector<int> gltf_parents(const json& nodes, NodeReader& reader) {
    std::vector<int> parent(nodes.size(), -1);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        if (!nodes[i].contains("children")) continue;
        const std::string path = "nodes[" + std::to_string(i) + "].children";
        const auto& children = nodes[i]["children"];
        if (!children.is_array()) {
            reader.errors.push_back(reader.error(path, "children must be an array of node indices"));
            continue;
        }
        for (const auto& c : children) {
            if (!c.is_number_integer() || c.get<long long>() < 0 ||
                c.get<long long>() >= static_cast<long long>(nodes.size())) {
                reader.errors.push_back(reader.error(path, "child is not a node index"));
                continue;
            }
            auto& p = parent[c.get<std::size_t>()];
            if (p >= 0 || c.get<std::size_t>() == i)
                reader.errors.push_back(reader.error(path, "node " + std::to_string(c.get<std::size_t>()) +
                                                               " has more than one parent"));
            else
                p = static_cast<int>(i);
        }
    }
    return parent;
}

} // namespace

Result<Rig> parse_gltf_rig(std::string_view json_text, const std::string& file_name) {
    const auto doc = json::parse(json_text, nullptr, false);
    if (doc.is_discarded() || !doc.is_object() || !doc.contains("nodes") || !doc["nodes"].is_array())
        return Error("not a glTF JSON file with a \"nodes\" array", Location(file_name),
                     "regenerate the model (see docs/assets.md)");
    const auto& gnodes = doc["nodes"];
    NodeReader reader{file_name, {}};
    const std::vector<int> parent = gltf_parents(gnodes, reader);
    std::vector<RigNode> read(gnodes.size());
    std::set<std::string> names;
    for (std::size_t i = 0; i < gnodes.size(); ++i) {
        const std::string where = "nodes[" + std::to_string(i) + "]";
        if (!gnodes[i].is_object()) {
            reader.errors.push_back(reader.error(where, "a node must be an object"));
            continue;
        }
        const auto& n = gnodes[i];
        const std::string name =
            n.contains("name") && n["name"].is_string() ? n["name"].get<std::string>() : "";
        read[i].name = name.empty() || names.count(name) ? "_node" + std::to_string(i) + "_" + name : name;
        names.insert(read[i].name);
        reader.rest_transform(n, where, read[i]);
    }
    if (!reader.errors.empty()) return combine_errors(reader.errors);

    // Depth first from each root, so parents come before children whatever the file's order.
    std::vector<int> rig_index(gnodes.size(), -1);
    std::vector<RigNode> nodes;
    std::vector<std::size_t> stack;
    for (std::size_t root = gnodes.size(); root-- > 0;)
        if (parent[root] < 0) stack.push_back(root);
    while (!stack.empty()) {
        const std::size_t i = stack.back();
        stack.pop_back();
        rig_index[i] = static_cast<int>(nodes.size());
        nodes.push_back(std::move(read[i]));
        nodes.back().parent = parent[i] < 0 ? -1 : rig_index[static_cast<std::size_t>(parent[i])];
        if (!gnodes[i].contains("children")) continue;
        const auto& children = gnodes[i]["children"];
        for (std::size_t c = children.size(); c-- > 0;) stack.push_back(children[c].get<std::size_t>());
    }
    if (nodes.size() != gnodes.size())
        return Error("the node hierarchy has a cycle", Location(file_name, 0, 0, "nodes"),
                     "each node must be reachable from a root");
    return Rig::create(std::move(nodes));
}

Result<Rig> load_gltf_rig(const std::filesystem::path& gltf) {
    auto text = files::read_text(gltf);
    if (!text) return text.error();
    return parse_gltf_rig(*text, gltf.string());
}

} // namespace ks::anim
