// The level's views: the render pass of the single view or of the 4-up view's four panes (each its own
// camera and target, the level emitted once), and the 4-up view's panes in the ImGui pass. view_ is the
// camera being drawn: each pane's camera is swapped into it while that pane is rendered, laid out and given
// the mouse, so every overlay, pick and gizmo drag works unchanged in every pane; between frames it holds
// the active pane's camera, where the menus, keys and the status file find it.
#include "ui/editor_app.h"
#include "ui/layout.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <type_traits>

namespace ks::editor::ui {

namespace {
constexpr float kPaneGap = 2.0f;

// FNV-1a over the bytes of plain values (no padding in any of them).
struct Fnv {
    std::uint64_t h = 1469598103934665603ull;
    template <class T>
    void add(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        unsigned char bytes[sizeof(T)];
        std::memcpy(bytes, &value, sizeof(T));
        for (unsigned char b : bytes) h = (h ^ b) * 1099511628211ull;
    }
};

// Everything a view's picture is made of: a view whose key has not changed keeps the picture it has, so an
// idle editor draws nothing, and the 4-up view (the level four times) redraws only the panes that change:
// one of four while it is navigated. `scene_builds` stands for the level scene's meshes, light map and
// environment.
std::uint64_t picture_key(const render::SceneFrame& frame, unsigned long long scene_builds) {
    Fnv key;
    key.add(scene_builds);
    key.add(frame.camera);
    key.add(frame.width);
    key.add(frame.height);
    for (const render::MeshInstance& m : *frame.instances) {
        key.add(m.mesh);
        key.add(m.material);
        key.add(m.world);
        key.add(m.emissive_scale);
        key.add(m.tint);
        key.add(m.lightmap);
        key.add(static_cast<unsigned char>(m.casts_shadow));
    }
    for (const render::Light& l : *frame.lights) {
        key.add(l.type);
        key.add(l.position);
        key.add(l.direction);
        key.add(l.color);
        key.add(l.intensity);
        key.add(l.range);
        key.add(l.cos_outer);
        key.add(l.cos_inner);
    }
    for (const render::DebugVertex& v : frame.debug->vertices()) {
        key.add(v.position);
        key.add(v.color);
    }
    return key.h;
}
} // namespace

void EditorApp::sync_active_pane() {
    if (quad_.on) quad_.cameras[static_cast<size_t>(quad_.active)] = view_;
}

bool EditorApp::render_view(int width, int height, std::uint64_t* last_key) {
    debug_.clear();
    draw_overlays();
    render::SceneFrame frame;
    frame.camera = view_.camera;
    frame.camera.aspect = static_cast<float>(width) / static_cast<float>(std::max(1, height));
    frame.environment = scene_->environment();
    frame.instances = &instances_;
    frame.lights = &lights_;
    frame.debug = &debug_;
    frame.width = width;
    frame.height = height;
    if (last_key) {
        const std::uint64_t key = picture_key(frame, scene_stats_.builds);
        if (key == *last_key) return false;
        *last_key = key;
    }
    renderer_->render(frame);
    return true;
}

void EditorApp::render_level_views(int width, int height) {
    scene_->emit(instances_, lights_);
    if (!quad_.on) {
        viewport_target_.ensure(width, height);
        view_.set_viewport(Vec2(static_cast<float>(width), static_cast<float>(std::max(1, height))));
        viewport_target_.bind();
        render_view(width, height, &single_key_);
        return;
    }
    sync_active_pane();
    const auto panes =
        quad_panes(Vec2(0.0f), Vec2(static_cast<float>(width), static_cast<float>(height)), kPaneGap);
    for (size_t i = 0; i < panes.size(); ++i) {
        const int w = static_cast<int>(panes[i].size.x), h = static_cast<int>(panes[i].size.y);
        pane_targets_[i].ensure(w, h);
        view_ = quad_.cameras[i];
        view_.set_viewport(panes[i].size);
        pane_targets_[i].bind();
        if (render_view(w, h, &pane_keys_[i])) ++pane_renders_[i];
        quad_.cameras[i] = view_;
    }
    view_ = quad_.cameras[static_cast<size_t>(quad_.active)];
}

void EditorApp::quad_viewport(Vec2 origin, Vec2 size) {
    sync_active_pane();
    pane_rects_ = quad_panes(origin, size, kPaneGap);
    const ImGuiIO& io = ImGui::GetIO();
    // The pane under the mouse becomes the active one, unless a drag, a fly or a box select started in
    // another is still going on (it keeps the pane it started in until the button is released).
    bool busy = gizmo_.dragging() || patrol_drag_.dragging() || box_selecting_ || flying_;
    for (int button = 0; button < 3; ++button)
        if (io.MouseDown[button] && !ImGui::IsMouseClicked(button)) busy = true;
    const int under =
        ImGui::IsWindowHovered() ? pane_at(pane_rects_, Vec2(io.MousePos.x, io.MousePos.y)) : -1;
    if (!busy && under >= 0) quad_.active = under;

    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(ImVec2(origin.x, origin.y), ImVec2(origin.x + size.x, origin.y + size.y),
                        IM_COL32(30, 33, 40, 255));
    for (size_t i = 0; i < pane_rects_.size(); ++i) {
        const PaneRect& pane = pane_rects_[i];
        const bool active = static_cast<int>(i) == quad_.active;
        view_ = quad_.cameras[i];
        view_.set_viewport(pane.size);
        ImGui::SetCursorScreenPos(ImVec2(pane.origin.x, pane.origin.y));
        ImGui::PushID(static_cast<int>(i));
        ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(pane_targets_[i].texture())),
                     ImVec2(pane.size.x, pane.size.y), ImVec2(0, 1), ImVec2(1, 0));
        ImGui::PopID();
        const bool hovered = ImGui::IsItemHovered() && !shell_.screenshot_mode();
        if (active) {
            viewport_origin_ = pane.origin;
            viewport_size_ = pane.size;
            viewport_hovered_ = hovered;
            viewport_input(pane.origin, hovered);
        }
        pane_overlays(draw, pane.origin, active);
        const char* name = view_mode_name(view_.mode);
        const ImVec2 label(pane.origin.x + 8, pane.origin.y + 6), extent = ImGui::CalcTextSize(name);
        draw->AddRectFilled(ImVec2(label.x - 4, label.y - 2),
                            ImVec2(label.x + extent.x + 4, label.y + extent.y + 2), IM_COL32(15, 17, 22, 190),
                            3.0f);
        draw->AddText(label, active ? IM_COL32(255, 200, 90, 255) : IM_COL32(210, 215, 225, 255), name);
        open_group_hint(draw, pane.origin, pane.size, true);
        if (active) // the pane the keys and the mouse work in
            draw->AddRect(ImVec2(pane.origin.x, pane.origin.y),
                          ImVec2(pane.origin.x + pane.size.x, pane.origin.y + pane.size.y),
                          IM_COL32(255, 190, 70, 200), 0.0f, 0, 2.0f);
        quad_.cameras[i] = view_;
    }
    const PaneRect& active = pane_rects_[static_cast<size_t>(quad_.active)];
    view_ = quad_.cameras[static_cast<size_t>(quad_.active)];
    viewport_origin_ = active.origin;
    viewport_size_ = active.size;
}

void EditorApp::toggle_quad() {
    if (quad_.on) {
        sync_active_pane();
        view_ = quad_.leave();
        log_line("single view: " + std::string(view_mode_name(view_.mode)));
        return;
    }
    Vec3 lo, hi;
    level_box(lo, hi);
    // The panes' size now (before the first frame too): from the window, as the layout computes it.
    int width = 0, height = 0;
    glfwGetFramebufferSize(shell_.window(), &width, &height);
    const Layout layout =
        compute_layout(static_cast<float>(width), static_cast<float>(height), ImGui::GetFrameHeight());
    const Vec2 area(std::floor(layout.centre.w), std::max(1.0f, std::floor(layout.centre.h - kViewportBar)));
    quad_.enter(view_, lo, hi, quad_panes(Vec2(0.0f), area, kPaneGap)[0].size);
    view_ = quad_.cameras[static_cast<size_t>(quad_.active)];
    log_line("4-up view: top, front, side and perspective (Numpad 0 toggles)");
}

// --status-file, in the 4-up view: each pane's view, rectangle and the entities' centres in it.
void EditorApp::panes_status(nlohmann::json& s) const {
    using nlohmann::json;
    s["quad"] = quad_.on;
    s["viewport_area"] = {viewport_area_.origin.x, viewport_area_.origin.y, viewport_area_.size.x,
                          viewport_area_.size.y};
    s["active_pane"] = quad_.on ? quad_.active : -1;
    json panes = json::array();
    if (quad_.on)
        for (size_t i = 0; i < pane_rects_.size(); ++i) {
            const PaneRect& rect = pane_rects_[i];
            ViewCamera view = quad_.cameras[i];
            if (static_cast<int>(i) == quad_.active) view = view_; // changed since the panes were drawn
            view.set_viewport(rect.size);
            json screen = json::object();
            int listed = 0;
            for (const auto& e : editor_.level().entities) {
                if (listed++ >= 64) break;
                Vec2 p;
                if (view.project(entity_obb(e).center, p) && p.x >= 0 && p.y >= 0 && p.x < rect.size.x &&
                    p.y < rect.size.y)
                    screen[std::to_string(e.id)] = {rect.origin.x + p.x, rect.origin.y + p.y};
            }
            panes.push_back({{"view", view_mode_name(view.mode)},
                             {"rect", {rect.origin.x, rect.origin.y, rect.size.x, rect.size.y}},
                             {"screen", screen},
                             {"renders", pane_renders_[i]}});
        }
    s["panes"] = panes;
}

} // namespace ks::editor::ui
