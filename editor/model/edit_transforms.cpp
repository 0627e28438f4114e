// Moving, nudging, turning and scaling the selection: edit_transforms.h. Each is one LevelChange through
// Editor::modify_selection.
#include "model/edit_transforms.h"

#include "model/edit_selection.h"
#include "model/field_access.h"

#include <cmath>

namespace ks::editor {
using level::Entity;
using level::EntityType;

Result<void> move_selection(Editor& editor, Vec3 delta, bool snap, std::string merge_key) {
    const Document& doc = editor.doc();
    if (!is_finite(delta)) return Error("move: the offset must be finite numbers");
    if (snap && !doc.selection.empty()) {
        if (doc.selection.front() == kPlayerStartId) {
            const Vec3 start = doc.level.player_start.position;
            delta = doc.grid.snap_point(start + delta) - start;
        } else if (const Entity* primary = doc.level.find(doc.selection.front())) {
            delta = doc.grid.snap_point(primary->position + delta) - primary->position;
        }
    }
    return editor.modify_selection(
        "Move", [&](Entity& e) { return set_entity_field(e, "position", e.position + delta); },
        std::move(merge_key),
        [&](level::PlayerStart& start) -> Result<void> {
            start.position += delta;
            return ok();
        },
        [&](level::Group& group) { group.position += delta; });
}

Result<void> nudge(Editor& editor, int axis, int direction) {
    const Document& doc = editor.doc();
    if (axis < 0 || axis > 2 || (direction != 1 && direction != -1))
        return Error("nudge: axis must be 0..2 and direction +1 or -1");
    Vec3 delta(0.0f);
    delta[axis] = static_cast<float>(direction) * doc.grid.step;
    return move_selection(editor, delta, false, "nudge");
}

Result<void> scale_selection(Editor& editor, Vec3 factors, std::string merge_key) {
    const Document& doc = editor.doc();
    if (!is_finite(factors) || factors.x <= 0 || factors.y <= 0 || factors.z <= 0)
        return Error("scale: factors must be positive finite numbers");
    bool any = false;
    auto result = editor.modify_selection(
        "Scale",
        [&](Entity& e) -> Result<void> {
            auto scale_field = [&](const char* field, auto scaled) -> Result<void> {
                any = true;
                auto current = get_entity_field(e, field);
                if (!current) return current.error();
                return set_entity_field(e, field, scaled(*current));
            };
            auto vec3 = [&](const FieldValue& v) { return FieldValue(std::get<Vec3>(v) * factors); };
            auto by = [](float f) {
                return [f](const FieldValue& v) {
                    return FieldValue(std::get<double>(v) * static_cast<double>(f));
                };
            };
            switch (e.type()) {
            case EntityType::Wall:
            case EntityType::Stair:
            case EntityType::ControlPanel:
                return scale_field("size", vec3);
            case EntityType::Floor:
                return scale_field("size", [&](const FieldValue& v) {
                    return FieldValue(std::get<Vec2>(v) * Vec2(factors.x, factors.z));
                });
            case EntityType::Door:
                if (auto r = scale_field("width", by(factors.x)); !r) return r;
                return scale_field("height", by(factors.y));
            case EntityType::GasCylinder:
                if (auto r = scale_field("radius", by(factors.x)); !r) return r;
                return scale_field("height", by(factors.y));
            default:
                return ok(); // no size fields: robots, pickups and lights keep their model size
            }
        },
        std::move(merge_key));
    if (result && !any && !doc.selection.empty())
        return Error("Scale: none of the selected entities has size fields", Location{},
                     "walls, floors, stairs, doors, gas cylinders and the control panel can be scaled");
    return result;
}

Result<void> rotate_selection(Editor& editor, float degrees, std::string merge_key) {
    return rotate_selection_about(editor, 1, degrees, RotationSpace::World, true, std::move(merge_key));
}

Result<void> rotate_selection_about(Editor& editor, int axis, float degrees, RotationSpace space, bool snap,
                                    std::string merge_key) {
    const Document& doc = editor.doc();
    if (axis < 0 || axis > 2) return Error("rotate: the axis must be x, y or z");
    if (!std::isfinite(degrees)) return Error("rotate: the angle must be a finite number");
    if (doc.selection.empty())
        return Error("Rotate: nothing is selected", Location{}, "select entities first");
    if (axis != 1)
        if (std::string reason = yaw_only_reason(doc); !reason.empty())
            return Error("rotate about " + std::string(1, "xyz"[axis]) + ": " + reason, Location{},
                         "turn it about y, or select only entities that pitch and roll");
    if (snap) degrees = doc.grid.snap_angle(degrees);
    // Pivot: the centre of the selected positions' bounds (a single object turns in place).
    const auto selected = selected_entities(editor);
    const bool with_start = doc.player_start_selected();
    std::vector<Vec3> positions;
    for (const auto* e : selected) positions.push_back(e->position);
    if (with_start) positions.push_back(doc.level.player_start.position);
    if (positions.empty()) return Error("Rotate: nothing is selected", Location{}, "select entities first");
    Vec3 lo = positions.front(), hi = lo;
    for (const Vec3& p : positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const DVec3 pivot = (DVec3(lo) + DVec3(hi)) * 0.5;
    const bool around_pivot = positions.size() > 1 && space == RotationSpace::World;
    auto turned_position = [&](const Vec3& p) {
        return around_pivot ? Vec3(pivot + turned_offset(DVec3(p) - pivot, axis, degrees)) : p;
    };
    const char* name = axis == 1 ? "Rotate" : axis == 0 ? "Rotate about x" : "Rotate about z";
    return editor.modify_selection(
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
