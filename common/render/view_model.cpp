#include "render/view_model.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace ks::render {

Mat4 rifle_view_transform(float recoil) {
    recoil = is_finite(recoil) ? std::clamp(recoil, 0.0f, 1.0f) : 0.0f;
    // Kick: back toward the camera and the muzzle up.
    Vec3 position(0.3f, -0.25f + 0.02f * recoil, -0.75f + 0.12f * recoil);
    Mat4 m = glm::translate(Mat4(1.0f), position);
    m = glm::rotate(m, kPi / 14.0f * 0.5f, Vec3(0, 1, 0));
    m = glm::rotate(m, 0.05f + 0.15f * recoil, Vec3(1, 0, 0));
    return m;
}

} // namespace ks::render
