#include "view/gizmo.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ks::editor {

const char* gizmo_mode_name(GizmoMode mode) {
    switch (mode) {
    case GizmoMode::Move:
        return "Move";
    case GizmoMode::Rotate:
        return "Rotate";
    case GizmoMode::Scale:
        return "Scale";
    }
    return "?";
}

namespace {
constexpr float kPlaneNear = 0.18f, kPlaneFar = 0.42f; // plane squares span this part of the axis length
constexpr float kMinAxisPixels = 12.0f;                // an axis shorter on screen points at the viewer
constexpr float kMinPlanePixels2 = 60.0f;              // a plane square smaller on screen is edge-on
constexpr float kMinRingFacing = 0.2f; // |cos| of the ring's normal to the view below this: edge-on
const Vec3 kAxes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

float distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
    const Vec2 ab = b - a;
    const float len2 = glm::dot(ab, ab);
    const float t = len2 > 0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
    return glm::length(p - (a + ab * t));
}

bool inside_quad(Vec2 p, const std::array<Vec2, 4>& q) {
    int sign = 0;
    for (int i = 0; i < 4; ++i) {
        const Vec2 e = q[(i + 1) % 4] - q[i], r = p - q[i];
        const float c = e.x * r.y - e.y * r.x;
        const int s = c > 0 ? 1 : (c < 0 ? -1 : 0);
        if (s != 0 && sign != 0 && s != sign) return false;
        if (s != 0) sign = s;
    }
    return true;
}

float quad_area(const std::array<Vec2, 4>& q) {
    float a = 0.0f;
    for (int i = 0; i < 4; ++i) a += q[i].x * q[(i + 1) % 4].y - q[(i + 1) % 4].x * q[i].y;
    return 0.5f * std::abs(a);
}

int axis_of(Handle h) {
    return h == Handle::AxisX ? 0 : h == Handle::AxisY ? 1 : h == Handle::AxisZ ? 2 : -1;
}
int plane_index(Handle h) {
    return h == Handle::PlaneXY ? 0 : h == Handle::PlaneXZ ? 1 : h == Handle::PlaneYZ ? 2 : -1;
}
// The plane handles' axes (u, v) and normal, in the order XY, XZ, YZ.
constexpr int kPlaneU[3] = {0, 0, 1}, kPlaneV[3] = {1, 2, 2}, kPlaneNormal[3] = {2, 1, 0};
constexpr Handle kPlaneHandles[3] = {Handle::PlaneXY, Handle::PlaneXZ, Handle::PlaneYZ};
constexpr Handle kAxisHandles[3] = {Handle::AxisX, Handle::AxisY, Handle::AxisZ};
} // namespace

GizmoShape gizmo_shape(const ViewCamera& view, const Vec3& pivot) {
    GizmoShape s;
    if (!view.project(pivot, s.centre)) return s;
    s.valid = true;
    s.length = view.world_per_pixel(pivot) * view.viewport().y * kGizmoScreenFraction;
    for (int i = 0; i < 3; ++i) {
        s.axis_visible[i] = view.project(pivot + kAxes[i] * s.length, s.tips[i]) &&
                            glm::length(s.tips[i] - s.centre) >= kMinAxisPixels;
        const float a = s.length * kPlaneNear, b = s.length * kPlaneFar;
        const Vec3 u = kAxes[kPlaneU[i]], v = kAxes[kPlaneV[i]];
        const Vec3 corners[4] = {pivot + u * a + v * a, pivot + u * b + v * a, pivot + u * b + v * b,
                                 pivot + u * a + v * b};
        bool ok = true;
        for (int k = 0; k < 4; ++k) ok = view.project(corners[k], s.planes[i][k]) && ok;
        s.plane_visible[i] = ok && quad_area(s.planes[i]) >= kMinPlanePixels2;
    }
    bool ring_ok = std::abs(glm::dot(view.forward(), kAxes[1])) >= kMinRingFacing ||
                   !view.orthographic(); // perspective: the ring is an ellipse unless seen exactly level
    for (int i = 0; i <= kGizmoRingSegments; ++i) {
        const float a = static_cast<float>(i) / kGizmoRingSegments * 6.2831853f;
        ring_ok = view.project(pivot + Vec3(std::cos(a), 0, std::sin(a)) * s.length, s.ring[i]) && ring_ok;
    }
    s.ring_visible = ring_ok;
    return s;
}

Handle gizmo_hit(GizmoMode mode, const GizmoShape& s, Vec2 mouse) {
    if (!s.valid) return Handle::None;
    if (mode == GizmoMode::Rotate) {
        if (!s.ring_visible) return Handle::None;
        for (int i = 0; i < kGizmoRingSegments; ++i)
            if (distance_to_segment(mouse, s.ring[i], s.ring[i + 1]) < kGizmoPickPixels) return Handle::Yaw;
        return Handle::None;
    }
    if (mode == GizmoMode::Move)
        for (int i = 0; i < 3; ++i)
            if (s.plane_visible[i] && inside_quad(mouse, s.planes[i])) return kPlaneHandles[i];
    float best = kGizmoPickPixels;
    Handle best_handle = Handle::None;
    for (int i = 0; i < 3; ++i) {
        if (!s.axis_visible[i]) continue;
        const float d = distance_to_segment(mouse, s.centre, s.tips[i]);
        if (d < best) best = d, best_handle = kAxisHandles[i];
    }
    return best_handle;
}

std::optional<float> axis_parameter(const geometry::Ray& ray, const Vec3& pivot, const Vec3& axis) {
    const Vec3 w0 = pivot - ray.origin;
    const float b = glm::dot(axis, ray.direction);
    const float denom = 1.0f - b * b;
    if (denom < 1e-5f) return std::nullopt; // looking down the axis: no motion along it
    return (b * glm::dot(ray.direction, w0) - glm::dot(axis, w0)) / denom;
}

std::optional<Vec3> plane_point(const geometry::Ray& ray, const Vec3& pivot, const Vec3& normal) {
    const float denom = glm::dot(normal, ray.direction);
    if (std::abs(denom) < 1e-5f) return std::nullopt; // edge-on plane
    const float t = glm::dot(pivot - ray.origin, normal) / denom;
    if (t < 0.0f) return std::nullopt;
    return ray.origin + ray.direction * t;
}

void Gizmo::begin(Editor& editor, const ViewCamera& view, const Vec3& pivot, Handle handle, Vec2 mouse) {
    active_ = handle;
    pivot_ = pivot;
    length_ = gizmo_shape(view, pivot).length;
    applied_move_ = Vec3(0.0f);
    applied_angle_ = 0.0f;
    applied_scale_ = Vec3(1.0f);
    readout_.clear();
    const geometry::Ray r = view.ray(mouse);
    if (const int axis = axis_of(handle); axis >= 0) {
        start_param_ = axis_parameter(r, pivot, kAxes[axis]).value_or(0.0f);
    } else if (handle == Handle::Yaw) {
        const auto p = plane_point(r, pivot, kAxes[1]);
        start_param_ = p ? std::atan2(p->z - pivot.z, p->x - pivot.x) : 0.0f;
    } else {
        start_point_ = plane_point(r, pivot, kAxes[kPlaneNormal[plane_index(handle)]]).value_or(pivot);
    }
    editor.begin_transaction(mode == GizmoMode::Move     ? "Move (gizmo)"
                             : mode == GizmoMode::Rotate ? "Rotate (gizmo)"
                                                         : "Scale (gizmo)");
}

std::string Gizmo::drag(Editor& editor, const ViewCamera& view, Vec2 mouse) {
    if (active_ == Handle::None) return {};
    const GridSettings& grid = editor.doc().grid;
    const geometry::Ray r = view.ray(mouse);
    char text[96];
    Result<void> result;
    auto move_to = [&](const Vec3& total) {
        const Vec3 increment = total - applied_move_;
        if (increment != Vec3(0.0f)) {
            result = editor.move_selection(increment);
            if (result) applied_move_ = total;
        }
        std::snprintf(text, sizeof(text), "move %+.2f, %+.2f, %+.2f", applied_move_.x, applied_move_.y,
                      applied_move_.z);
    };
    if (active_ == Handle::Yaw) {
        const auto p = plane_point(r, pivot_, kAxes[1]);
        if (!p) return {};
        // The angle is measured from +x toward +z; the level's yaw turns the other way (counterclockwise
        // seen from above).
        const float angle = -(std::atan2(p->z - pivot_.z, p->x - pivot_.x) - start_param_);
        const float degrees = grid.snap_angle(std::remainder(angle * 57.29578f, 360.0f));
        const float increment = degrees - applied_angle_;
        if (increment != 0.0f) {
            result = editor.rotate_selection(increment);
            if (result) applied_angle_ = degrees;
        }
        std::snprintf(text, sizeof(text), "yaw %+.1f deg", applied_angle_);
    } else if (const int axis = axis_of(active_); axis >= 0) {
        const auto param = axis_parameter(r, pivot_, kAxes[axis]);
        if (!param) return {};
        const float t = *param - start_param_;
        if (mode == GizmoMode::Scale) {
            float factor = std::max(0.05f, 1.0f + t / length_);
            if (grid.snap) factor = std::max(0.1f, std::round(factor * 10.0f) / 10.0f);
            Vec3 target(1.0f);
            target[axis] = factor;
            const Vec3 increment = target / applied_scale_;
            if (increment != Vec3(1.0f)) {
                result = editor.scale_selection(increment);
                if (result) applied_scale_ = target;
            }
            std::snprintf(text, sizeof(text), "scale %c x%.2f", "xyz"[axis], applied_scale_[axis]);
        } else {
            Vec3 total(0.0f);
            total[axis] = grid.snap_value(t);
            move_to(total);
        }
    } else {
        const int k = plane_index(active_);
        const auto p = plane_point(r, pivot_, kAxes[kPlaneNormal[k]]);
        if (!p) return {};
        Vec3 total(0.0f);
        total[kPlaneU[k]] = grid.snap_value((*p)[kPlaneU[k]] - start_point_[kPlaneU[k]]);
        total[kPlaneV[k]] = grid.snap_value((*p)[kPlaneV[k]] - start_point_[kPlaneV[k]]);
        move_to(total);
    }
    readout_ = text;
    return result ? std::string() : result.error().str();
}

void Gizmo::end(Editor& editor) {
    if (active_ == Handle::None) return;
    editor.commit_transaction();
    active_ = Handle::None;
    readout_.clear();
}

void Gizmo::cancel(Editor& editor) {
    if (active_ == Handle::None) return;
    editor.cancel_transaction();
    active_ = Handle::None;
    readout_.clear();
}

} // namespace ks::editor
