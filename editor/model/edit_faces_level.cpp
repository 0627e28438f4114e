// Brush faces, the level-wide part of edit_faces.h: replacing a texture everywhere, and texture lock.
#include "brush/texture_mapping.h"
#include "model/edit_faces.h"
#include "model/field_access.h"

#include <cmath>

namespace ks::editor {
namespace {
using level::Entity;

// The entity's frame as a rotation and a translation in double.
struct EntityFrame {
    glm::dmat3 rotation;
    DVec3 position;
};
EntityFrame frame_of(const Entity& e) {
    return {glm::mat3_cast(dquat_from_ypr_degrees(DVec3(e.rotation))), DVec3(e.position)};
}

} // namespace

Result<int> replace_texture(Editor& editor, const std::string& from, const std::string& to) {
    constexpr const char* kWhat = "Replace texture";
    if (to.empty() || to.find_first_of(" \t\n") != std::string::npos)
        return Error(std::string(kWhat) + ": the new material must be one word, got \"" + to + "\"",
                     Location{}, "pick one from the texture browser");
    if (from == to)
        return Error(std::string(kWhat) + ": '" + from + "' would replace itself", Location{},
                     "give two different materials");
    const Document& doc = editor.doc();
    auto change = std::make_unique<LevelChange>();
    int replaced = 0;
    for (const Entity& e : doc.level.entities) {
        if (doc.locked.contains(e.id)) continue;
        if (const auto* props = e.try_as<level::BrushProps>()) {
            // Only the attributes change: the planes stay, so the brush is not derived again.
            std::vector<brush::FaceAttributes> attributes;
            int here = 0;
            for (const brush::Face& f : props->brush.faces()) {
                attributes.push_back(f.attributes);
                if (f.attributes.material == from) attributes.back().material = to, ++here;
            }
            if (here == 0) continue;
            auto swapped = props->brush.with_attributes(std::move(attributes));
            if (!swapped)
                return Error(std::string(kWhat) + ": brush " + std::to_string(e.id) + ": " +
                             swapped.error().message);
            Entity after = e;
            after.as<level::BrushProps>().brush = std::move(*swapped);
            change->updates.push_back({e, std::move(after)});
            replaced += here;
        } else {
            auto current = get_entity_field(e, "texture");
            if (!current || *current != FieldValue(from)) continue;
            Entity after = e;
            if (auto r = set_entity_field(after, "texture", FieldValue(to)); !r)
                return Error(std::string(kWhat) + ": entity " + std::to_string(e.id) + ": " +
                             r.error().message);
            ++replaced;
            change->updates.push_back({e, std::move(after)});
        }
    }
    if (replaced == 0)
        return Error(std::string(kWhat) + ": no unlocked brush face or texture field uses '" + from + "'",
                     Location{}, "check the name (the texture browser lists the materials in use)");
    change->set_name(kWhat);
    editor.execute(std::move(change), doc.selection);
    return replaced;
}

void set_texture_lock(Editor& editor, bool on) {
    editor.face_session().texture_lock = on;
}

Result<void> keep_textures_on_world(const Entity& before, Entity& after) {
    auto* props = after.try_as<level::BrushProps>();
    if (!props || !before.try_as<level::BrushProps>()) return ok();
    if (before.position == after.position && before.rotation == after.rotation) return ok();
    if (!is_finite(after.position) || !is_finite(after.rotation)) return ok(); // the field check refuses it
    const EntityFrame was = frame_of(before), now = frame_of(after);
    const glm::dmat3 back = glm::transpose(now.rotation);
    const auto& local = props->brush.faces();
    std::vector<brush::FaceAttributes> attributes;
    for (size_t i = 0; i < local.size(); ++i) {
        // The face's world mapping before the motion, carried onto its plane after it, then back into the
        // entity's frame: the inverse of what world_brush applies.
        const brush::FaceAttributes world = brush::locked_attributes(local[i], was.rotation, was.position);
        const brush::Face moved{{glm::normalize(now.rotation * local[i].plane.normal), 0.0}, world};
        brush::FaceAttributes kept = brush::locked_attributes(moved, back, -(back * now.position));
        // A move without a turn leaves the angle as it was, not a rounding away from it.
        if (std::abs(std::remainder(kept.rotation_degrees - local[i].attributes.rotation_degrees, 360.0)) <
            1e-9)
            kept.rotation_degrees = local[i].attributes.rotation_degrees;
        attributes.push_back(kept);
    }
    auto rebuilt = props->brush.with_attributes(std::move(attributes));
    if (!rebuilt) return Error("texture lock: " + rebuilt.error().message);
    props->brush = std::move(*rebuilt);
    return ok();
}

} // namespace ks::editor
