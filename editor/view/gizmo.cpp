#include "view/gizmo.h"
#include "model/edit_transforms.h"

#include "level/entity_shapes.h"

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

std::string gizmo_label(const Gizmo& gizmo) {
    if (gizmo.mode != GizmoMode::Rotate) return gizmo_mode_name(gizmo.mode);
    return std::string("Rotate (") + rotation_space_name(gizmo.space) + ")";
}

namespace {
constexpr float kPlaneNear = 0.18f, kPlaneFar = 0.42f; // plane squares span this part of the axis length
constexpr float kMinAxisPixels = 12.0f;                // an axis shorter on screen points at the viewer
constexpr float kMinPlanePixels2 = 60.0f;              // a plane square smaller on screen is edge-on
constexpr float kMinRingFacing = 0.2f; // |cos| of the ring's normal to the view below this: edge-on
// In perspective a ring is an ellipse unless seen almost exactly edge-on, where it cannot be dragged.
constexpr float kMinRingFacingPerspective = 0.05f;
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
constexpr Handle kRingHandles[3] = {Handle::RingX, Handle::RingY, Handle::RingZ};

// Ring k lies in the plane of the frame's next two axes (u, v), so that u x v is its axis and a turn from
// u toward v is a positive turn about it.
Vec3 ring_u(const Mat3& axes, int k) {
    return axes[(k + 1) % 3];
}
Vec3 ring_v(const Mat3& axes, int k) {
    return axes[(k + 2) % 3];
}

} // namespace

float angle_in_plane(const Vec3& offset, const Vec3& u, const Vec3& v) {
    return std::atan2(glm::dot(offset, v), glm::dot(offset, u));
}

float ring_angle(const GizmoFrame& frame, int k, const Vec3& offset) {
    return angle_in_plane(offset, ring_u(frame.axes, k), ring_v(frame.axes, k));
}

int ring_axis(Handle h) {
    return h == Handle::RingX ? 0 : h == Handle::RingY ? 1 : h == Handle::RingZ ? 2 : -1;
}

GizmoFrame gizmo_frame(const Document& doc, RotationSpace space) {
    GizmoFrame frame;
    Vec3 sum(0.0f);
    int n = 0;
    for (int id : doc.selection) {
        if (id == kPlayerStartId) {
            sum += doc.level.player_start.position, ++n;
        } else if (const level::Entity* e = doc.level.find(id)) {
            sum += e->position, ++n;
        }
    }
    if (n > 0) frame.pivot = sum / static_cast<float>(n);
    frame.three_axes = selection_turns_on_three_axes(doc);
    if (space == RotationSpace::Local && !doc.selection.empty()) {
        const int primary = doc.selection.front();
        const level::Entity* e = doc.level.find(primary);
        if (primary == kPlayerStartId)
            frame.axes = glm::mat3_cast(quat_from_ypr(radians(doc.level.player_start.yaw), 0, 0));
        else if (e && level::keeps_pitch_and_roll(e->type()))
            frame.axes = glm::mat3_cast(e->orientation());
        else if (e)
            frame.axes = glm::mat3_cast(quat_from_ypr(radians(e->rotation.x), 0, 0));
    }
    return frame;
}

GizmoShape gizmo_shape(const ViewCamera& view, const GizmoFrame& frame) {
    GizmoShape s;
    const Vec3 pivot = frame.pivot;
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
    const Vec3 towards = view.orthographic() ? view.forward() : glm::normalize(pivot - view.camera.position);
    const float min_facing = view.orthographic() ? kMinRingFacing : kMinRingFacingPerspective;
    for (int k = 0; k < 3; ++k) {
        if (k != 1 && !frame.three_axes) continue;
        const Vec3 axis = frame.axes[k], u = ring_u(frame.axes, k), v = ring_v(frame.axes, k);
        bool ok = std::abs(glm::dot(towards, axis)) >= min_facing;
        for (int i = 0; i <= kGizmoRingSegments; ++i) {
            const float a = static_cast<float>(i) / kGizmoRingSegments * 6.2831853f;
            ok = view.project(pivot + (u * std::cos(a) + v * std::sin(a)) * s.length, s.rings[k][i]) && ok;
        }
        s.ring_visible[k] = ok;
    }
    return s;
}

Handle gizmo_hit(GizmoMode mode, const GizmoShape& s, Vec2 mouse) {
    if (!s.valid) return Handle::None;
    float best = kGizmoPickPixels;
    Handle best_handle = Handle::None;
    if (mode == GizmoMode::Rotate) {
        for (int k = 0; k < 3; ++k) {
            if (!s.ring_visible[k]) continue;
            for (int i = 0; i < kGizmoRingSegments; ++i) {
                const float d = distance_to_segment(mouse, s.rings[k][i], s.rings[k][i + 1]);
                if (d < best) best = d, best_handle = kRingHandles[k];
            }
        }
        return best_handle;
    }
    if (mode == GizmoMode::Move)
        for (int i = 0; i < 3; ++i)
            if (s.plane_visible[i] && inside_quad(mouse, s.planes[i])) return kPlaneHandles[i];
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

void Gizmo::begin(Editor& editor, const ViewCamera& view, const GizmoFrame& frame, Handle handle,
                  Vec2 mouse) {
    active_ = handle;
    pivot_ = frame.pivot;
    length_ = gizmo_shape(view, frame).length;
    applied_move_ = Vec3(0.0f);
    applied_angle_ = 0.0f;
    applied_scale_ = Vec3(1.0f);
    readout_.clear();
    const geometry::Ray r = view.ray(mouse);
    if (const int axis = axis_of(handle); axis >= 0) {
        start_param_ = axis_parameter(r, pivot_, kAxes[axis]).value_or(0.0f);
    } else if (const int k = ring_axis(handle); k >= 0) {
        ring_axis_ = frame.axes[k];
        ring_u_ = ring_u(frame.axes, k);
        ring_v_ = ring_v(frame.axes, k);
        const auto p = plane_point(r, pivot_, ring_axis_);
        start_param_ = p ? angle_in_plane(*p - pivot_, ring_u_, ring_v_) : 0.0f;
    } else {
        start_point_ = plane_point(r, pivot_, kAxes[kPlaneNormal[plane_index(handle)]]).value_or(pivot_);
    }
    editor.begin_transaction(mode == GizmoMode::Move     ? "Move (gizmo)"
                             : mode == GizmoMode::Rotate ? "Rotate (gizmo)"
                                                         : "Scale (gizmo)");
}

std::string Gizmo::drag_ring(Editor& editor, const geometry::Ray& ray, const GridSettings& grid) {
    const auto p = plane_point(ray, pivot_, ring_axis_);
    if (!p) return {};
    const float angle = angle_in_plane(*p - pivot_, ring_u_, ring_v_) - start_param_;
    const float degrees = grid.snap_angle(std::remainder(angle * 57.29578f, 360.0f));
    const float increment = degrees - applied_angle_;
    Result<void> result;
    if (increment != 0.0f) {
        const int k = ring_axis(active_);
        result = rotate_selection_about(editor, k, increment, space, grid.snap);
        if (result) applied_angle_ = degrees;
    }
    char text[96];
    std::snprintf(text, sizeof(text), "rotate %c %+.1f deg (%s)", "xyz"[ring_axis(active_)], applied_angle_,
                  rotation_space_name(space));
    readout_ = text;
    return result ? std::string() : result.error().str();
}

std::string Gizmo::drag(Editor& editor, const ViewCamera& view, Vec2 mouse, bool free) {
    if (active_ == Handle::None) return {};
    GridSettings grid = editor.doc().grid;
    if (free) grid.snap = false;
    const geometry::Ray r = view.ray(mouse);
    if (ring_axis(active_) >= 0) return drag_ring(editor, r, grid);
    char text[96];
    Result<void> result;
    auto move_to = [&](const Vec3& total) {
        const Vec3 increment = total - applied_move_;
        if (increment != Vec3(0.0f)) {
            result = move_selection(editor, increment);
            if (result) applied_move_ = total;
        }
        std::snprintf(text, sizeof(text), "move %+.2f, %+.2f, %+.2f", applied_move_.x, applied_move_.y,
                      applied_move_.z);
    };
    if (const int axis = axis_of(active_); axis >= 0) {
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
                result = scale_selection(editor, increment);
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
