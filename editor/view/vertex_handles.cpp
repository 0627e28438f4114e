// The vertex tool's handles in a view: vertex_handles.h.
#include "view/vertex_handles.h"

#include "view/tool_pointer.h"

#include <algorithm>
#include <cmath>

namespace ks::editor {

std::optional<VertexHandle> handle_under(const std::vector<VertexHandle>& handles, const ViewCamera& view,
                                         Vec2 mouse, float pixels) {
    const VertexHandle* best = nullptr;
    float best_pixels = pixels, best_depth = 0.0f;
    const Vec3 eye = view.camera.position, forward = view.forward();
    for (const VertexHandle& h : handles) {
        Vec2 s;
        if (!view.project(Vec3(h.at), s)) continue;
        const float d = glm::length(s - mouse), depth = glm::dot(Vec3(h.at) - eye, forward);
        // Handles on one pixel (a box's top and bottom seen from above): the nearer one, a vertex first.
        const bool tie = best && std::abs(d - best_pixels) < 0.01f;
        const bool better_tie = tie && (best->split != h.split ? !h.split : depth < best_depth);
        if (better_tie || (!tie && d < best_pixels)) best = &h, best_pixels = d, best_depth = depth;
    }
    if (!best) return std::nullopt;
    return *best;
}

std::vector<DVec3> handles_in_rect(const std::vector<VertexHandle>& handles, const ViewCamera& view, Vec2 a,
                                   Vec2 b) {
    const Vec2 lo = glm::min(a, b), hi = glm::max(a, b);
    std::vector<DVec3> out;
    for (const VertexHandle& h : handles) {
        Vec2 s;
        if (!h.split && view.project(Vec3(h.at), s) && s.x >= lo.x && s.x <= hi.x && s.y >= lo.y &&
            s.y <= hi.y)
            out.push_back(h.at);
    }
    return out;
}

VertexDrag start_vertex_drag(const Document& doc, const ViewCamera& view, Vec2 mouse, const DVec3& grabbed,
                             bool on_grid) {
    VertexDrag drag;
    const int axis = view_axis(view).value_or(1);
    drag.plane = {axis, grabbed[axis], std::nullopt};
    drag.from = grabbed;
    if (!on_grid)
        if (const auto pressed = point_on_plane(doc, view, mouse, drag.plane)) drag.from = *pressed;
    return drag;
}

std::optional<DVec3> vertex_drag_delta(const Document& doc, const ViewCamera& view, Vec2 mouse,
                                       const VertexDrag& drag) {
    const auto p = point_on_plane(doc, view, mouse, drag.plane);
    if (!p) return std::nullopt;
    DVec3 delta = *p - drag.from;
    delta[drag.plane.axis] = 0.0;
    return delta;
}

} // namespace ks::editor
