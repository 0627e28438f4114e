#include "anim/rig.h"

#include "anim/rotation.h"

#include <glm/gtc/matrix_transform.hpp>
#include <unordered_set>

namespace ks::anim {

Result<Rig> Rig::create(std::vector<RigNode> nodes) {
    std::vector<Error> errors;
    std::unordered_set<std::string> seen;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const RigNode& n = nodes[i];
        const std::string where = "rig node " + std::to_string(i) + " '" + n.name + "'";
        if (n.name.empty())
            errors.emplace_back("rig node " + std::to_string(i) + " has no name");
        else if (!seen.insert(n.name).second)
            errors.emplace_back(where + ": duplicate name", Location{}, "names must be unique");
        if (n.parent >= static_cast<int>(i) || n.parent < -1)
            errors.emplace_back(where + ": parent index " + std::to_string(n.parent) +
                                    " is not an earlier node",
                                Location{}, "list parents before their children");
        if (!is_finite(n.rest_position) || !is_finite(n.rest_euler) || !is_finite(n.rest_scale))
            errors.emplace_back(where + ": rest transform is not finite");
    }
    if (!errors.empty()) return combine_errors(errors);
    Rig rig;
    rig.nodes_ = std::move(nodes);
    return rig;
}

Result<Rig> Rig::from_names(const std::vector<std::pair<std::string, std::string>>& name_and_parent) {
    std::vector<RigNode> nodes;
    std::vector<Error> errors;
    for (const auto& [name, parent] : name_and_parent) {
        RigNode n;
        n.name = name;
        if (!parent.empty()) {
            for (std::size_t j = 0; j < nodes.size(); ++j)
                if (nodes[j].name == parent) n.parent = static_cast<int>(j);
            if (n.parent < 0)
                errors.emplace_back("rig node '" + name + "': parent '" + parent +
                                    "' is not an earlier node");
        }
        nodes.push_back(std::move(n));
    }
    if (!errors.empty()) return combine_errors(errors);
    return create(std::move(nodes));
}

int Rig::find(std::string_view name) const {
    for (std::size_t i = 0; i < nodes_.size(); ++i)
        if (nodes_[i].name == name) return static_cast<int>(i);
    return -1;
}

Rig Rig::with_rest_from(const Rig& model) const {
    Rig out = *this;
    for (RigNode& node : out.nodes_) {
        const int source = model.find(node.name);
        if (source < 0) continue;
        node.rest_position = model.node(source).rest_position;
        node.rest_euler = model.node(source).rest_euler;
        node.rest_scale = model.node(source).rest_scale;
    }
    return out;
}

void Pose::resize(int node_count) {
    auto n = static_cast<std::size_t>(node_count);
    euler.assign(n, Vec3(0));
    rotation.assign(n, Quat(1, 0, 0, 0));
    position.assign(n, Vec3(0));
}

void Pose::set_rest(const Rig& rig) {
    resize(rig.size());
    for (int i = 0; i < rig.size(); ++i) {
        euler[static_cast<std::size_t>(i)] = rig.node(i).rest_euler;
        position[static_cast<std::size_t>(i)] = rig.node(i).rest_position;
    }
    update_rotations();
}

void Pose::update_rotations() {
    for (std::size_t i = 0; i < euler.size(); ++i) rotation[i] = euler_xyz_to_quat(euler[i]);
}

Mat4 local_matrix(const Rig& rig, const Pose& pose, int index) {
    const auto k = static_cast<std::size_t>(index);
    return glm::translate(Mat4(1), pose.position[k]) * glm::mat4_cast(pose.rotation[k]) *
           glm::scale(Mat4(1), rig.node(index).rest_scale);
}

void compute_world(const Rig& rig, const Pose& pose, std::span<Mat4> out, const Mat4& root_parent) {
    for (int i = 0; i < rig.size() && i < static_cast<int>(out.size()); ++i) {
        const int parent = rig.node(i).parent;
        out[static_cast<std::size_t>(i)] =
            (parent < 0 ? root_parent : out[static_cast<std::size_t>(parent)]) * local_matrix(rig, pose, i);
    }
}

} // namespace ks::anim
