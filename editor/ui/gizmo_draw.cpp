#include "ui/gizmo_draw.h"

#include <imgui.h>

#include <cmath>
#include <utility>

namespace ks::editor::ui {

namespace {
const ImU32 kAxisColours[3] = {IM_COL32(235, 70, 70, 255), IM_COL32(110, 215, 80, 255),
                               IM_COL32(70, 130, 240, 255)};
const ImU32 kPlaneColours[3] = {kAxisColours[2], kAxisColours[1], kAxisColours[0]}; // by normal
const ImU32 kHot = IM_COL32(255, 220, 60, 255);
constexpr Handle kPlanes[3] = {Handle::PlaneXY, Handle::PlaneXZ, Handle::PlaneYZ};
constexpr Handle kAxes[3] = {Handle::AxisX, Handle::AxisY, Handle::AxisZ};
constexpr Handle kRings[3] = {Handle::RingX, Handle::RingY, Handle::RingZ};

// The rings about x, y and z in their axes' colours (the one under the mouse or dragged hot and thick),
// the others first so the hot one lies on top; ticks every 15 degrees help read the snapping (48 segments:
// every other point is 15 degrees).
template <class At>
void draw_rings(ImDrawList* draw, const GizmoShape& s, Handle shown, const At& at) {
    int order[3] = {0, 1, 2};
    for (int& k : order)
        if (kRings[k] == shown) std::swap(k, order[2]);
    for (int k : order) {
        if (!s.ring_visible[k]) continue;
        const bool hot = shown == kRings[k];
        const ImU32 colour = hot ? kHot : kAxisColours[k];
        ImVec2 points[kGizmoRingSegments + 1];
        for (int i = 0; i <= kGizmoRingSegments; ++i) points[i] = at(s.rings[k][i]);
        draw->AddPolyline(points, kGizmoRingSegments + 1, colour, 0, hot ? 4.0f : 2.5f);
        const ImVec2 c = at(s.centre);
        for (int i = 0; i < kGizmoRingSegments; i += 2) {
            const ImVec2 p = points[i];
            draw->AddLine(ImVec2(p.x + (c.x - p.x) * 0.07f, p.y + (c.y - p.y) * 0.07f), p, colour, 1.5f);
        }
    }
    draw->AddCircleFilled(at(s.centre), 3.0f, IM_COL32(240, 240, 240, 255));
}
} // namespace

void draw_gizmo(ImDrawList* draw, const Gizmo& gizmo, const ViewCamera& view, Vec2 origin,
                const GizmoFrame& frame, Handle hovered) {
    const GizmoShape s = gizmo_shape(view, frame);
    if (!s.valid) return;
    const Handle shown = gizmo.dragging() ? gizmo.active() : hovered;
    auto at = [&](Vec2 p) { return ImVec2(p.x + origin.x, p.y + origin.y); };
    if (gizmo.mode == GizmoMode::Rotate) {
        draw_rings(draw, s, shown, at);
        return;
    }
    if (gizmo.mode == GizmoMode::Move) {
        for (int k = 0; k < 3; ++k) {
            if (!s.plane_visible[k]) continue;
            const auto& q = s.planes[k];
            const ImU32 c = shown == kPlanes[k] ? kHot : kPlaneColours[k];
            draw->AddQuadFilled(at(q[0]), at(q[1]), at(q[2]), at(q[3]), (c & 0x00FFFFFF) | 0x70000000);
            draw->AddQuad(at(q[0]), at(q[1]), at(q[2]), at(q[3]), c, 1.5f);
        }
    }
    for (int i = 0; i < 3; ++i) {
        if (!s.axis_visible[i]) continue;
        const ImU32 c = shown == kAxes[i] ? kHot : kAxisColours[i];
        const Vec2 tip = s.tips[i] + origin, centre = s.centre + origin;
        draw->AddLine(at(s.centre), at(s.tips[i]), c, shown == kAxes[i] ? 4.0f : 2.5f);
        if (gizmo.mode == GizmoMode::Scale) {
            draw->AddRectFilled(ImVec2(tip.x - 5, tip.y - 5), ImVec2(tip.x + 5, tip.y + 5), c);
            continue;
        }
        Vec2 dir = tip - centre;
        const float len = glm::length(dir);
        if (len < 1.0f) continue;
        dir /= len;
        const Vec2 side(-dir.y, dir.x), base = tip - dir * 12.0f;
        const Vec2 a = tip + dir * 4.0f, b = base + side * 5.0f, d = base - side * 5.0f;
        draw->AddTriangleFilled(ImVec2(a.x, a.y), ImVec2(b.x, b.y), ImVec2(d.x, d.y), c);
    }
    draw->AddCircleFilled(at(s.centre), 3.5f, IM_COL32(240, 240, 240, 255));
}

} // namespace ks::editor::ui
