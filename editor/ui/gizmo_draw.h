#pragma once
// Draws the gizmo's handles (view/gizmo.h) over the viewport with ImGui.
#include "view/gizmo.h"

struct ImDrawList;

namespace ks::editor::ui {

// `origin`: the viewport's top-left in screen pixels.
void draw_gizmo(ImDrawList* draw, const Gizmo& gizmo, const ViewCamera& view, Vec2 origin,
                const GizmoFrame& frame, Handle hovered);

} // namespace ks::editor::ui
