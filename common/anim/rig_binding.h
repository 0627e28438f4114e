#pragma once
// The one pose -> node binding: maps a rig's nodes by name onto another node list (a render model's nodes)
// once, then writes a Pose's local matrices into that list's slots every frame without allocating. The
// runtime's robots and the editor's dojo preview both pose the robot model through it.
#include "anim/rig.h"

#include <span>
#include <string>
#include <vector>

namespace ks::anim {

class RigBinding {
  public:
    RigBinding() = default;
    // target_names[t] is the name of target node t; rig nodes with no target of their name stay unmapped.
    RigBinding(const Rig& rig, std::span<const std::string> target_names);

    // Writes local_matrix(rig, pose, i) into target_locals[target of i] for every mapped rig node; other
    // slots keep what they hold (the caller's rest transforms). Slots past the span's end are skipped.
    void write_locals(const Pose& pose, std::span<Mat4> target_locals) const;

    int mapped() const { return mapped_; }
    int target_of(int rig_node) const { return target_of_node_[static_cast<std::size_t>(rig_node)]; }

  private:
    Rig rig_;                         // a copy: the binding never dangles when the caller's rig is replaced
    std::vector<int> target_of_node_; // -1 when the target list lacks the node
    int mapped_ = 0;
};

} // namespace ks::anim
