#pragma once
// The renderer's camera maths (common/render/camera.cpp) as inline functions of a render::Camera's fields,
// so the editor's view maths links without the render module (ks_tests_editor links level, physics and
// anim only). tests/runtime/test_editor_view_parity.cpp checks they agree with render::Camera exactly.
#include "core/math.h"
#include "render/camera.h"

#include <glm/gtc/matrix_transform.hpp>

namespace ks::editor {

// Columns: the image's right, up and back directions in world space (yaw about +y, then pitch, then roll).
inline Mat3 camera_basis(const render::Camera& c) {
    Mat4 m = glm::rotate(Mat4(1.0f), c.yaw, Vec3(0, 1, 0));
    m = glm::rotate(m, c.pitch, Vec3(1, 0, 0));
    m = glm::rotate(m, -c.roll, Vec3(0, 0, 1));
    return Mat3(m);
}

inline Vec3 camera_forward(const render::Camera& c) {
    return -camera_basis(c)[2];
}

inline Mat4 camera_view(const render::Camera& c) {
    const Mat3 basis = camera_basis(c);
    Mat4 v(glm::transpose(basis));
    v[3] = Vec4(-(glm::transpose(basis) * c.position), 1.0f);
    return v;
}

inline Mat4 camera_projection(const render::Camera& c) {
    if (c.orthographic()) {
        const float half_h = 0.5f * c.ortho_height, half_w = half_h * c.aspect;
        return glm::ortho(-half_w, half_w, -half_h, half_h, c.near_plane, c.far_plane);
    }
    return glm::perspective(c.fov_y, c.aspect, c.near_plane, c.far_plane);
}

} // namespace ks::editor
