#include "ui/view_camera.h"

#include <GLFW/glfw3.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace ks::editor::ui {

const char* view_mode_name(ViewMode mode) {
    switch (mode) {
    case ViewMode::Perspective:
        return "Perspective";
    case ViewMode::Top:
        return "Top";
    case ViewMode::Front:
        return "Front";
    case ViewMode::Side:
        return "Side";
    }
    return "?";
}

namespace {
constexpr float kAxisFov = 4.0f; // degrees, the near-orthographic lens of the axis views

bool key(GLFWwindow* w, int k) {
    return glfwGetKey(w, k) == GLFW_PRESS;
}
} // namespace

bool ViewCamera::update(GLFWwindow* window, double dt, bool hovered, float wheel) {
    double mx = 0, my = 0;
    glfwGetCursorPos(window, &mx, &my);
    const bool right = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
    const bool left = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
    const bool alt = key(window, GLFW_KEY_LEFT_ALT) || key(window, GLFW_KEY_RIGHT_ALT);
    if (!flying_ && !orbiting_ && hovered) {
        if (right)
            flying_ = true;
        else if (left && alt)
            orbiting_ = true;
        last_x_ = mx;
        last_y_ = my;
    }
    if (flying_ && !right) flying_ = false;
    if (orbiting_ && !left) orbiting_ = false;
    const float dx = static_cast<float>(mx - last_x_), dy = static_cast<float>(my - last_y_);
    last_x_ = mx;
    last_y_ = my;

    if (flying_) {
        if (mode != ViewMode::Perspective) { // leaving an axis view keeps where it looks
            mode = ViewMode::Perspective;
            camera.fov_y = radians(60.0f);
        }
        camera.yaw -= dx * 0.004f;
        camera.pitch = std::clamp(camera.pitch - dy * 0.004f, -1.55f, 1.55f);
        if (wheel != 0.0f) speed = std::clamp(speed * std::pow(1.2f, wheel), 0.5f, 400.0f);
        const Vec3 fwd = camera.forward();
        const Vec3 right_dir(std::cos(camera.yaw), 0.0f, -std::sin(camera.yaw));
        Vec3 move(0.0f);
        // Physical keys: GLFW key codes name positions on a US layout, whatever the user's layout is.
        if (key(window, GLFW_KEY_W)) move += fwd;
        if (key(window, GLFW_KEY_S)) move -= fwd;
        if (key(window, GLFW_KEY_D)) move += right_dir;
        if (key(window, GLFW_KEY_A)) move -= right_dir;
        if (key(window, GLFW_KEY_E)) move.y += 1.0f;
        if (key(window, GLFW_KEY_Q)) move.y -= 1.0f;
        const float boost = key(window, GLFW_KEY_LEFT_SHIFT) ? 3.0f : 1.0f;
        if (glm::length(move) > 0.0f)
            camera.position += glm::normalize(move) * speed * boost * static_cast<float>(dt);
        return true;
    }
    if (orbiting_) {
        if (mode != ViewMode::Perspective) {
            mode = ViewMode::Perspective;
            camera.fov_y = radians(60.0f);
            camera.position = pivot - camera.forward() * 40.0f;
        }
        const float distance = std::max(0.5f, glm::length(camera.position - pivot));
        camera.yaw -= dx * 0.005f;
        camera.pitch = std::clamp(camera.pitch - dy * 0.005f, -1.55f, 1.55f);
        camera.position = pivot - camera.forward() * distance;
        return true;
    }
    if (hovered && wheel != 0.0f) { // dolly toward what the camera looks at
        const float step = mode == ViewMode::Perspective ? speed * 0.25f : speed * 2.0f;
        camera.position += camera.forward() * wheel * step;
    }
    return false;
}

void ViewCamera::focus(const Vec3& min, const Vec3& max) {
    pivot = (min + max) * 0.5f;
    const float radius = std::max(1.5f, glm::length(max - min) * 0.5f);
    const float distance = radius / std::sin(camera.fov_y * 0.5f) * 1.1f;
    camera.position = pivot - camera.forward() * distance;
}

void ViewCamera::set_view(ViewMode view, const Vec3& centre, float extent) {
    mode = view;
    pivot = centre;
    if (view == ViewMode::Perspective) {
        camera.fov_y = radians(60.0f);
        camera.yaw = radians(-35.0f);
        camera.pitch = radians(-35.0f);
        camera.position = centre - camera.forward() * std::max(10.0f, extent * 0.8f);
        return;
    }
    camera.fov_y = radians(kAxisFov);
    const float distance = std::max(20.0f, extent) / std::tan(camera.fov_y * 0.5f) * 0.55f;
    switch (view) {
    case ViewMode::Top:
        camera.yaw = 0.0f;
        camera.pitch = radians(-89.9f);
        break;
    case ViewMode::Front:
        camera.yaw = 0.0f;
        camera.pitch = 0.0f;
        break;
    case ViewMode::Side:
        camera.yaw = radians(90.0f);
        camera.pitch = 0.0f;
        break;
    default:
        break;
    }
    camera.far_plane = std::max(1000.0f, distance * 2.0f);
    camera.near_plane = std::max(0.1f, distance * 0.2f);
    camera.position = centre - camera.forward() * distance;
}

Ray ViewCamera::ray(float x, float y, float width, float height) const {
    render::Camera cam = camera;
    cam.aspect = width / std::max(1.0f, height);
    const Mat4 inverse = glm::inverse(cam.projection() * cam.view());
    const float nx = 2.0f * x / width - 1.0f, ny = 1.0f - 2.0f * y / height;
    Vec4 a = inverse * Vec4(nx, ny, -1.0f, 1.0f);
    Vec4 b = inverse * Vec4(nx, ny, 1.0f, 1.0f);
    Vec3 pa = Vec3(a) / a.w, pb = Vec3(b) / b.w;
    return {pa, glm::normalize(pb - pa)};
}

bool ViewCamera::project(const Vec3& world, float width, float height, Vec2& out) const {
    render::Camera cam = camera;
    cam.aspect = width / std::max(1.0f, height);
    const Vec4 clip = cam.projection() * cam.view() * Vec4(world, 1.0f);
    if (clip.w <= 1e-4f) return false;
    out = Vec2((clip.x / clip.w * 0.5f + 0.5f) * width, (0.5f - clip.y / clip.w * 0.5f) * height);
    return true;
}

} // namespace ks::editor::ui
