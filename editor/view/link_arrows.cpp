#include "view/link_arrows.h"

#include "level/logic_names.h"
#include "model/bounds.h"
#include "view/link_options.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace ks::editor {

namespace {
// Where the line from `outside` toward `box`'s centre enters the box (the centre when `outside` is inside).
Vec3 box_entry(const geometry::Obb& box, const Vec3& outside) {
    const Vec3 to_centre = box.center - outside;
    const float distance = glm::length(to_centre);
    if (distance < 1e-4f) return box.center;
    geometry::Ray ray;
    ray.origin = outside;
    ray.direction = to_centre / distance;
    ray.max_distance = distance;
    const float t = geometry::ray_obb(ray, box);
    return t > 0.0f ? ray.at(t) : box.center;
}

// A target's entity, when the link names an entity (by its action) and the name resolves to exactly one.
int target_entity(const std::unordered_map<std::string_view, int>& ids_by_name, const level::Link& link) {
    const auto action = level::action_from_name(link.action);
    if (action && level::target_kind(*action) != level::TargetKind::Entity) return 0;
    if (!action && link.target == level::kLevelTarget) return 0;
    const auto found = ids_by_name.find(link.target);
    return found == ids_by_name.end() ? 0 : found->second; // -1: the name is ambiguous
}

bool contains(const std::vector<int>& ids, int id) {
    return std::find(ids.begin(), ids.end(), id) != ids.end();
}

void shape_curve(LinkArrow& arrow, const geometry::Obb& source, const geometry::Obb& target) {
    arrow.from = box_entry(source, target.center);
    arrow.to = box_entry(target, source.center);
    if (glm::length(arrow.to - arrow.from) < 1e-3f) arrow.from = source.center, arrow.to = target.center;
    const Vec3 along = arrow.to - arrow.from;
    const float length = glm::length(along);
    Vec3 side = glm::cross(along, Vec3(0, 1, 0));
    side = glm::length(side) > 1e-4f ? glm::normalize(side) : Vec3(1, 0, 0);
    // Lifted so it clears the floor and reads as an arc from the side, and bent to its right so that the
    // arrow back from the target takes the other side (and the arc shows in the top view too).
    const float lift = std::clamp(length * 0.25f, 0.5f, 8.0f);
    arrow.control = (arrow.from + arrow.to) * 0.5f + Vec3(0, lift, 0) + side * (length * 0.12f);
}
} // namespace

Vec3 LinkArrow::point_at(float t) const {
    const float u = 1.0f - t;
    return from * (u * u) + control * (2.0f * u * t) + to * (t * t);
}

std::vector<LinkArrow> link_arrows(const level::Level& level, const std::vector<int>& selected,
                                   const std::function<bool(const level::Entity&)>& shown) {
    std::unordered_map<std::string_view, int> ids_by_name;
    std::unordered_map<int, size_t> index_of;
    for (size_t i = 0; i < level.entities.size(); ++i) {
        const auto& e = level.entities[i];
        index_of[e.id] = i;
        if (e.name.empty()) continue;
        auto [it, fresh] = ids_by_name.emplace(e.name, e.id);
        if (!fresh) it->second = -1;
    }
    std::vector<LinkArrow> arrows;
    for (const auto& source : level.entities) {
        if (source.links.empty() || !shown(source)) continue;
        const size_t first = arrows.size(); // this source's arrows, one per target
        for (const auto& link : source.links) {
            const int target_id = target_entity(ids_by_name, link);
            if (target_id <= 0 || target_id == source.id) continue;
            const level::Entity& target = level.entities[index_of.at(target_id)];
            if (!shown(target)) continue;
            auto same = std::find_if(arrows.begin() + static_cast<std::ptrdiff_t>(first), arrows.end(),
                                     [&](const LinkArrow& a) { return a.target_id == target_id; });
            if (same == arrows.end()) {
                LinkArrow arrow;
                arrow.source_id = source.id;
                arrow.target_id = target_id;
                arrow.role = contains(selected, source.id)   ? ArrowRole::Outgoing
                             : contains(selected, target_id) ? ArrowRole::Incoming
                                                             : ArrowRole::Other;
                shape_curve(arrow, entity_obb(source), entity_obb(target));
                arrows.push_back(std::move(arrow));
                same = arrows.end() - 1;
            }
            same->labels.push_back(link_label(link));
        }
    }
    return arrows;
}

void arrow_lines(const LinkArrow& arrow, int segments, std::vector<MarkerLine>& out) {
    segments = std::max(1, segments);
    Vec3 previous = arrow.from;
    for (int i = 1; i <= segments; ++i) {
        const Vec3 p = arrow.point_at(static_cast<float>(i) / static_cast<float>(segments));
        out.push_back({previous, p});
        previous = p;
    }
    // The head: four lines back from the tip along the curve's last direction, spread on two axes across it
    // so that it reads from any view.
    Vec3 back = arrow.control - arrow.to;
    if (glm::length(back) < 1e-4f) back = arrow.from - arrow.to;
    if (glm::length(back) < 1e-4f) return;
    back = glm::normalize(back);
    Vec3 across = glm::cross(back, Vec3(0, 1, 0));
    across = glm::length(across) > 1e-4f ? glm::normalize(across) : Vec3(1, 0, 0);
    const Vec3 across2 = glm::normalize(glm::cross(back, across));
    const float size = std::clamp(glm::length(arrow.to - arrow.from) * 0.08f, 0.5f, 1.5f);
    const Vec3 base = arrow.to + back * size;
    for (const Vec3& spread : {across, -across, across2, -across2})
        out.push_back({arrow.to, base + spread * (size * 0.45f)});
}

} // namespace ks::editor
