// The 3D viewport: the level drawn by the game's renderer into the panel's own target, overlays (grid,
// selection, collision bounds, light ranges, robot radii, patrol routes, player start), the camera,
// picking, box select, placing from the palette and the gizmo.
#include "model/edit_entities.h"
#include "model/edit_prefabs.h"
#include "model/edit_selection.h"
#include "ui/dojo_panel.h"
#include "ui/editor_app.h"
#include "ui/layout.h"
#include "ui/structure_actions.h"
#include "ui/view_input.h"
#include "view/face_picking.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <optional>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>

namespace ks::editor::ui {
namespace fs = std::filesystem;

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

Mat4 obb_transform(const geometry::Obb& box) {
    Mat4 m(box.axes);
    m[3] = Vec4(box.center, 1.0f);
    return m;
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

} // namespace

bool EditorApp::shown(const level::Entity& e) const {
    if (editor_.doc().hidden.contains(e.id)) return false;
    const auto* floor = e.try_as<level::FloorProps>();
    return overlays_.ceilings || !floor || !floor->ceiling;
}

void EditorApp::rebuild_scene_if_changed() {
    const std::uint64_t revision = editor_.revision() ^
                                   (static_cast<std::uint64_t>(editor_.doc().hidden.size()) << 48) ^
                                   (static_cast<std::uint64_t>(overlays_.ceilings) << 63);
    // While a continuous edit is in progress (a gizmo drag: an open history transaction; an inspector field
    // dragged: an active ImGui item, its edits merged into one step) the scene is rebuilt every changed frame
    // without the light-map bake (most of a rebuild's cost on a software rasteriser); the bake runs once when
    // the edit ends, even if nothing changed since.
    const bool continuous = editor_.history().in_transaction() ||
                            (ImGui::GetCurrentContext() != nullptr && ImGui::IsAnyItemActive());
    const bool bake = !continuous;
    if (scene_ && revision == scene_revision_ && (scene_baked_ || !bake)) return;
    const std::clock_t cpu_start = std::clock();
    render::LevelSceneOptions options = render::level_scene_options(renderer_->settings());
    options.bake_light_map = options.bake_light_map && bake;
    const auto& entities = editor_.level().entities;
    if (std::all_of(entities.begin(), entities.end(), [&](const level::Entity& e) { return shown(e); })) {
        scene_ = render::LevelScene::build(editor_.level(), assets_, options);
    } else { // hidden entities (and ceilings, unless shown) are left out of the picture and of picking
        level::Level visible = editor_.level();
        std::erase_if(visible.entities, [&](const level::Entity& e) { return !shown(e); });
        scene_ = render::LevelScene::build(visible, assets_, options);
    }
    scene_stats_.last_build_cpu_ms = 1000.0 * static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    ++scene_stats_.builds;
    if (scene_->bake_stats().faces > 0) ++scene_stats_.bakes;
    renderer_->invalidate_shadows();
    scene_revision_ = revision;
    scene_baked_ = bake;
}

// The robots' walkable surface, outlined just above it: green where robots walk, orange in doorways. Rebuilt
// in the background when the level changes, never during a drag (the newest finished mesh stays shown).
void EditorApp::draw_navmesh() {
    const bool continuous = editor_.history().in_transaction() ||
                            (ImGui::GetCurrentContext() != nullptr && ImGui::IsAnyItemActive());
    if (!continuous) nav_preview_.update(editor_.level(), editor_.revision());
    if (shell_.screenshot_mode()) nav_preview_.finish(); // a screenshot shows the mesh, not "building"
    const Vec3 lift(0.0f, 0.06f, 0.0f);
    for (const nav::NavTriangle& t : nav_preview_.triangles()) {
        const Vec4 colour = t.door_id != 0 ? Vec4(1.0f, 0.6f, 0.2f, 0.8f) : Vec4(0.3f, 0.95f, 0.5f, 0.45f);
        debug_.line(t.a + lift, t.b + lift, colour);
        debug_.line(t.b + lift, t.c + lift, colour);
        debug_.line(t.c + lift, t.a + lift, colour);
    }
}

void EditorApp::draw_overlays() {
    const Document& doc = editor_.doc();
    if (overlays_.navmesh) draw_navmesh();
    if (overlays_.grid && !view_.orthographic()) { // the axis views draw theirs on screen (draw_axis_grid)
        // Around the point under the camera, on y = 0: minor lines every 4 units, major every 16 (a wall).
        const float step = 4.0f, extent = 96.0f;
        // Centred where the view looks at the ground (or under the camera when it looks up).
        Vec3 c = view_.camera.position;
        const Vec3 f = view_.camera.forward();
        if (f.y < -0.05f && c.y > 0.0f) c += f * std::min(c.y / -f.y, 150.0f);
        const float cx = std::round(c.x / 16.0f) * 16.0f, cz = std::round(c.z / 16.0f) * 16.0f;
        for (float o = -extent; o <= extent; o += step) {
            const bool major_x = std::fmod(std::abs(cx + o), 16.0f) < 0.01f;
            const bool major_z = std::fmod(std::abs(cz + o), 16.0f) < 0.01f;
            debug_.line(Vec3(cx + o, 0.01f, cz - extent), Vec3(cx + o, 0.01f, cz + extent),
                        std::abs(cx + o) < 0.01f ? Vec4(0.3f, 0.45f, 1.0f, 0.8f)
                        : major_x                ? kGridMajor
                                                 : kGridMinor);
            debug_.line(Vec3(cx - extent, 0.01f, cz + o), Vec3(cx + extent, 0.01f, cz + o),
                        std::abs(cz + o) < 0.01f ? Vec4(1.0f, 0.35f, 0.3f, 0.8f)
                        : major_z                ? kGridMajor
                                                 : kGridMinor);
        }
    }
    for (const auto& e : doc.level.entities) {
        if (!shown(e)) continue;
        const bool selected = doc.is_selected(e.id);
        const auto outline = view_.orthographic() && overlays_.outlines ? outline_colour(e) : std::nullopt;
        if (selected || overlays_.collision || outline) {
            geometry::Obb box = entity_obb(e);
            if (selected) box.half += Vec3(0.06f);
            debug_.box(obb_transform(box), box.half,
                       selected              ? kSelected
                       : overlays_.collision ? kCollision
                                             : *outline);
        }
        if (overlays_.lights) {
            if (const auto* fl = e.try_as<level::FloorLightProps>()) {
                const Vec3 lamp = e.position + Vec3(0, fl->height, 0);
                circle(debug_, Vec3(e.position.x, e.position.y + 0.05f, e.position.z), fl->light.range,
                       Vec4(1.0f, 0.9f, 0.4f, selected ? 0.9f : 0.35f));
                debug_.line(e.position, lamp, Vec4(1.0f, 0.9f, 0.4f, 0.6f));
            } else if (const auto* tl = e.try_as<level::TopLightProps>()) {
                const Vec3 bulb = e.position - Vec3(0, tl->hang, 0);
                circle(debug_, bulb, tl->light.range, Vec4(1.0f, 0.9f, 0.4f, selected ? 0.9f : 0.35f));
            }
        }
        if (overlays_.robots) {
            if (const auto* r = e.try_as<level::RobotProps>()) {
                const Vec3 base = e.position + Vec3(0, 0.08f, 0);
                circle(debug_, base, r->eye_radius_min, Vec4(1.0f, 0.85f, 0.2f, 0.75f), 64);
                circle(debug_, base, r->eye_radius_max, Vec4(1.0f, 0.85f, 0.2f, 0.3f), 64);
                circle(debug_, base, r->shooting_distance, Vec4(1.0f, 0.25f, 0.2f, 0.8f), 48);
            }
        }
        if (const auto* r = e.try_as<level::RobotProps>(); r && (selected || overlays_.patrols))
            patrol_route(debug_, r->patrol, selected);
        if (e.type() == level::EntityType::Sound) draw_sound_emitter(e, selected);
        logic_overlay_.draw_marker(debug_, view_, e, selected);
    }
    draw_player_start();
    if (placing_ && place_ray_) { // where a click would place (in every pane of the 4-up view)
        const Vec3 p = place_point(*place_ray_);
        if (placing_.type) {
            level::Entity preview;
            preview.position = placement_for(*placing_.type, p);
            preview.props = level::default_props(*placing_.type);
            const geometry::Obb box = entity_obb(preview);
            debug_.box(obb_transform(box), box.half, Vec4(0.4f, 1.0f, 0.5f, 0.9f));
        } else if (const PrefabEntry* entry = editor_.prefabs().find(placing_.prefab);
                   entry && entry->prefab) {
            for (const level::Entity& local : entry->prefab->entities) { // each entity where it would land
                level::Entity at = local;
                at.position += p;
                const geometry::Obb box = entity_obb(at);
                debug_.box(obb_transform(box), box.half, Vec4(0.4f, 1.0f, 0.5f, 0.75f));
            }
        }
    }
    draw_open_group_box();
    draw_selected_faces(debug_, editor_.doc()); // face_inspector.h
}

// A speaker facing the camera (the renderer draws nothing for a sound: it is heard, not seen); selected, the
// sphere it is heard within; with View > All sound radii, every emitter's horizontal circle, faintly.
void EditorApp::draw_sound_emitter(const level::Entity& e, bool selected) {
    const auto& sound = e.as<level::SoundProps>();
    const Vec4 colour = selected ? kSoundMarker : Vec4(Vec3(kSoundMarker), 0.8f);
    marker_lines_.clear();
    speaker_icon(e.position, view_.camera.right(), view_.camera.up(), level::kSoundMarkerHalfSize,
                 marker_lines_);
    if (selected) wire_sphere(e.position, sound.radius, 64, marker_lines_);
    for (const MarkerLine& line : marker_lines_) debug_.line(line.a, line.b, colour);
    if (overlays_.sound_radii && !selected)
        circle(debug_, e.position, sound.radius, Vec4(Vec3(kSoundMarker), 0.3f), 64);
}

void EditorApp::draw_axis_grid(ImDrawList* draw, Vec2 origin) const {
    // The view plane's grid on screen, over the picture: lines at least 10 pixels apart (the grid step
    // doubled until they are), majors every 16 units (a wall), the world axes through 0.
    const GridPlan plan = plan_axis_grid(view_, editor_.doc().grid.step, 10.0f);
    const Vec2 size = view_.viewport();
    const ImU32 axis_colours[3] = {IM_COL32(235, 80, 70, 170), IM_COL32(110, 215, 80, 170),
                                   IM_COL32(80, 130, 255, 170)};
    auto colour = [&](float coordinate, int other_axis) {
        if (std::abs(coordinate) < plan.step * 0.01f) return axis_colours[other_axis];
        const float major = std::max(16.0f, plan.step * 4.0f);
        return std::abs(std::remainder(coordinate, major)) < plan.step * 0.01f ? IM_COL32(190, 205, 230, 80)
                                                                               : IM_COL32(170, 180, 200, 34);
    };
    const Vec3 at = view_.camera.position + view_.forward();
    // Lines of constant u are vertical on screen, lines of constant v horizontal.
    auto lines = [&](int axis, float first, int count, int other_axis, bool vertical) {
        for (int i = 0; i < count; ++i) {
            const float c = first + static_cast<float>(i) * plan.step;
            Vec3 p = at;
            p[axis] = c;
            Vec2 s;
            if (!view_.project(p, s)) continue;
            const ImVec2 from =
                vertical ? ImVec2(origin.x + s.x, origin.y) : ImVec2(origin.x, origin.y + s.y);
            const ImVec2 to = vertical ? ImVec2(origin.x + s.x, origin.y + size.y)
                                       : ImVec2(origin.x + size.x, origin.y + s.y);
            draw->AddLine(from, to, colour(c, other_axis));
        }
    };
    lines(plan.u_axis, plan.u_first, plan.u_count, plan.v_axis, true);
    lines(plan.v_axis, plan.v_first, plan.v_count, plan.u_axis, false);
    char text[48];
    std::snprintf(text, sizeof(text), "grid %g", plan.step);
    draw->AddText(ImVec2(origin.x + 10, origin.y + 26), IM_COL32(200, 210, 230, 200), text);
}

int EditorApp::pick(const geometry::Ray& ray) const {
    return pick_entity(editor_.doc(), ray, [this](const level::Entity& e) { return shown(e); }).id;
}

Vec3 EditorApp::place_point(const geometry::Ray& ray) const {
    return editor::place_point(
        editor_.doc(), ray, [this](const level::Entity& e) { return shown(e); }, view_.pivot);
}

Vec3 EditorApp::selection_pivot() const {
    return gizmo_frame().pivot;
}

GizmoFrame EditorApp::gizmo_frame() const {
    return editor::gizmo_frame(editor_.doc(), gizmo_.space);
}

void EditorApp::focus_selection() {
    const auto selected = selected_entities(editor_);
    geometry::Aabb box{Vec3(-10.0f), Vec3(10.0f)}; // an empty level
    if (editor_.doc().player_start_selected())
        box = player_obb(editor_.level().player_start).aabb();
    else if (!selected.empty())
        box = selection_bounds(selected);
    else if (!editor_.level().entities.empty())
        box = selection_bounds(editor_.level().entities);
    const Vec3 lo = box.min, hi = box.max;
    if (!quad_.on) {
        view_.focus(lo, hi);
        return;
    }
    sync_active_pane(); // F in the 4-up view focuses every pane
    for (ViewCamera& pane : quad_.cameras) pane.focus(lo, hi);
    view_ = quad_.cameras[static_cast<size_t>(quad_.active)];
}

void EditorApp::level_box(Vec3& lo, Vec3& hi) const {
    lo = Vec3(-20.0f), hi = Vec3(20.0f);
    if (editor_.level().entities.empty()) return;
    const geometry::Aabb box = selection_bounds(editor_.level().entities);
    lo = box.min, hi = box.max;
}

void EditorApp::set_view(ViewMode mode) { // in the 4-up view: the active pane's
    Vec3 lo, hi;
    level_box(lo, hi);
    frame_box(view_, mode, lo, hi);
}

void EditorApp::viewport_panel(float x, float y, float w, float h) {
    ImGui::SetNextWindowPos(ImVec2(x, y));
    ImGui::SetNextWindowSize(ImVec2(w, h));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    ImGui::Begin("Viewport", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoScrollWithMouse);
    ImGui::PopStyleVar();
    // Tool bar: palette, gizmo mode, view.
    ImGui::SetCursorPos(ImVec2(6, 4));
    viewport_toolbar();
    ImGui::SetCursorPos(ImVec2(0, kViewportBar));
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    // The same size the render pass gave the views (render_views).
    const Vec2 area(static_cast<float>(static_cast<int>(w)),
                    static_cast<float>(std::max(1, static_cast<int>(h - kViewportBar))));
    viewport_area_ = {Vec2(origin.x, origin.y), area};
    if (quad_.on) {
        quad_viewport(Vec2(origin.x, origin.y), area);
    } else {
        bool hovered = false;
        single_viewport(Vec2(origin.x, origin.y), hovered);
    }
    ImDrawList* draw = ImGui::GetWindowDrawList();
    // Status overlay: view, camera speed, grid, what a drag does; in the 4-up view over the active pane.
    const ImVec2 under = quad_.on ? ImVec2(viewport_origin_.x, viewport_origin_.y) : origin;
    const Vec2 span = quad_.on ? viewport_size_ : area;
    char text[256];
    char speed[48] = "";
    if (!quad_.on) std::snprintf(speed, sizeof(speed), "  |  fly speed %.1f u/s (wheel)", view_.speed);
    std::snprintf(text, sizeof(text), "%s%s%s  |  grid %.2f %s  |  %s%s%s", quad_.on ? "4-up: " : "",
                  view_mode_name(view_.mode), speed, editor_.doc().grid.step,
                  editor_.doc().grid.snap ? "snap" : "free", gizmo_label(gizmo_).c_str(),
                  gizmo_.readout().empty() ? "" : "  ", gizmo_.readout().c_str());
    draw->PushClipRect(under, ImVec2(under.x + span.x, under.y + span.y), true);
    draw->AddRectFilled(ImVec2(under.x + 6, under.y + span.y - 26),
                        ImVec2(under.x + span.x - 6, under.y + span.y - 4), IM_COL32(15, 17, 22, 170), 4.0f);
    draw->AddText(ImVec2(under.x + 12, under.y + span.y - 23), IM_COL32(225, 230, 240, 255), text);
    draw->PopClipRect();
    clip_preview_.draw(editor_, *dojo_, Vec2(origin.x, origin.y),
                       area); // the selection's, not a pane's: across the bottom
    logic_.pick_hint(draw, viewport_origin_);
    if (!quad_.on) open_group_hint(draw, viewport_origin_, viewport_size_, false);
    if (placing_) {
        const std::string hint = "Click to place " + placing_.label() + "  (Shift: several, Esc: stop)";
        draw->AddText(ImVec2(viewport_origin_.x + 12, viewport_origin_.y + 8), IM_COL32(140, 255, 160, 255),
                      hint.c_str());
    }
    ImGui::End();
}

// The single view: the picture, the mouse and the overlays.
void EditorApp::single_viewport(Vec2 origin, bool& hovered) {
    const Vec2 size(static_cast<float>(viewport_target_.width()),
                    static_cast<float>(viewport_target_.height()));
    ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(viewport_target_.texture())),
                 ImVec2(size.x, size.y), ImVec2(0, 1), ImVec2(1, 0));
    viewport_origin_ = origin;
    viewport_size_ = size;
    view_.set_viewport(size);
    // A screenshot does not depend on where the X pointer happens to rest (no hot gizmo handle).
    hovered = ImGui::IsItemHovered() && !shell_.screenshot_mode();
    viewport_hovered_ = hovered;
    viewport_input(viewport_origin_, hovered);
    pane_overlays(ImGui::GetWindowDrawList(), viewport_origin_, true);
}

// Over one view (the single view, or a pane of the 4-up view with its camera in view_): the axis views'
// grid, the level logic, the play-test report, the gizmo, the box being dragged (`active`: the view the
// mouse works in) and the axis indicator in the corner.
void EditorApp::pane_overlays(ImDrawList* draw, Vec2 origin, bool active) {
    const Vec2 size = view_.viewport();
    draw->PushClipRect(ImVec2(origin.x, origin.y), ImVec2(origin.x + size.x, origin.y + size.y), true);
    if (overlays_.grid && view_.orthographic()) draw_axis_grid(draw, origin);
    logic_overlay_.draw(draw, origin, view_, editor_, overlays_.links, overlays_.ceilings,
                        [this](const level::Entity& e) { return shown(e); });
    analysis_.draw(draw, view_, origin);
    if (!editor_.doc().selection.empty() && !placing_)
        draw_gizmo(draw, gizmo_, view_, origin, gizmo_frame(), active ? hovered_handle_ : Handle::None);
    if (active && box_selecting_) {
        const ImVec2 m = ImGui::GetIO().MousePos;
        draw->AddRectFilled(ImVec2(box_start_.x, box_start_.y), m, IM_COL32(90, 160, 255, 40));
        draw->AddRect(ImVec2(box_start_.x, box_start_.y), m, IM_COL32(90, 160, 255, 200));
    }
    const Vec2 corner(origin.x + size.x - 40, origin.y + 40);
    const Mat4 view_matrix = view_.camera.view();
    const char* names[3] = {"X", "Y", "Z"};
    const ImU32 colours[3] = {IM_COL32(235, 70, 70, 255), IM_COL32(110, 215, 80, 255),
                              IM_COL32(70, 130, 240, 255)};
    for (int i = 0; i < 3; ++i) {
        Vec3 axis(0.0f);
        axis[i] = 1.0f;
        const Vec3 v = Mat3(view_matrix) * axis;
        const ImVec2 tip(corner.x + v.x * 24.0f, corner.y - v.y * 24.0f);
        draw->AddLine(ImVec2(corner.x, corner.y), tip, colours[i], 2.0f);
        draw->AddText(ImVec2(tip.x - 3, tip.y - 7), colours[i], names[i]);
    }
    draw->PopClipRect();
}

void EditorApp::viewport_input(Vec2 origin, bool hovered) {
    const ImGuiIO& io = ImGui::GetIO();
    const Vec2 mouse(io.MousePos.x - origin.x, io.MousePos.y - origin.y);
    place_ray_.reset();
    if (hovered) place_ray_ = view_.ray(mouse);
    if (!shell_.screenshot_mode())
        flying_ = view_.update(
            read_view_input(shell_.window(),
                            hovered && !gizmo_.dragging() && !patrol_drag_.dragging() && !box_selecting_,
                            mouse, hovered ? wheel_ : 0.0f),
            io.DeltaTime);
    if (logic_.picking() && hovered && ImGui::IsMouseReleased(ImGuiMouseButton_Right) &&
        io.MouseDragMaxDistanceSqr[1] < 16.0f)
        logic_.end_pick(); // a right click (not a fly drag) cancels picking
    if (flying_) return;
    if (logic_.picking()) { // the next left click picks; nothing else happens meanwhile
        if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left))
            logic_.pick_click(pick(view_.ray(mouse)));
        hovered_handle_ = Handle::None;
        return;
    }
    const bool has_selection = !editor_.doc().selection.empty();
    if (patrol_drag_.dragging()) {
        if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
            if (auto message = patrol_drag_.drag(editor_, view_, mouse); !message.empty())
                log_line(message, true);
        } else {
            patrol_drag_.end();
        }
        return;
    }
    if (gizmo_.dragging()) {
        if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
            if (auto message = gizmo_.drag(editor_, view_, mouse, io.KeyCtrl); !message.empty())
                log_line(message, true);
        } else {
            gizmo_.end(editor_);
        }
        return;
    }
    hovered_handle_ =
        hovered && has_selection && !placing_ ? gizmo_.hit(view_, gizmo_frame(), mouse) : Handle::None;
    if (io.KeyAlt) return; // Alt + left drag orbits
    if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
        if (placing_) {
            const geometry::Ray ray = view_.ray(mouse);
            if (placing_.type) {
                auto placed = place(editor_, *placing_.type, placement_for(*placing_.type, place_point(ray)));
                if (!placed) log_line("place: " + placed.error().str(), true);
            } else {
                auto placed = place_prefab(editor_, placing_.prefab, place_point(ray), 0.0f);
                if (!placed) log_line("place prefab: " + placed.error().str(), true);
            }
            if (!io.KeyShift) placing_.reset(); // Shift keeps placing
            return;
        }
        if (io.KeyCtrl && io.KeyShift) { // a brush face joins or leaves the face selection (face_picking.h)
            report(click_face(editor_, pick_face(editor_.doc(), view_.ray(mouse),
                                                 [this](const level::Entity& e) { return shown(e); })),
                   "face");
            return;
        }
        // A double click on a group's member enters the group (before the gizmo: the first click selected
        // the group, and its gizmo may lie under the pointer now).
        if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left) &&
            double_click_enter(editor_, log_, pick(view_.ray(mouse))))
            return;
        if (auto point = pick_patrol_point(editor_, view_, mouse)) { // a route point beats the gizmo
            patrol_drag_.begin(editor_, view_, *point, mouse);
            return;
        }
        if (hovered_handle_ != Handle::None) {
            gizmo_.begin(editor_, view_, gizmo_frame(), hovered_handle_, mouse);
            return;
        }
        box_selecting_ = true;
        box_start_ = Vec2(io.MousePos.x, io.MousePos.y);
    }
    if (box_selecting_ && !ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        box_selecting_ = false;
        const Vec2 end(io.MousePos.x, io.MousePos.y);
        const SelectMode mode = io.KeyCtrl    ? SelectMode::Toggle
                                : io.KeyShift ? SelectMode::Add
                                              : SelectMode::Replace;
        if (glm::length(end - box_start_) < 4.0f) { // a click: pick under the cursor (the player start too)
            const int id = pick_selectable(
                               editor_.doc(), view_.ray(mouse),
                               [this](const level::Entity& e) { return shown(e); }, overlays_.player_start)
                               .id;
            if (id > 0) // its whole group, or inside an entered group what lies in it
                report(select_picked(editor_, id, mode), "select");
            else if (id)
                report(select(editor_, {id}, mode), "select");
            else if (mode == SelectMode::Replace)
                editor_.clear_selection();
            return;
        }
        const Vec2 lo = glm::min(box_start_, end) - origin, hi = glm::max(box_start_, end) - origin;
        const int n = select_picked_where(
            editor_,
            [&](const level::Entity& e) {
                Vec2 p;
                if (!view_.project(entity_obb(e).center, p)) return false;
                return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y;
            },
            mode);
        log_line("box select: " + std::to_string(n) + " entities");
    }
}

} // namespace ks::editor::ui
