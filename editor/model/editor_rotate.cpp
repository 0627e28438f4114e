// Editor: turning the selection about one axis (the maths are in rotation.h). Each turn is one LevelChange.
#include "model/editor.h"

#include <cmath>

namespace ks::editor {

Result<void> Editor::rotate_selection(float degrees, std::string merge_key) {
    return rotate_selection_about(1, degrees, RotationSpace::World, true, std::move(merge_key));
}

Result<void> Editor::rotate_selection_about(int axis, float degrees, RotationSpace space, bool snap,
                                            std::string merge_key) {
    if (axis < 0 || axis > 2) return Error("rotate: the axis must be x, y or z");
    if (!std::isfinite(degrees)) return Error("rotate: the angle must be a finite number");
    if (doc_.selection.empty())
        return Error("Rotate: nothing is selected", Location{}, "select entities first");
    if (axis != 1)
        if (std::string reason = yaw_only_reason(doc_); !reason.empty())
            return Error("rotate about " + std::string(1, "xyz"[axis]) + ": " + reason, Location{},
                         "turn it about y, or select only entities that pitch and roll");
    if (snap) degrees = doc_.grid.snap_angle(degrees);
    // Pivot: the centre of the selected positions' bounds (a single object turns in place).
    const auto selected = selected_entities();
    const bool with_start = doc_.player_start_selected();
    std::vector<Vec3> positions;
    for (const auto* e : selected) positions.push_back(e->position);
    if (with_start) positions.push_back(doc_.level.player_start.position);
    if (positions.empty()) return Error("Rotate: nothing is selected", Location{}, "select entities first");
    Vec3 lo = positions.front(), hi = lo;
    for (const Vec3& p : positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const DVec3 pivot = (DVec3(lo) + DVec3(hi)) * 0.5;
    const bool around_pivot = positions.size() > 1 && space == RotationSpace::World;
    auto turned_position = [&](const Vec3& p) {
        return around_pivot ? Vec3(pivot + turned_offset(DVec3(p) - pivot, axis, degrees)) : p;
    };
    const char* name = axis == 1 ? "Rotate" : axis == 0 ? "Rotate about x" : "Rotate about z";
    return modify_selection(
        name,
        [&](level::Entity& e) -> Result<void> {
            if (auto r = set_entity_field(e, "position", turned_position(e.position)); !r) return r;
            // Types that stand upright turn by their yaw whatever pitch a file gave them.
            const Vec3 rotation =
                level::keeps_pitch_and_roll(e.type())
                    ? turned_ypr(e.rotation, axis, degrees, space)
                    : Vec3(wrap_degrees(e.rotation.x + degrees), e.rotation.y, e.rotation.z);
            return set_entity_field(e, "rotation", rotation);
        },
        std::move(merge_key),
        [&](level::PlayerStart& start) -> Result<void> {
            start.position = turned_position(start.position);
            start.yaw = wrap_degrees(start.yaw + degrees);
            return ok();
        },
        // A group turned as one about y keeps its frame with its members (a prefab instance stays in line
        // with its prefab); other turns leave the frame, and prefab members record what they changed.
        [&](level::Group& group) {
            if (axis != 1 || (!around_pivot && positions.size() > 1)) return;
            group.position = turned_position(group.position);
            group.yaw = wrap_degrees(group.yaw + degrees);
        });
}

} // namespace ks::editor
