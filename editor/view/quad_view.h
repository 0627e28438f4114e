#pragma once
// The 4-up viewport, window-free: top, front, side and perspective panes at once, each with a camera of its
// own (pan and zoom one axis view without moving the others). The panes split the viewport 2 x 2 and all
// have the same size, so the renderer's targets (and its MSAA buffer) are reused from pane to pane; they
// are recomputed from the viewport's size every frame, so the layout follows the window as it is resized.
// The active pane is the one the mouse works in: picking, box select, the gizmo and the camera keys.
#include "view/view_camera.h"

#include <array>

namespace ks::editor {

inline constexpr int kQuadPanes = 4;
// Top-left, top-right, bottom-left, bottom-right (as 3ds Max lays them out).
inline constexpr std::array<ViewMode, kQuadPanes> kQuadModes = {ViewMode::Top, ViewMode::Front,
                                                                ViewMode::Side, ViewMode::Perspective};

struct PaneRect {
    Vec2 origin{0.0f}, size{0.0f};
    bool contains(Vec2 point) const {
        return point.x >= origin.x && point.y >= origin.y && point.x < origin.x + size.x &&
               point.y < origin.y + size.y;
    }
};

// The four panes of the area at `origin` of `size` pixels, `gap` pixels apart, whole pixels, in
// kQuadModes order. Each is at least one pixel wide and high, however small the area.
std::array<PaneRect, kQuadPanes> quad_panes(Vec2 origin, Vec2 size, float gap);
// The pane under `point`, or -1 (outside, or in a gap between panes).
int pane_at(const std::array<PaneRect, kQuadPanes>& panes, Vec2 point);

class QuadView {
  public:
    bool on = false;
    int active = 3; // the perspective pane
    std::array<ViewCamera, kQuadPanes> cameras;

    // Turns the 4-up view on from the single view `single`: the pane of its mode takes its camera (and
    // becomes active); the other panes keep where they were the last time, or, the first time, frame the
    // box lo..hi in panes of `pane_size` pixels.
    void enter(const ViewCamera& single, const Vec3& lo, const Vec3& hi, Vec2 pane_size);
    // The single view to go back to: the active pane's camera.
    const ViewCamera& leave();

  private:
    bool framed_ = false;
};

// How an editor frames a box in `mode` (the single view's set_view): centred, sized to the larger of its
// width, depth and 1.5 times its height.
void frame_box(ViewCamera& view, ViewMode mode, const Vec3& lo, const Vec3& hi);
// The box filling a picture of `viewport` pixels in `mode`: an axis view sized to the box's two sides it
// shows (top: x and z, front: x and y, side: z and y) at the picture's aspect, perspective as frame_box.
void fit_box(ViewCamera& view, ViewMode mode, const Vec3& lo, const Vec3& hi, Vec2 viewport);

} // namespace ks::editor
