#include "view/section_view.h"

#include "model/bounds.h"
#include "model/edit_selection.h"

#include <bit>
#include <cmath>

namespace ks::editor {
namespace {
// The entity's box along `direction`: the largest dot(direction, p) over its corners.
float far_depth(const geometry::Obb& box, const Vec3& direction) {
    float depth = glm::dot(direction, box.center);
    for (int i = 0; i < 3; ++i) depth += std::abs(glm::dot(direction, box.axes[i])) * box.half[i];
    return depth;
}
} // namespace

std::optional<SectionCut> section_cut(const Editor& editor, const ViewCamera& view) {
    if (view.mode != ViewMode::Front && view.mode != ViewMode::Side) return std::nullopt;
    const auto selected = selected_entities(editor);
    if (selected.empty()) return std::nullopt;
    const geometry::Aabb box = selection_bounds(selected);
    if (box.min.x > box.max.x) return std::nullopt; // empty
    SectionCut cut;
    cut.direction = view.forward();
    // The box's corner nearest the camera: the smallest depth along the view.
    const Vec3 nearest(cut.direction.x > 0 ? box.min.x : box.max.x,
                       cut.direction.y > 0 ? box.min.y : box.max.y,
                       cut.direction.z > 0 ? box.min.z : box.max.z);
    cut.depth = glm::dot(cut.direction, nearest);
    return cut;
}

bool in_front_of_cut(const SectionCut& cut, const level::Entity& entity) {
    // A small margin: a wall touching the selection's face is part of its room, not in front of it.
    constexpr float kMargin = 0.01f;
    return far_depth(entity_obb(entity), cut.direction) < cut.depth - kMargin;
}

std::uint64_t section_key(const std::optional<SectionCut>& cut) {
    if (!cut) return 0;
    std::uint64_t key = 0x9e3779b97f4a7c15ull;
    for (float f : {cut->direction.x, cut->direction.y, cut->direction.z, cut->depth})
        key = (key ^ std::bit_cast<std::uint32_t>(f)) * 0x100000001b3ull;
    return key | 1; // never 0, the key of no cut
}

} // namespace ks::editor
