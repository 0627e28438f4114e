#pragma once
// A rig is a model's named node hierarchy: names, parent indices (parents before children) and each node's
// rest local transform. Models' rigs are read by anim/gltf_rig.h; the clip file's "rig" list gives the same
// names and hierarchy without a model. A Pose holds one local transform per node, in arrays sized once, so
// evaluating animations allocates nothing per frame.
#include "core/math.h"
#include "core/result.h"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace ks::anim {

struct RigNode {
    std::string name;
    int parent = -1;       // index of an earlier node, or -1 for a root
    Vec3 rest_position{0}; // local translation
    Vec3 rest_euler{0};    // local rotation, Euler XYZ radians
    Vec3 rest_scale{1};
};

class Rig {
  public:
    // Checks the description: unique non-empty names, parents earlier in the list (so one forward pass
    // computes world transforms), finite numbers.
    static Result<Rig> create(std::vector<RigNode> nodes);
    // Nodes named in order, each the child of the node named in `parents` (empty = root); rest transforms
    // are identity. For tests and tools that have no model.
    static Result<Rig> from_names(const std::vector<std::pair<std::string, std::string>>& name_and_parent);

    int size() const { return static_cast<int>(nodes_.size()); }
    const RigNode& node(int index) const { return nodes_[static_cast<std::size_t>(index)]; }
    std::span<const RigNode> nodes() const { return nodes_; }
    int find(std::string_view name) const; // -1 if absent
    // This rig with the rest transforms of the nodes `model` has under the same names (others keep theirs).
    Rig with_rest_from(const Rig& model) const;

  private:
    std::vector<RigNode> nodes_;
};

// One local transform per rig node: Euler angles (what clips interpolate), the quaternion made from them
// (what the renderer uses), and the translation.
struct Pose {
    std::vector<Vec3> euler;
    std::vector<Quat> rotation;
    std::vector<Vec3> position;

    void resize(int node_count);
    int size() const { return static_cast<int>(euler.size()); }
    void set_rest(const Rig& rig);
    // Recomputes `rotation` from `euler`.
    void update_rotations();
};

// Node `index`'s local matrix in `pose`: translation * rotation * the rig's rest scale.
Mat4 local_matrix(const Rig& rig, const Pose& pose, int index);

// World matrices of every node (out.size() == rig.size()), given the root's parent transform.
void compute_world(const Rig& rig, const Pose& pose, std::span<Mat4> out, const Mat4& root_parent = Mat4(1));

} // namespace ks::anim
