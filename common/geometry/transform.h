#pragma once
// A rigid placement: a position and a rotation. Physics bodies, the level's entity frames and the shapes
// built from them all place things with this one type.
#include "core/math.h"

#include <glm/gtc/matrix_transform.hpp>

namespace ks::geometry {

struct Transform {
    Vec3 position{0.0f};
    Quat rotation{1.0f, 0.0f, 0.0f, 0.0f};

    Vec3 to_world(const Vec3& local) const { return position + rotation * local; }
    Vec3 to_local(const Vec3& world) const { return glm::conjugate(rotation) * (world - position); }
    Vec3 dir_to_world(const Vec3& local) const { return rotation * local; }
    Vec3 dir_to_local(const Vec3& world) const { return glm::conjugate(rotation) * world; }
    Mat4 matrix() const { return glm::translate(Mat4(1.0f), position) * glm::mat4_cast(rotation); }
};

} // namespace ks::geometry
