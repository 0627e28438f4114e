#include "view/patrol_drag.h"
#include "model/edit_patrols.h"

#include "view/gizmo.h"

namespace ks::editor {
namespace {

const Vec3 kUp(0.0f, 1.0f, 0.0f);

} // namespace

std::optional<PatrolPointHit> pick_patrol_point(const Editor& editor, const ViewCamera& view, Vec2 mouse,
                                                float max_pixels) {
    std::optional<PatrolPointHit> best;
    float best_distance = max_pixels;
    for (int id : editor.doc().selection) {
        const level::Entity* e = editor.level().find(id);
        const auto* robot = e ? e->try_as<level::RobotProps>() : nullptr;
        if (!robot) continue;
        for (std::size_t i = 0; i < robot->patrol.points.size(); ++i) {
            Vec2 at;
            if (!view.project(robot->patrol.points[i], at)) continue;
            const float d = glm::length(at - mouse);
            if (d <= best_distance) {
                best_distance = d;
                best = PatrolPointHit{id, static_cast<int>(i)};
            }
        }
    }
    return best;
}

void PatrolDrag::begin(const Editor& editor, const ViewCamera& view, PatrolPointHit hit, Vec2 mouse) {
    const level::Entity* e = editor.level().find(hit.robot_id);
    if (!e || !e->try_as<level::RobotProps>()) return;
    start_ = e->as<level::RobotProps>().patrol.points[static_cast<std::size_t>(hit.index)];
    // Grabbed off-centre, the point keeps its offset from the cursor instead of jumping under it.
    grab_ = plane_point(view.ray(mouse), start_, kUp).value_or(start_);
    hit_ = hit;
    merge_key_ = "patrol drag " + std::to_string(++drag_count_);
}

std::string PatrolDrag::drag(Editor& editor, const ViewCamera& view, Vec2 mouse) {
    if (!hit_) return {};
    const auto on_plane = plane_point(view.ray(mouse), start_, kUp);
    if (!on_plane) return {}; // the plane is edge-on or behind: keep the point where it is
    // With Snap on, the point lands on the grid in x and z (as a palette click does); its height is kept.
    const GridSettings& grid = editor.doc().grid;
    const Vec3 free = start_ + (*on_plane - grab_);
    const Vec3 moved(grid.snap_value(free.x), free.y, grid.snap_value(free.z));
    auto r = patrol_move(editor, hit_->robot_id, hit_->index, moved, merge_key_);
    return r ? std::string() : "patrol drag: " + r.error().str();
}

} // namespace ks::editor
