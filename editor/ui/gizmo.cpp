#include "ui/gizmo.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ks::editor::ui {

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
constexpr float kPickPixels = 9.0f;
constexpr float kScreenFraction = 0.16f; // handle length as a fraction of the viewport height
constexpr float kPlaneFraction = 0.3f;   // plane squares sit at this fraction of the axis length
const Vec3 kAxes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
const ImU32 kAxisColours[3] = {IM_COL32(235, 70, 70, 255), IM_COL32(110, 215, 80, 255),
                               IM_COL32(70, 130, 240, 255)};
const ImU32 kHot = IM_COL32(255, 220, 60, 255);

float distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
    const Vec2 ab = b - a;
    const float len2 = glm::dot(ab, ab);
    const float t = len2 > 0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
    return glm::length(p - (a + ab * t));
}

bool inside_quad(Vec2 p, const Vec2 q[4]) {
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

int axis_of(Handle h) {
    return h == Handle::AxisX ? 0 : h == Handle::AxisY ? 1 : h == Handle::AxisZ ? 2 : -1;
}
// Normal of a plane handle, and the two axes it moves along.
Vec3 plane_normal(Handle h) {
    return h == Handle::PlaneXY ? kAxes[2] : h == Handle::PlaneXZ ? kAxes[1] : kAxes[0];
}
void plane_axes(Handle h, int& u, int& v) {
    if (h == Handle::PlaneXY)
        u = 0, v = 1;
    else if (h == Handle::PlaneXZ)
        u = 0, v = 2;
    else
        u = 1, v = 2;
}
ImVec2 im(Vec2 v) {
    return ImVec2(v.x, v.y);
}
} // namespace

float Gizmo::handle_length(const GizmoView& view, const Vec3& pivot) const {
    const auto& cam = view.camera->camera;
    const float distance = std::max(0.5f, glm::dot(pivot - cam.position, cam.forward()));
    return distance * std::tan(cam.fov_y * 0.5f) * 2.0f * kScreenFraction;
}

Handle Gizmo::hit(const GizmoView& view, const Vec3& pivot, Vec2 mouse) const {
    const float length = handle_length(view, pivot);
    Vec2 centre;
    if (!view.camera->project(pivot, view.size.x, view.size.y, centre)) return Handle::None;
    if (mode == GizmoMode::Rotate) {
        Vec2 prev{};
        bool have_prev = false;
        for (int i = 0; i <= 48; ++i) {
            const float a = static_cast<float>(i) / 48.0f * 6.2831853f;
            Vec2 p;
            const bool ok = view.camera->project(pivot + Vec3(std::cos(a), 0, std::sin(a)) * length,
                                                 view.size.x, view.size.y, p);
            if (ok && have_prev && distance_to_segment(mouse, prev, p) < kPickPixels) return Handle::Yaw;
            prev = p;
            have_prev = ok;
        }
        return Handle::None;
    }
    if (mode == GizmoMode::Move) {
        const Handle planes[3] = {Handle::PlaneXY, Handle::PlaneXZ, Handle::PlaneYZ};
        for (Handle h : planes) {
            int u = 0, v = 0;
            plane_axes(h, u, v);
            const float a = length * kPlaneFraction * 0.6f, b = length * kPlaneFraction * 1.4f;
            Vec3 corners[4] = {pivot + kAxes[u] * a + kAxes[v] * a, pivot + kAxes[u] * b + kAxes[v] * a,
                               pivot + kAxes[u] * b + kAxes[v] * b, pivot + kAxes[u] * a + kAxes[v] * b};
            Vec2 q[4];
            bool ok = true;
            for (int i = 0; i < 4; ++i)
                ok = ok && view.camera->project(corners[i], view.size.x, view.size.y, q[i]);
            if (ok && inside_quad(mouse, q)) return h;
        }
    }
    float best = kPickPixels;
    Handle best_handle = Handle::None;
    const Handle axes[3] = {Handle::AxisX, Handle::AxisY, Handle::AxisZ};
    for (int i = 0; i < 3; ++i) {
        Vec2 tip;
        if (!view.camera->project(pivot + kAxes[i] * length, view.size.x, view.size.y, tip)) continue;
        const float d = distance_to_segment(mouse, centre, tip);
        if (d < best) best = d, best_handle = axes[i];
    }
    return best_handle;
}

float Gizmo::axis_parameter(const GizmoView& view, Vec2 mouse, const Vec3& axis) const {
    const Ray r = view.camera->ray(mouse.x, mouse.y, view.size.x, view.size.y);
    const Vec3 w0 = pivot_ - r.origin;
    const float b = glm::dot(axis, r.direction);
    const float denom = 1.0f - b * b;
    if (denom < 1e-5f) return start_param_; // looking down the axis: no motion along it
    return (b * glm::dot(r.direction, w0) - glm::dot(axis, w0)) / denom;
}

bool Gizmo::plane_point(const GizmoView& view, Vec2 mouse, const Vec3& normal, Vec3& out) const {
    const Ray r = view.camera->ray(mouse.x, mouse.y, view.size.x, view.size.y);
    const float denom = glm::dot(normal, r.direction);
    if (std::abs(denom) < 1e-5f) return false; // edge-on plane
    const float t = glm::dot(pivot_ - r.origin, normal) / denom;
    if (t < 0.0f) return false;
    out = r.origin + r.direction * t;
    return true;
}

void Gizmo::begin(Editor& editor, const GizmoView& view, const Vec3& pivot, Handle handle, Vec2 mouse) {
    active_ = handle;
    pivot_ = pivot;
    applied_move_ = Vec3(0.0f);
    applied_angle_ = 0.0f;
    applied_scale_ = Vec3(1.0f);
    const int axis = axis_of(handle);
    if (axis >= 0)
        start_param_ = axis_parameter(view, mouse, kAxes[axis]);
    else if (handle == Handle::Yaw) {
        Vec3 p;
        start_param_ =
            plane_point(view, mouse, kAxes[1], p) ? std::atan2(p.z - pivot.z, p.x - pivot.x) : 0.0f;
    } else if (!plane_point(view, mouse, plane_normal(handle), start_point_))
        start_point_ = pivot;
    editor.begin_transaction(mode == GizmoMode::Move     ? "Move (gizmo)"
                             : mode == GizmoMode::Rotate ? "Rotate (gizmo)"
                                                         : "Scale (gizmo)");
}

std::string Gizmo::drag(Editor& editor, const GizmoView& view, Vec2 mouse) {
    if (active_ == Handle::None) return {};
    const GridSettings& grid = editor.doc().grid;
    char text[96];
    Result<void> result;
    if (active_ == Handle::Yaw) {
        Vec3 p;
        if (!plane_point(view, mouse, kAxes[1], p)) return {};
        // Screen-space angle is measured with +z toward the viewer; the level's yaw turns the other way.
        const float angle = -(std::atan2(p.z - pivot_.z, p.x - pivot_.x) - start_param_);
        float degrees = std::remainder(angle * 57.29578f, 360.0f);
        degrees = grid.snap_angle(degrees);
        const float increment = degrees - applied_angle_;
        if (increment != 0.0f) {
            result = editor.rotate_selection(increment);
            if (result) applied_angle_ = degrees;
        }
        std::snprintf(text, sizeof(text), "yaw %+.1f deg", applied_angle_);
        readout_ = text;
    } else if (const int axis = axis_of(active_); axis >= 0) {
        const float t = axis_parameter(view, mouse, kAxes[axis]) - start_param_;
        if (mode == GizmoMode::Scale) {
            const float length = handle_length(view, pivot_);
            float factor = std::max(0.05f, 1.0f + t / length);
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
            const Vec3 increment = total - applied_move_;
            if (increment != Vec3(0.0f)) {
                result = editor.move_selection(increment);
                if (result) applied_move_ = total;
            }
            std::snprintf(text, sizeof(text), "move %+.2f, %+.2f, %+.2f", applied_move_.x, applied_move_.y,
                          applied_move_.z);
        }
        readout_ = text;
    } else {
        Vec3 p;
        if (!plane_point(view, mouse, plane_normal(active_), p)) return {};
        int u = 0, v = 0;
        plane_axes(active_, u, v);
        Vec3 total(0.0f);
        total[u] = grid.snap_value(p[u] - start_point_[u]);
        total[v] = grid.snap_value(p[v] - start_point_[v]);
        const Vec3 increment = total - applied_move_;
        if (increment != Vec3(0.0f)) {
            result = editor.move_selection(increment);
            if (result) applied_move_ = total;
        }
        std::snprintf(text, sizeof(text), "move %+.2f, %+.2f, %+.2f", applied_move_.x, applied_move_.y,
                      applied_move_.z);
        readout_ = text;
    }
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

void Gizmo::draw(ImDrawList* draw, const GizmoView& view, const Vec3& pivot, Handle hovered) const {
    const Handle shown = active_ != Handle::None ? active_ : hovered;
    const float length = handle_length(view, pivot);
    auto to_screen = [&](const Vec3& w, Vec2& out) {
        if (!view.camera->project(w, view.size.x, view.size.y, out)) return false;
        out += view.origin;
        return true;
    };
    Vec2 centre;
    if (!to_screen(pivot, centre)) return;
    if (mode == GizmoMode::Rotate) {
        const ImU32 colour = shown == Handle::Yaw ? kHot : kAxisColours[1];
        ImVec2 points[65];
        int n = 0;
        for (int i = 0; i <= 64; ++i) {
            const float a = static_cast<float>(i) / 64.0f * 6.2831853f;
            Vec2 p;
            if (to_screen(pivot + Vec3(std::cos(a), 0, std::sin(a)) * length, p)) points[n++] = im(p);
        }
        draw->AddPolyline(points, n, colour, 0, shown == Handle::Yaw ? 4.0f : 2.5f);
        // Tick marks every rotation step of 15 degrees help read the snapping.
        for (int i = 0; i < 24; ++i) {
            const float a = static_cast<float>(i) / 24.0f * 6.2831853f;
            Vec2 p0, p1;
            if (to_screen(pivot + Vec3(std::cos(a), 0, std::sin(a)) * length * 0.93f, p0) &&
                to_screen(pivot + Vec3(std::cos(a), 0, std::sin(a)) * length, p1))
                draw->AddLine(im(p0), im(p1), colour, 1.5f);
        }
        draw->AddCircleFilled(im(centre), 3.0f, colour);
        return;
    }
    if (mode == GizmoMode::Move) {
        const Handle planes[3] = {Handle::PlaneXY, Handle::PlaneXZ, Handle::PlaneYZ};
        const ImU32 plane_colours[3] = {kAxisColours[2], kAxisColours[1], kAxisColours[0]};
        for (int k = 0; k < 3; ++k) {
            int u = 0, v = 0;
            plane_axes(planes[k], u, v);
            const float a = length * kPlaneFraction * 0.6f, b = length * kPlaneFraction * 1.4f;
            Vec3 corners[4] = {pivot + kAxes[u] * a + kAxes[v] * a, pivot + kAxes[u] * b + kAxes[v] * a,
                               pivot + kAxes[u] * b + kAxes[v] * b, pivot + kAxes[u] * a + kAxes[v] * b};
            ImVec2 q[4];
            bool ok = true;
            for (int i = 0; i < 4; ++i) {
                Vec2 p;
                ok = ok && to_screen(corners[i], p);
                q[i] = im(p);
            }
            if (!ok) continue;
            const ImU32 c = shown == planes[k] ? kHot : plane_colours[k];
            draw->AddQuadFilled(q[0], q[1], q[2], q[3], (c & 0x00FFFFFF) | 0x70000000);
            draw->AddQuad(q[0], q[1], q[2], q[3], c, 1.5f);
        }
    }
    const Handle axes[3] = {Handle::AxisX, Handle::AxisY, Handle::AxisZ};
    for (int i = 0; i < 3; ++i) {
        Vec2 tip;
        if (!to_screen(pivot + kAxes[i] * length, tip)) continue;
        const ImU32 c = shown == axes[i] ? kHot : kAxisColours[i];
        draw->AddLine(im(centre), im(tip), c, shown == axes[i] ? 4.0f : 2.5f);
        if (mode == GizmoMode::Scale) {
            draw->AddRectFilled(ImVec2(tip.x - 5, tip.y - 5), ImVec2(tip.x + 5, tip.y + 5), c);
        } else {
            Vec2 dir = tip - centre;
            const float len = glm::length(dir);
            if (len < 1.0f) continue;
            dir /= len;
            const Vec2 side(-dir.y, dir.x);
            const Vec2 base = tip - dir * 12.0f;
            draw->AddTriangleFilled(im(tip + dir * 4.0f), im(base + side * 5.0f), im(base - side * 5.0f), c);
        }
    }
    draw->AddCircleFilled(im(centre), 3.5f, IM_COL32(240, 240, 240, 255));
}

} // namespace ks::editor::ui
