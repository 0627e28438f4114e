// Where a geometry tool's click lands: tool_pointer.h.
#include "view/tool_pointer.h"

#include "model/brush_frame.h"

#include "brush/brush_query.h"
#include "level/entity_shapes.h"

#include <cmath>

namespace ks::editor {
namespace {

// The axis a unit normal lies along (within 1e-9), or -1.
int pointer_normal_axis(const DVec3& n) {
    for (int axis = 0; axis < 3; ++axis)
        if (std::abs(std::abs(n[axis]) - 1.0) <= 1e-9) return axis;
    return -1;
}

struct PointerBrushHit {
    const level::Entity* entity = nullptr;
    double distance = 1e300;
};

const brush::Brush& local_brush(const level::Entity& e) {
    return e.as<level::BrushProps>().brush;
}

// The nearest shown brush the ray enters (boxes first, so only brushes under the mouse are clipped).
PointerBrushHit pointer_nearest_brush(const Document& doc, const geometry::Ray& ray, const ShownFn& shown) {
    PointerBrushHit best;
    for (const level::Entity& e : doc.level.entities) {
        if (e.type() != level::EntityType::Brush || !shown(e)) continue;
        const float box_t = geometry::ray_obb(ray, entity_obb(e));
        if (box_t < 0.0f || box_t > best.distance) continue;
        const BrushFrame frame(e);
        const DVec3 direction = glm::transpose(frame.rotation) * DVec3(ray.direction);
        const auto t = brush::ray_entry(local_brush(e), frame.to_local(DVec3(ray.origin)), direction);
        if (t && *t < best.distance) best = {&e, *t};
    }
    return best;
}

// The face of `world` that `p` lies on (the nearest plane).
brush::Plane pointer_face_at(const brush::Brush& world, const DVec3& p) {
    const brush::Plane* best = &world.faces().front().plane;
    for (const brush::Face& f : world.faces())
        if (std::abs(f.plane.signed_distance(p)) < std::abs(best->signed_distance(p))) best = &f.plane;
    return *best;
}

} // namespace

const char* point_kind_name(PointKind kind) {
    return kind == PointKind::vertex ? "vertex" : kind == PointKind::face ? "face" : "grid";
}

std::optional<int> view_axis(const ViewCamera& view) {
    switch (view.mode) {
    case ViewMode::Top:
        return 1;
    case ViewMode::Front:
        return 2;
    case ViewMode::Side:
        return 0;
    case ViewMode::Perspective:
        return std::nullopt;
    }
    return std::nullopt;
}

std::optional<ToolPoint> tool_point(const Document& doc, const ViewCamera& view, Vec2 mouse,
                                    const ShownFn& shown, const PointerOptions& options) {
    const geometry::Ray ray = view.ray(mouse);
    const auto snap = [&](double v) {
        return static_cast<double>(doc.grid.snap_value(static_cast<float>(v)));
    };
    if (options.vertices || options.faces) {
        PointerBrushHit hit = pointer_nearest_brush(doc, ray, shown);
        if (options.vertices) { // the hit brush's and the selected brushes' vertices near the mouse
            std::optional<ToolPoint> best;
            float best_pixels = options.vertex_pixels, best_depth = 0.0f;
            const Vec3 eye = view.camera.position, forward = view.forward();
            auto consider = [&](const level::Entity& e) {
                const BrushFrame frame(e);
                for (const DVec3& local : local_brush(e).vertices()) {
                    const DVec3 v = frame.to_world(local);
                    Vec2 s;
                    if (!view.project(Vec3(v), s)) continue;
                    // Vertices on one pixel (a box's top and bottom seen from above): the nearer one.
                    const float d = glm::length(s - mouse), depth = glm::dot(Vec3(v) - eye, forward);
                    const bool tie = best && std::abs(d - best_pixels) < 0.01f;
                    if ((tie && depth < best_depth) || (!tie && d < best_pixels)) {
                        best_pixels = d, best_depth = depth;
                        best = ToolPoint{v, PointKind::vertex, std::nullopt, e.id};
                    }
                }
            };
            if (hit.entity) consider(*hit.entity);
            for (int id : doc.selection) {
                const level::Entity* e = doc.level.find(id);
                if (e && e->type() == level::EntityType::Brush && e != hit.entity) consider(*e);
            }
            if (best) return best;
        }
        if (options.faces && hit.entity) {
            DVec3 p = DVec3(ray.origin) + DVec3(ray.direction) * hit.distance;
            const BrushFrame frame(*hit.entity);
            const brush::Plane local = pointer_face_at(local_brush(*hit.entity), frame.to_local(p));
            const DVec3 normal = frame.rotation * local.normal;
            const brush::Plane face{normal, glm::dot(normal, frame.to_world(local.normal * local.distance))};
            const int axis = pointer_normal_axis(face.normal);
            if (axis >= 0) { // on the face's plane exactly, the two other coordinates on the grid
                for (int other = 0; other < 3; ++other)
                    p[other] = other == axis ? face.distance * face.normal[axis] : snap(p[other]);
            }
            return ToolPoint{p, PointKind::face, face, hit.entity->id};
        }
    }
    DVec3 p;
    if (const auto axis = view_axis(view)) {
        p = DVec3(ray.origin);
        p[*axis] = 0.0;
    } else {
        if (std::abs(ray.direction.y) < 1e-6f || -ray.origin.y / ray.direction.y <= 0.0f) return std::nullopt;
        p = DVec3(ray.origin) + DVec3(ray.direction) * (-double(ray.origin.y) / ray.direction.y);
        p.y = 0.0;
    }
    for (int axis = 0; axis < 3; ++axis) p[axis] = snap(p[axis]);
    return ToolPoint{p, PointKind::grid, std::nullopt, 0};
}

std::optional<DVec3> point_on_plane(const Document& doc, const ViewCamera& view, Vec2 mouse,
                                    const DrawPlane& plane) {
    const geometry::Ray ray = view.ray(mouse);
    DVec3 p(ray.origin);
    if (!view_axis(view)) {
        const double along = ray.direction[plane.axis];
        const double t = (plane.level - p[plane.axis]) / along;
        if (std::abs(along) < 1e-6 || !(t > 0.0)) return std::nullopt;
        p += DVec3(ray.direction) * t;
    }
    for (int axis = 0; axis < 3; ++axis)
        p[axis] = axis == plane.axis ? plane.level
                                     : static_cast<double>(doc.grid.snap_value(static_cast<float>(p[axis])));
    return p;
}

DrawPlane draw_plane_at(const ToolPoint& at, const ViewCamera& view) {
    if (const auto axis = view_axis(view)) return {*axis, at.point[*axis], std::nullopt};
    if (at.face) {
        const int axis = pointer_normal_axis(at.face->normal);
        if (axis >= 0) return {axis, at.point[axis], at.face->normal[axis] > 0 ? 1 : -1};
    }
    return {1, at.point.y, 1};
}

} // namespace ks::editor
