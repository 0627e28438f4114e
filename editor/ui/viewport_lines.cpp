// The level viewport's lines in each view's picture (viewport_lines.h). The player start is a viewport
// object drawn here as its figure (view/player_start_marker.h); its row at the top of the outliner is in
// outliner_tree.cpp, its inspector section in inspector_sections.cpp. It is selected, moved and turned like
// an entity (kPlayerStartId in the selection); every change is an Editor edit.
#include "ui/viewport_lines.h"
#include "level/entity_shapes.h"
#include "model/bounds.h"
#include "model/groups.h"
#include "ui/viewport_tool.h"
#include "view/player_start_marker.h"

#include <imgui.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

namespace ks::editor::ui {

namespace {
const Vec4 kGridMinor(0.55f, 0.6f, 0.7f, 0.22f);
const Vec4 kGridMajor(0.65f, 0.72f, 0.85f, 0.5f);
const Vec4 kSelected(1.0f, 0.62f, 0.1f, 1.0f);
const Vec4 kCollision(0.3f, 0.9f, 1.0f, 0.55f);
// Outlines of the structure in the axis views, where a 16-unit wall seen edge-on is a few grey pixels.
const Vec4 kWallOutline(0.85f, 0.9f, 1.0f, 0.9f);
const Vec4 kDoorOutline(1.0f, 0.55f, 0.25f, 0.95f);
const Vec4 kStairOutline(0.45f, 1.0f, 0.55f, 0.9f);
const Vec4 kSoundMarker(1.0f, 0.45f, 0.85f, 1.0f);
const Vec4 kStartColour(0.3f, 1.0f, 0.4f, 1.0f);

// The outline colour of an entity in the axis views, or none (floors, lights and props need none).
std::optional<Vec4> outline_colour(const level::Entity& e) {
    switch (e.type()) {
    case level::EntityType::Wall:
        return kWallOutline;
    case level::EntityType::Door:
        return kDoorOutline;
    case level::EntityType::Stair:
        return kStairOutline;
    default:
        return std::nullopt;
    }
}

void circle(render::DebugDraw& draw, const Vec3& centre, float radius, const Vec4& colour,
            int segments = 48) {
    Vec3 prev = centre + Vec3(radius, 0, 0);
    for (int i = 1; i <= segments; ++i) {
        const float a = static_cast<float>(i) / static_cast<float>(segments) * 6.2831853f;
        const Vec3 p = centre + Vec3(std::cos(a) * radius, 0, std::sin(a) * radius);
        draw.line(prev, p, colour);
        prev = p;
    }
}

// A patrol route: a small diamond on a post at each point (the first larger), joined in walking order, the
// last back to the first for a loop.
void patrol_route(render::DebugDraw& draw, const level::Patrol& patrol, bool selected) {
    const Vec4 colour = selected ? Vec4(0.25f, 0.95f, 1.0f, 1.0f) : Vec4(0.25f, 0.8f, 0.95f, 0.55f);
    const Vec3 lift(0, 0.15f, 0);
    for (size_t i = 0; i < patrol.points.size(); ++i) {
        const Vec3 p = patrol.points[i] + lift;
        const float r = i == 0 ? 0.6f : 0.4f;
        const Vec3 corners[4] = {p + Vec3(r, 0, 0), p + Vec3(0, 0, r), p - Vec3(r, 0, 0), p - Vec3(0, 0, r)};
        for (int k = 0; k < 4; ++k) draw.line(corners[k], corners[(k + 1) % 4], colour);
        draw.line(p, p + Vec3(0, 1.2f, 0), colour);
        if (i + 1 < patrol.points.size()) draw.line(p, patrol.points[i + 1] + lift, colour);
    }
    if (!patrol.ping_pong() && patrol.points.size() > 2)
        draw.line(patrol.points.back() + lift, patrol.points.front() + lift, colour);
}

// Around the point under the camera, on y = 0: minor lines every 4 units, major every 16 (a wall). The axis
// views draw theirs on screen (viewport.cpp).
void ground_grid(render::DebugDraw& debug, const ViewCamera& view) {
    const float step = 4.0f, extent = 96.0f;
    // Centred where the view looks at the ground (or under the camera when it looks up).
    Vec3 c = view.camera.position;
    const Vec3 f = view.camera.forward();
    if (f.y < -0.05f && c.y > 0.0f) c += f * std::min(c.y / -f.y, 150.0f);
    const float cx = std::round(c.x / 16.0f) * 16.0f, cz = std::round(c.z / 16.0f) * 16.0f;
    for (float o = -extent; o <= extent; o += step) {
        const bool major_x = std::fmod(std::abs(cx + o), 16.0f) < 0.01f;
        const bool major_z = std::fmod(std::abs(cz + o), 16.0f) < 0.01f;
        debug.line(Vec3(cx + o, 0.01f, cz - extent), Vec3(cx + o, 0.01f, cz + extent),
                   std::abs(cx + o) < 0.01f ? Vec4(0.3f, 0.45f, 1.0f, 0.8f)
                   : major_x                ? kGridMajor
                                            : kGridMinor);
        debug.line(Vec3(cx - extent, 0.01f, cz + o), Vec3(cx + extent, 0.01f, cz + o),
                   std::abs(cz + o) < 0.01f ? Vec4(1.0f, 0.35f, 0.3f, 0.8f)
                   : major_z                ? kGridMajor
                                            : kGridMinor);
    }
}
} // namespace

void draw_obb(render::DebugDraw& debug, const geometry::Obb& box, const Vec4& colour) {
    Mat4 m(box.axes);
    m[3] = Vec4(box.center, 1.0f);
    debug.box(m, box.half, colour);
}

bool Overlays::shows(const Document& doc, const level::Entity& e) const {
    if (doc.hidden.contains(e.id)) return false;
    const auto* floor = e.try_as<level::FloorProps>();
    return ceilings || !floor || !floor->ceiling;
}

void ViewportLines::draw(render::DebugDraw& debug, const ViewCamera& view, const Editor& editor,
                         const Overlays& overlays, LogicOverlay& logic, bool screenshot) {
    if (overlays.navmesh) navmesh(debug, editor, screenshot);
    if (overlays.grid && !view.orthographic()) ground_grid(debug, view);
    const Document& doc = editor.doc();
    for (const auto& e : doc.level.entities) {
        if (!overlays.shows(doc, e)) continue;
        entity(debug, view, doc, overlays, e);
        logic.draw_marker(debug, view, e, doc.is_selected(e.id));
    }
    if (overlays.player_start) player_start(debug, editor);
}

void ViewportLines::entity(render::DebugDraw& debug, const ViewCamera& view, const Document& doc,
                           const Overlays& overlays, const level::Entity& e) {
    const bool selected = doc.is_selected(e.id);
    const auto outline = view.orthographic() && overlays.outlines ? outline_colour(e) : std::nullopt;
    if (selected || overlays.collision || outline) {
        geometry::Obb box = entity_obb(e);
        if (selected) box.half += Vec3(0.06f);
        draw_obb(debug, box, selected ? kSelected : overlays.collision ? kCollision : *outline);
    }
    if (overlays.lights) {
        if (const auto* fl = e.try_as<level::FloorLightProps>()) {
            const Vec3 lamp = e.position + Vec3(0, fl->height, 0);
            circle(debug, Vec3(e.position.x, e.position.y + 0.05f, e.position.z), fl->light.range,
                   Vec4(1.0f, 0.9f, 0.4f, selected ? 0.9f : 0.35f));
            debug.line(e.position, lamp, Vec4(1.0f, 0.9f, 0.4f, 0.6f));
        } else if (const auto* tl = e.try_as<level::TopLightProps>()) {
            const Vec3 bulb = e.position - Vec3(0, tl->hang, 0);
            circle(debug, bulb, tl->light.range, Vec4(1.0f, 0.9f, 0.4f, selected ? 0.9f : 0.35f));
        }
    }
    if (overlays.robots) {
        if (const auto* r = e.try_as<level::RobotProps>()) {
            const Vec3 base = e.position + Vec3(0, 0.08f, 0);
            circle(debug, base, r->eye_radius_min, Vec4(1.0f, 0.85f, 0.2f, 0.75f), 64);
            circle(debug, base, r->eye_radius_max, Vec4(1.0f, 0.85f, 0.2f, 0.3f), 64);
            circle(debug, base, r->shooting_distance, Vec4(1.0f, 0.25f, 0.2f, 0.8f), 48);
        }
    }
    if (const auto* r = e.try_as<level::RobotProps>(); r && (selected || overlays.patrols))
        patrol_route(debug, r->patrol, selected);
    if (e.type() == level::EntityType::Sound) sound_emitter(debug, view, e, selected, overlays.sound_radii);
}

// The robots' walkable surface, outlined just above it: green where robots walk, orange in doorways. Rebuilt
// in the background when the level changes, never during a drag (the newest finished mesh stays shown).
void ViewportLines::navmesh(render::DebugDraw& debug, const Editor& editor, bool screenshot) {
    const bool continuous = editor.history().in_transaction() ||
                            (ImGui::GetCurrentContext() != nullptr && ImGui::IsAnyItemActive());
    if (!continuous) nav_preview_.update(editor.level(), editor.revision());
    if (screenshot) nav_preview_.finish(); // a screenshot shows the mesh, not "building"
    const Vec3 lift(0.0f, 0.06f, 0.0f);
    for (const nav::NavTriangle& t : nav_preview_.triangles()) {
        const Vec4 colour = t.door_id != 0 ? Vec4(1.0f, 0.6f, 0.2f, 0.8f) : Vec4(0.3f, 0.95f, 0.5f, 0.45f);
        debug.line(t.a + lift, t.b + lift, colour);
        debug.line(t.b + lift, t.c + lift, colour);
        debug.line(t.c + lift, t.a + lift, colour);
    }
}

// A speaker facing the camera (the renderer draws nothing for a sound: it is heard, not seen); selected, the
// sphere it is heard within; with View > All sound radii, every emitter's horizontal circle, faintly.
void ViewportLines::sound_emitter(render::DebugDraw& debug, const ViewCamera& view, const level::Entity& e,
                                  bool selected, bool all_radii) {
    const auto& sound = e.as<level::SoundProps>();
    const Vec4 colour = selected ? kSoundMarker : Vec4(Vec3(kSoundMarker), 0.8f);
    marker_lines_.clear();
    speaker_icon(e.position, view.camera.right(), view.camera.up(), level::kSoundMarkerHalfSize,
                 marker_lines_);
    if (selected) wire_sphere(e.position, sound.radius, 64, marker_lines_);
    for (const MarkerLine& line : marker_lines_) debug.line(line.a, line.b, colour);
    if (all_radii && !selected) circle(debug, e.position, sound.radius, Vec4(Vec3(kSoundMarker), 0.3f), 64);
}

void ViewportLines::player_start(render::DebugDraw& debug, const Editor& editor) {
    marker_lines_.clear();
    player_start_figure(editor.level().player_start, marker_lines_);
    const Vec4 colour = editor.doc().player_start_selected() ? kSelected : kStartColour;
    for (const MarkerLine& line : marker_lines_) debug.line(line.a, line.b, colour);
}

// The entered group's bounds, a thin box in every view, so the designer sees they are inside it.
void ViewportLines::open_group_box(render::DebugDraw& debug, const Editor& editor) const {
    const int open = editor.open_group();
    if (open == 0) return;
    std::vector<const level::Entity*> members;
    for (int id : group_entities_deep(editor.level().editor, open))
        if (const level::Entity* e = editor.level().find(id)) members.push_back(e);
    const geometry::Aabb box = selection_bounds(members);
    if (!box.valid()) return;
    const Vec3 lo = box.min - Vec3(0.25f), hi = box.max + Vec3(0.25f);
    Mat4 m(1.0f);
    m[3] = Vec4((lo + hi) * 0.5f, 1.0f);
    debug.box(m, (hi - lo) * 0.5f, Vec4(0.55f, 0.75f, 1.0f, 0.9f));
}

void ViewportLines::status(nlohmann::json& s, const Overlays& overlays) const {
    s["navmesh"] = {{"shown", overlays.navmesh},
                    {"builds", nav_preview_.stats().builds},
                    {"last_build_ms", nav_preview_.stats().last_build_ms},
                    {"triangles", nav_preview_.stats().triangles},
                    {"error", nav_preview_.error()}};
}

} // namespace ks::editor::ui
