// --status-file: the level viewport's part of the session's snapshot (status_report.cpp): the tool and
// gizmo, the view and its area, what the overlays show, and where the entities, the player start, the
// gizmo's handles and the 4-up view's panes are on screen, so real-input tests can aim their clicks.
#include "model/bounds.h"
#include "ui/level_viewport.h"
#include "view/tool_pointer.h"

#include <nlohmann/json.hpp>

namespace ks::editor::ui {

namespace {
nlohmann::json screen_point(Vec2 p) {
    return nlohmann::json::array({p.x, p.y});
}

// Entity centres on screen (window pixels), for the first 64 entities.
nlohmann::json entities_on_screen(const Editor& editor, const ViewCamera& view, Vec2 origin) {
    nlohmann::json screen = nlohmann::json::object();
    int listed = 0;
    for (const auto& e : editor.level().entities) {
        if (listed++ >= 64) break;
        Vec2 p;
        if (view.project(entity_obb(e).center, p)) screen[std::to_string(e.id)] = screen_point(p + origin);
    }
    return screen;
}

// In an axis view, where the world's origin and unit axes land (window pixels): the projection is affine
// there, so a script can aim at any world point (scripts/brief_actions.sh); absent in perspective.
nlohmann::json axes_on_screen(const ViewCamera& view, Vec2 origin) {
    if (!view_axis(view)) return nullptr;
    nlohmann::json axes = nlohmann::json::object();
    const std::pair<const char*, Vec3> points[] = {
        {"origin", Vec3(0.0f)}, {"x", Vec3(1, 0, 0)}, {"y", Vec3(0, 1, 0)}, {"z", Vec3(0, 0, 1)}};
    for (const auto& [name, world] : points) {
        Vec2 p;
        if (!view.project(world, p)) return nullptr;
        axes[name] = screen_point(p + origin);
    }
    return axes;
}
} // namespace

void LevelViewport::status(nlohmann::json& s, bool level_shown) const {
    place_.status(s);
    s["gizmo"] = gizmo_mode_name(gizmo_.mode);
    s["gizmo_space"] = rotation_space_name(gizmo_.space);
    s["dragging"] = gizmo_.dragging();
    s["texture_drag"] = face_drag_.dragging() ? face_drag_.describe() : std::string();
    lines_.status(s, overlays_);
    s["view"] = view_mode_name(view_.mode);
    geometry_.status(s, ctx_.editor.doc());
    geometry_.status_on_screen(s, ctx_.editor.doc(), view_, origin_);
    s["viewport"] = {origin_.x, origin_.y, size_.x, size_.y};
    s["show_links"] = overlays_.links;
    s["link_arrows"] = logic_overlay_.arrow_count();
    s["screen"] = entities_on_screen(ctx_.editor, view_, origin_);
    s["axes_on_screen"] = axes_on_screen(view_, origin_);
    if (level_shown) {
        Vec2 p;
        if (view_.project(player_obb(ctx_.editor.level().player_start).center, p))
            s["player_start"]["screen"] = screen_point(p + origin_);
        if (!ctx_.editor.doc().selection.empty()) {
            const GizmoShape g = gizmo_shape(view_, gizmo_frame());
            if (g.valid) {
                nlohmann::json handles;
                handles["centre"] = screen_point(g.centre + origin_);
                const char* axes[3] = {"x", "y", "z"};
                for (int i = 0; i < 3; ++i) {
                    if (g.axis_visible[i]) // the middle of the arrow: a safe place to grab it
                        handles[axes[i]] = screen_point((g.centre + g.tips[i]) * 0.5f + origin_);
                    if (g.ring_visible[i] && gizmo_.mode == GizmoMode::Rotate) // where the ring starts
                        handles[std::string("ring_") + axes[i]] = screen_point(g.rings[i][0] + origin_);
                }
                s["gizmo_handles"] = handles;
            }
        }
    }
    panes_status(s);
}

// In the 4-up view: each pane's view, rectangle and the entities' centres in it.
void LevelViewport::panes_status(nlohmann::json& s) const {
    using nlohmann::json;
    s["quad"] = quad_.on;
    s["viewport_area"] = {area_.origin.x, area_.origin.y, area_.size.x, area_.size.y};
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
            for (const auto& e : ctx_.editor.level().entities) {
                if (listed++ >= 64) break;
                Vec2 p;
                if (view.project(entity_obb(e).center, p) && p.x >= 0 && p.y >= 0 && p.x < rect.size.x &&
                    p.y < rect.size.y)
                    screen[std::to_string(e.id)] = {rect.origin.x + p.x, rect.origin.y + p.y};
            }
            panes.push_back({{"view", view_mode_name(view.mode)},
                             {"rect", {rect.origin.x, rect.origin.y, rect.size.x, rect.size.y}},
                             {"screen", screen},
                             {"renders", scene_.pane_renders(i)}});
        }
    s["panes"] = panes;
}

} // namespace ks::editor::ui
