#include "anim/rig_binding.h"

#include <algorithm>

namespace ks::anim {

RigBinding::RigBinding(const Rig& rig, std::span<const std::string> target_names) : rig_(rig) {
    target_of_node_.assign(static_cast<std::size_t>(rig.size()), -1);
    for (int i = 0; i < rig.size(); ++i) {
        const auto found = std::find(target_names.begin(), target_names.end(), rig.node(i).name);
        if (found == target_names.end()) continue;
        target_of_node_[static_cast<std::size_t>(i)] = static_cast<int>(found - target_names.begin());
        ++mapped_;
    }
}

void RigBinding::write_locals(const Pose& pose, std::span<Mat4> target_locals) const {
    const int n = std::min(pose.size(), rig_.size());
    for (int i = 0; i < n; ++i) {
        const int target = target_of_node_[static_cast<std::size_t>(i)];
        if (target < 0 || target >= static_cast<int>(target_locals.size())) continue;
        target_locals[static_cast<std::size_t>(target)] = local_matrix(rig_, pose, i);
    }
}

} // namespace ks::anim
