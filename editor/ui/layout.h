#pragma once
// The editor's fixed panel layout (ImGui 1.86 has no docking): computed from the window size alone, so the
// render pass (before ImGui's frame) and the panels agree on where the viewport is.
#include <algorithm>

namespace ks::editor::ui {

struct Rect {
    float x = 0, y = 0, w = 0, h = 0;
};

struct Layout {
    Rect left, centre, right, bottom;
};

inline constexpr float kViewportBar = 30.0f; // the viewport's tool bar above the 3D picture

inline Layout compute_layout(float width, float height, float menu_height) {
    Layout l;
    const float left_w = std::clamp(width * 0.19f, 200.0f, 320.0f);
    const float right_w = std::clamp(width * 0.25f, 260.0f, 420.0f);
    const float bottom_h = std::clamp(height * 0.22f, 120.0f, 260.0f);
    const float top = menu_height;
    const float middle_h = std::max(60.0f, height - top - bottom_h);
    l.left = {0, top, left_w, middle_h};
    l.right = {width - right_w, top, right_w, middle_h};
    l.centre = {left_w, top, std::max(60.0f, width - left_w - right_w), middle_h};
    l.bottom = {0, top + middle_h, width, height - top - middle_h};
    return l;
}

} // namespace ks::editor::ui
