#include "view/view_camera.h"

#include <algorithm>
#include <cmath>

namespace ks::editor {

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
constexpr float kPerspectiveFov = 1.0471976f; // 60 degrees
constexpr float kMinOrthoHeight = 0.5f, kMaxOrthoHeight = 20000.0f;
} // namespace

void ViewCamera::set_viewport(Vec2 size) {
    viewport_ = glm::max(size, Vec2(1.0f));
    camera.aspect = viewport_.x / viewport_.y;
}

Vec3 ViewCamera::forward() const {
    return -camera.basis()[2];
}
Vec3 ViewCamera::right() const {
    return camera.basis()[0];
}
Vec3 ViewCamera::up() const {
    return camera.basis()[1];
}

Mat4 ViewCamera::view_projection() const {
    geometry::Camera c = camera;
    c.aspect = viewport_.x / viewport_.y;
    return c.view_projection();
}

float ViewCamera::world_per_pixel(const Vec3& at) const {
    if (orthographic()) return camera.ortho_height / viewport_.y;
    const float depth = std::max(0.5f, glm::dot(at - camera.position, forward()));
    return depth * 2.0f * std::tan(camera.fov_y * 0.5f) / viewport_.y;
}

geometry::Ray ViewCamera::ray(Vec2 pixel) const {
    return geometry::screen_ray(camera, pixel, viewport_);
}

bool ViewCamera::project(const Vec3& world, Vec2& out) const {
    return geometry::world_to_screen(camera, world, viewport_, out);
}

void ViewCamera::leave_axis_view() {
    if (!orthographic()) return;
    // The same picture size at the pivot's depth: height = 2 d tan(fov / 2).
    const Vec3 f = forward();
    const Vec3 look = camera.position + f * glm::dot(pivot - camera.position, f);
    const float distance = 0.5f * camera.ortho_height / std::tan(kPerspectiveFov * 0.5f);
    mode = ViewMode::Perspective;
    camera.ortho_height = 0.0f;
    camera.fov_y = kPerspectiveFov;
    camera.near_plane = 0.1f;
    camera.far_plane = 1000.0f;
    pivot = look;
    camera.position = look - f * distance;
}

bool ViewCamera::update(const ViewInput& in, double dt) {
    const bool pan_button = in.middle || (orthographic() && in.right);
    if (!flying_ && !orbiting_ && !panning_ && in.hovered) {
        if (pan_button)
            panning_ = true;
        else if (in.right)
            flying_ = true;
        else if (in.left && in.alt)
            orbiting_ = true;
        last_ = in.mouse;
    }
    if (flying_ && !in.right) flying_ = false;
    if (orbiting_ && !in.left) orbiting_ = false;
    if (panning_ && !pan_button) panning_ = false;
    const Vec2 d = in.mouse - last_;
    last_ = in.mouse;

    if (panning_) {
        pan_pixels(d.x, d.y);
        if (orthographic() && in.wheel != 0.0f) zoom_at(in.wheel, in.mouse);
        return true;
    }
    if (flying_) {
        camera.yaw -= d.x * 0.004f;
        camera.pitch = std::clamp(camera.pitch - d.y * 0.004f, -1.55f, 1.55f);
        if (in.wheel != 0.0f) speed = std::clamp(speed * std::pow(1.2f, in.wheel), 0.5f, 400.0f);
        const Vec3 fwd = forward();
        const Vec3 right_dir(std::cos(camera.yaw), 0.0f, -std::sin(camera.yaw));
        Vec3 move(0.0f);
        if (in.forward) move += fwd;
        if (in.back) move -= fwd;
        if (in.strafe_right) move += right_dir;
        if (in.strafe_left) move -= right_dir;
        if (in.up) move.y += 1.0f;
        if (in.down) move.y -= 1.0f;
        const float boost = in.boost ? 3.0f : 1.0f;
        if (glm::length(move) > 0.0f)
            camera.position += glm::normalize(move) * speed * boost * static_cast<float>(dt);
        return true;
    }
    if (orbiting_) {
        leave_axis_view(); // orbiting an axis view turns it into a perspective one, as in Blender
        const float distance = std::max(0.5f, glm::length(camera.position - pivot));
        camera.yaw -= d.x * 0.005f;
        camera.pitch = std::clamp(camera.pitch - d.y * 0.005f, -1.55f, 1.55f);
        camera.position = pivot - forward() * distance;
        return true;
    }
    if (in.hovered && in.wheel != 0.0f) {
        if (orthographic())
            zoom_at(in.wheel, in.mouse);
        else // dolly toward what the camera looks at
            camera.position += forward() * in.wheel * speed * 0.25f;
    }
    return false;
}

void ViewCamera::zoom_at(float wheel, Vec2 mouse) {
    if (!orthographic()) return;
    const geometry::Ray before = ray(mouse);
    const float old_height = camera.ortho_height;
    camera.ortho_height = std::clamp(old_height * std::pow(0.85f, wheel), kMinOrthoHeight, kMaxOrthoHeight);
    // The pixel's offset on the camera plane scales with the height; move the camera by the difference.
    const Vec3 offset = before.origin - camera.position;
    camera.position += offset * (1.0f - camera.ortho_height / old_height);
}

void ViewCamera::pan_pixels(float dx, float dy) {
    const float scale = world_per_pixel(pivot);
    const Vec3 move = (-right() * dx + up() * dy) * scale;
    camera.position += move;
    pivot += move;
}

void ViewCamera::focus(const Vec3& min, const Vec3& max) {
    pivot = (min + max) * 0.5f;
    const float radius = std::max(1.5f, glm::length(max - min) * 0.5f);
    if (orthographic()) {
        camera.ortho_height = std::clamp(radius * 2.2f, kMinOrthoHeight, kMaxOrthoHeight);
        const float distance = std::max(glm::dot(pivot - camera.position, forward()), radius + 50.0f);
        camera.far_plane = std::max(camera.far_plane, distance + radius + 50.0f);
        camera.position = pivot - forward() * distance;
        return;
    }
    const float distance = radius / std::sin(camera.fov_y * 0.5f) * 1.1f;
    camera.position = pivot - forward() * distance;
}

void ViewCamera::set_view(ViewMode view, const Vec3& centre, float extent) {
    mode = view;
    pivot = centre;
    extent = std::max(extent, 8.0f);
    camera.roll = 0.0f;
    if (view == ViewMode::Perspective) {
        camera.ortho_height = 0.0f;
        camera.fov_y = kPerspectiveFov;
        camera.near_plane = 0.1f;
        camera.far_plane = 1000.0f;
        camera.yaw = radians(-35.0f);
        camera.pitch = radians(-35.0f);
        camera.position = centre - forward() * std::max(10.0f, extent * 0.8f);
        return;
    }
    switch (view) {
    case ViewMode::Top: // screen up is -z (north), right is +x
        camera.yaw = 0.0f;
        camera.pitch = radians(-90.0f);
        break;
    case ViewMode::Front: // looking along -z: right +x, up +y
        camera.yaw = 0.0f;
        camera.pitch = 0.0f;
        break;
    case ViewMode::Side: // looking along -x: right -z, up +y
        camera.yaw = radians(90.0f);
        camera.pitch = 0.0f;
        break;
    default:
        break;
    }
    // Far enough back that the whole level is in front of the camera; orthographic depth is linear, so a
    // deep range costs no precision where it matters.
    const float distance = extent + 100.0f;
    camera.ortho_height = extent * 1.1f;
    camera.near_plane = 0.5f;
    camera.far_plane = 2.0f * distance + extent;
    camera.position = centre - forward() * distance;
}

GridPlan plan_axis_grid(const ViewCamera& view, float base_step, float min_pixels) {
    GridPlan plan;
    const Vec3 r = glm::abs(view.right()), u = glm::abs(view.up());
    plan.u_axis = r.x >= r.y && r.x >= r.z ? 0 : (r.y >= r.z ? 1 : 2);
    plan.v_axis = u.x >= u.y && u.x >= u.z ? 0 : (u.y >= u.z ? 1 : 2);
    const float wpp = view.world_per_pixel(view.pivot);
    float step = std::max(base_step, 1e-3f);
    while (step / wpp < min_pixels && step < 1e6f) step *= 2.0f;
    plan.step = step;
    const Vec2 size = view.viewport();
    const float half_w = 0.5f * size.x * wpp, half_h = 0.5f * size.y * wpp;
    const Vec3 c = view.camera.position;
    auto lines = [&](float centre, float half, float& first, int& count) {
        first = std::ceil((centre - half) / step) * step;
        count = std::clamp(static_cast<int>(std::floor((centre + half - first) / step)) + 1, 0, 4096);
    };
    lines(c[plan.u_axis], half_w, plan.u_first, plan.u_count);
    lines(c[plan.v_axis], half_h, plan.v_first, plan.v_count);
    return plan;
}

} // namespace ks::editor
