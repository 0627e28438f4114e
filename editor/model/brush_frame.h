#pragma once
// A brush entity's frame: world = rotation * local + position, the transform level::world_brush applies.
// The geometry tools read a brush's derived local brush through it instead of deriving a world copy every
// frame (the snapped pointer, the vertex tool).
#include "core/math.h"
#include "level/level.h"

namespace ks::editor {

struct BrushFrame {
    glm::dmat3 rotation{1.0};
    DVec3 position{0.0};
    explicit BrushFrame(const level::Entity& e)
        : rotation(glm::mat3_cast(dquat_from_ypr_degrees(DVec3(e.rotation)))), position(e.position) {}
    DVec3 to_world(const DVec3& local) const { return rotation * local + position; }
    DVec3 to_local(const DVec3& world) const { return glm::transpose(rotation) * (world - position); }
    // A world-space displacement in the brush's frame (no translation).
    DVec3 local_delta(const DVec3& world) const { return glm::transpose(rotation) * world; }
};

} // namespace ks::editor
