#include "view/quad_view.h"

#include <algorithm>
#include <cmath>

namespace ks::editor {

std::array<PaneRect, kQuadPanes> quad_panes(Vec2 origin, Vec2 size, float gap) {
    const float g = std::max(0.0f, std::round(gap));
    const float w = std::max(1.0f, std::floor((size.x - g) * 0.5f));
    const float h = std::max(1.0f, std::floor((size.y - g) * 0.5f));
    const Vec2 o = glm::round(origin);
    return {PaneRect{o, Vec2(w, h)}, PaneRect{o + Vec2(w + g, 0.0f), Vec2(w, h)},
            PaneRect{o + Vec2(0.0f, h + g), Vec2(w, h)}, PaneRect{o + Vec2(w + g, h + g), Vec2(w, h)}};
}

int pane_at(const std::array<PaneRect, kQuadPanes>& panes, Vec2 point) {
    for (int i = 0; i < kQuadPanes; ++i)
        if (panes[static_cast<std::size_t>(i)].contains(point)) return i;
    return -1;
}

void frame_box(ViewCamera& view, ViewMode mode, const Vec3& lo, const Vec3& hi) {
    const Vec3 size = hi - lo;
    view.set_view(mode, (lo + hi) * 0.5f, std::max({size.x, size.z, size.y * 1.5f}));
}

void fit_box(ViewCamera& view, ViewMode mode, const Vec3& lo, const Vec3& hi, Vec2 viewport) {
    view.set_viewport(viewport);
    if (mode == ViewMode::Perspective) {
        frame_box(view, mode, lo, hi);
        return;
    }
    const Vec3 size = glm::max(hi - lo, Vec3(0.0f));
    const float width = mode == ViewMode::Side ? size.z : size.x;
    const float height = mode == ViewMode::Top ? size.z : size.y;
    const float aspect = view.viewport().x / view.viewport().y;
    view.set_view(mode, (lo + hi) * 0.5f, std::max(height, width / aspect));
}

void QuadView::enter(const ViewCamera& single, const Vec3& lo, const Vec3& hi, Vec2 pane_size) {
    on = true;
    const auto mode = std::find(kQuadModes.begin(), kQuadModes.end(), single.mode);
    active = static_cast<int>(mode - kQuadModes.begin());
    if (!framed_)
        for (int i = 0; i < kQuadPanes; ++i)
            fit_box(cameras[static_cast<std::size_t>(i)], kQuadModes[static_cast<std::size_t>(i)], lo, hi,
                    pane_size);
    framed_ = true;
    ViewCamera& pane = cameras[static_cast<std::size_t>(active)];
    const Vec2 viewport = pane.viewport();
    pane = single;
    pane.set_viewport(viewport);
}

const ViewCamera& QuadView::leave() {
    on = false;
    return cameras[static_cast<std::size_t>(active)];
}

} // namespace ks::editor
