// The level viewport's mouse and keys (level_viewport.h): the camera, pick mode's clicks, patrol point and
// gizmo drags, the armed tool, picking and box select; the viewport's shortcuts, Esc and the View menu.
#include "model/edit_selection.h"
#include "ui/level_viewport.h"
#include "ui/structure_actions.h"
#include "ui/view_input.h"
#include "view/face_picking.h"
#include "view/model_drop.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

namespace ks::editor::ui {

void LevelViewport::input(Vec2 origin, bool hovered) {
    const ImGuiIO& io = ImGui::GetIO();
    const Vec2 mouse(io.MousePos.x - origin.x, io.MousePos.y - origin.y);
    place_ray_.reset();
    if (hovered) place_ray_ = view_.ray(mouse);
    if (!ctx_.shell.screenshot_mode())
        flying_ = view_.update(read_view_input(ctx_.shell.window(),
                                               hovered && !gizmo_.dragging() && !patrol_drag_.dragging() &&
                                                   !face_drag_.dragging() && !box_selecting_,
                                               mouse, hovered ? io.MouseWheel : 0.0f),
                               io.DeltaTime);
    LogicPanels& logic = ctx_.logic;
    if (logic.picking() && hovered && ImGui::IsMouseReleased(ImGuiMouseButton_Right) &&
        io.MouseDragMaxDistanceSqr[1] < 16.0f)
        logic.end_pick(); // a right click (not a fly drag) cancels picking
    if (flying_) return;
    if (logic.picking()) { // the next left click picks; nothing else happens meanwhile
        if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) logic.pick_click(pick(view_.ray(mouse)));
        hovered_handle_ = Handle::None;
        return;
    }
    const bool has_selection = !ctx_.editor.doc().selection.empty();
    if (drag(mouse)) return;
    hovered_handle_ = hovered && has_selection && !tool_armed() && geometry_.active() == GeometryTool::none
                          ? gizmo_.hit(view_, gizmo_frame(), mouse)
                          : Handle::None;
    if (io.KeyAlt) return; // Alt + left drag orbits
    if (ViewportTool* tool = armed_tool()) {
        const ShownFn shown = shown_fn();
        tool->input(ToolInput{ctx_.editor, ctx_.log, view_, mouse, hovered, shown});
        return;
    }
    if (geometry_.active() != GeometryTool::none) { // a geometry tool takes the left mouse
        geometry_.mouse(ctx_.editor, ctx_.log, view_, mouse, hovered, shown_fn());
        hovered_handle_ = Handle::None;
        return;
    }
    if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) click(mouse);
    if (box_selecting_ && !ImGui::IsMouseDown(ImGuiMouseButton_Left)) end_box_select(origin, mouse);
}

// A thumbnail of the Models tab dragged over the view whose picture was the last item (view_ is its camera):
// the box where it would land while it hovers (the place tool draws it), the model placed there when it is
// let go: one undo step, selected, as a click with the model armed would.
void LevelViewport::model_drop(Vec2 origin) {
    if (ctx_.shell.screenshot_mode() || !ImGui::BeginDragDropTarget()) return;
    const ImGuiPayload* payload =
        ImGui::AcceptDragDropPayload(kModelDragPayload, ImGuiDragDropFlags_AcceptBeforeDelivery);
    const std::optional<std::string> file =
        payload ? model_payload_file(payload->Data, payload->DataSize) : std::nullopt;
    if (file) {
        const ImGuiIO& io = ImGui::GetIO();
        const geometry::Ray ray = view_.ray(Vec2(io.MousePos.x - origin.x, io.MousePos.y - origin.y));
        place_.preview_drop(*file, ray);
        if (payload->IsDelivery()) {
            place_.end_drop_preview();
            if (auto placed = place_model_at(ctx_.editor, *file, ray, shown_fn(), view_.pivot); !placed)
                ctx_.log.line("place model: " + placed.error().str(), true);
        }
    }
    ImGui::EndDragDropTarget();
}

bool LevelViewport::drag(Vec2 mouse) {
    Editor& editor = ctx_.editor;
    if (patrol_drag_.dragging()) {
        if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
            if (auto message = patrol_drag_.drag(editor, view_, mouse); !message.empty())
                ctx_.log.line(message, true);
        } else {
            patrol_drag_.end();
        }
        return true;
    }
    if (face_drag_.dragging()) {
        if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
            if (ImGui::IsMouseDragging(ImGuiMouseButton_Left)) // past the click distance: a drag
                ctx_.log.report(face_drag_.drag(editor, view_.ray(mouse)), "texture drag");
        } else {
            // A press and release on the spot that changed nothing is a click: the box select below picks.
            box_selecting_ = !face_drag_.changed() && ImGui::GetIO().MouseDragMaxDistanceSqr[0] < 16.0f;
            face_drag_.end(editor);
        }
        return true;
    }
    if (gizmo_.dragging()) {
        if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
            if (auto message = gizmo_.drag(editor, view_, mouse, ImGui::GetIO().KeyCtrl); !message.empty())
                ctx_.log.line(message, true);
        } else {
            gizmo_.end(editor);
        }
        return true;
    }
    return false;
}

void LevelViewport::click(Vec2 mouse) {
    Editor& editor = ctx_.editor;
    if (ImGui::GetIO().KeyCtrl &&
        ImGui::GetIO().KeyShift) { // a brush face joins or leaves the face selection
        ctx_.log.report(click_face(editor, pick_face(editor.doc(), view_.ray(mouse), shown_fn())), "face");
        return;
    }
    // A double click on a group's member enters the group (before the gizmo: the first click selected the
    // group, and its gizmo may lie under the pointer now).
    if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left) &&
        double_click_enter(editor, ctx_.log, pick(view_.ray(mouse))))
        return;
    if (auto point = pick_patrol_point(editor, view_, mouse)) { // a route point beats the gizmo
        patrol_drag_.begin(editor, view_, *point, mouse);
        return;
    }
    if (hovered_handle_ != Handle::None) {
        gizmo_.begin(editor, view_, gizmo_frame(), hovered_handle_, mouse);
        return;
    }
    box_start_ = Vec2(ImGui::GetIO().MousePos.x, ImGui::GetIO().MousePos.y);
    const ImGuiIO& io = ImGui::GetIO();
    if (begin_face_drag(face_drag_, editor, view_.ray(mouse), shown_fn(),
                        face_drag_mode(io.KeyCtrl, io.KeyShift)))
        return; // a selected face's texture: moved, or turned with Ctrl, scaled with Shift
    box_selecting_ = true;
}

void LevelViewport::end_box_select(Vec2 origin, Vec2 mouse) {
    const ImGuiIO& io = ImGui::GetIO();
    Editor& editor = ctx_.editor;
    box_selecting_ = false;
    const Vec2 end(io.MousePos.x, io.MousePos.y);
    const SelectMode mode = io.KeyCtrl    ? SelectMode::Toggle
                            : io.KeyShift ? SelectMode::Add
                                          : SelectMode::Replace;
    if (glm::length(end - box_start_) < 4.0f) { // a click: pick under the cursor (the player start too)
        const int id = pick_selectable(editor.doc(), view_.ray(mouse), shown_fn(), overlays_.player_start).id;
        if (id > 0) // its whole group, or inside an entered group what lies in it
            ctx_.log.report(select_picked(editor, id, mode), "select");
        else if (id)
            ctx_.log.report(select(editor, {id}, mode), "select");
        else if (mode == SelectMode::Replace)
            editor.clear_selection();
        return;
    }
    const Vec2 lo = glm::min(box_start_, end) - origin, hi = glm::max(box_start_, end) - origin;
    const int n = select_picked_where(
        editor,
        [&](const level::Entity& e) {
            Vec2 p;
            if (!view_.project(entity_obb(e).center, p)) return false;
            return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y;
        },
        mode);
    ctx_.log.line("box select: " + std::to_string(n) + " entities");
}

int LevelViewport::pick(const geometry::Ray& ray) const {
    return pick_entity(ctx_.editor.doc(), ray, shown_fn()).id;
}

GizmoFrame LevelViewport::gizmo_frame() const {
    return editor::gizmo_frame(ctx_.editor.doc(), gizmo_.space);
}

ViewportTool* LevelViewport::armed_tool() {
    for (ViewportTool* tool : tools())
        if (tool->armed()) return tool;
    return nullptr;
}

bool LevelViewport::tool_armed() const {
    for (const ViewportTool* tool : tools())
        if (tool->armed()) return true;
    return false;
}

void LevelViewport::disarm_tools() {
    for (ViewportTool* tool : tools()) tool->disarm();
}

bool LevelViewport::escape() {
    if (gizmo_.dragging()) {
        gizmo_.cancel(ctx_.editor);
        return true;
    }
    if (face_drag_.dragging()) {
        face_drag_.cancel(ctx_.editor);
        return true;
    }
    if (ViewportTool* tool = armed_tool()) {
        tool->disarm();
        return true;
    }
    return false;
}

void LevelViewport::shortcuts() {
    // ImGui 1.86 indexes keys by the backend's codes: GLFW_KEY_* name physical positions (US layout).
    auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
    if (pressed(GLFW_KEY_F)) focus_selection();
    if (pressed(GLFW_KEY_W)) gizmo_.mode = GizmoMode::Move;
    if (pressed(GLFW_KEY_E)) gizmo_.mode = GizmoMode::Rotate;
    if (pressed(GLFW_KEY_R)) gizmo_.mode = GizmoMode::Scale;
    if (pressed(GLFW_KEY_X))
        gizmo_.space = gizmo_.space == RotationSpace::World ? RotationSpace::Local : RotationSpace::World;
    if (pressed(GLFW_KEY_KP_7)) set_view(ViewMode::Top);
    if (pressed(GLFW_KEY_KP_1)) set_view(ViewMode::Front);
    if (pressed(GLFW_KEY_KP_3)) set_view(ViewMode::Side);
    if (pressed(GLFW_KEY_KP_5)) set_view(ViewMode::Perspective);
    if (pressed(GLFW_KEY_KP_0)) toggle_quad();
}

// --gizmo MODE[,local]: the gizmo as a screenshot or a test wants it.
Result<void> LevelViewport::set_gizmo_option(const std::string& option) {
    std::string mode = option;
    if (mode.ends_with(",local")) {
        gizmo_.space = RotationSpace::Local;
        mode.resize(mode.size() - 6);
    }
    if (mode == "move")
        gizmo_.mode = GizmoMode::Move;
    else if (mode == "rotate")
        gizmo_.mode = GizmoMode::Rotate;
    else if (mode == "scale")
        gizmo_.mode = GizmoMode::Scale;
    else
        return Error("--gizmo '" + option + "': expected move, rotate or scale", {},
                     "add ,local for the entity's own rotation axes, e.g. --gizmo rotate,local");
    return ok();
}

void LevelViewport::view_menu() {
    if (ImGui::MenuItem("Perspective", "Num 5")) set_view(ViewMode::Perspective);
    if (ImGui::MenuItem("Top", "Num 7")) set_view(ViewMode::Top);
    if (ImGui::MenuItem("Front", "Num 1")) set_view(ViewMode::Front);
    if (ImGui::MenuItem("Side", "Num 3")) set_view(ViewMode::Side);
    if (ImGui::MenuItem("4-up view", "Num 0", quad_.on)) toggle_quad();
    if (ImGui::MenuItem("Focus Selection", "F")) focus_selection();
    ImGui::Separator();
    ImGui::MenuItem("Grid", nullptr, &overlays_.grid);
    ImGui::MenuItem("Collision bounds", nullptr, &overlays_.collision);
    ImGui::MenuItem("Structure outlines (axis views)", nullptr, &overlays_.outlines);
    ImGui::MenuItem("Light ranges", nullptr, &overlays_.lights);
    ImGui::MenuItem("Robot eye / shooting radii", nullptr, &overlays_.robots);
    ImGui::MenuItem("Player start", nullptr, &overlays_.player_start);
    ImGui::MenuItem("All patrol routes", nullptr, &overlays_.patrols);
    ImGui::MenuItem("All sound radii", nullptr, &overlays_.sound_radii);
    ImGui::MenuItem("Navigation mesh", nullptr, &overlays_.navmesh);
    ImGui::MenuItem("Ceilings", nullptr, &overlays_.ceilings);
    ImGui::MenuItem("Section at the selection (front, side)", nullptr, &overlays_.section);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "In the front and side views, hide what stands between the camera and the selection");
    ImGui::MenuItem("Show links", nullptr, &overlays_.links);
}

} // namespace ks::editor::ui
