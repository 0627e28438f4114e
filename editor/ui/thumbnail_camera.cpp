#include "ui/thumbnail_camera.h"

#include <algorithm>
#include <cmath>

namespace ks::editor::ui {

geometry::Camera thumbnail_camera(Vec3 lo, Vec3 hi) {
    geometry::Camera camera;
    camera.aspect = 1.0f;
    camera.fov_y = radians(40.0f);
    camera.yaw = radians(35.0f);
    camera.pitch = radians(-28.0f);
    const Vec3 centre = (lo + hi) * 0.5f;
    const float radius = std::max(0.5f, glm::length(hi - lo) * 0.5f);
    const float distance = radius / std::sin(camera.fov_y * 0.5f) * 1.02f;
    camera.position = centre - camera.forward() * distance;
    camera.near_plane = std::max(0.05f, distance - radius * 2.0f);
    camera.far_plane = distance + radius * 2.0f;
    return camera;
}

} // namespace ks::editor::ui
