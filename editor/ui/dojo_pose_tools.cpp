// Posing in the dojo's preview (dojo_pose_tools.h).
#include "ui/dojo_pose_tools.h"

#include "ui/gizmo_draw.h"

#include <imgui.h>

#include <algorithm>
#include <iterator>

namespace ks::editor::ui {

namespace {
const ImU32 kBone = IM_COL32(210, 215, 230, 200), kJoint = IM_COL32(235, 240, 250, 255);
const ImU32 kSelected = IM_COL32(255, 200, 40, 255), kHovered = IM_COL32(120, 220, 255, 255);
} // namespace

DojoPoseScene DojoPoseTools::scene(const DojoContext& dojo) {
    return {dojo.edits, dojo.playback, edits_, dojo.clip_index(), dojo.clip_time()};
}

int DojoPoseTools::selected(const DojoContext& dojo) const {
    return dojo.selection.node.empty() ? -1 : dojo.playback.rig().find(dojo.selection.node);
}

void DojoPoseTools::sync(const DojoContext& dojo) {
    edits_.sync(dojo.playback.clip(), dojo.playback.time(), dojo.edits.revision());
}

void DojoPoseTools::key(const DojoContext& dojo) {
    if (dojo.playback.transition() || !dojo.shown_def()) return;
    DojoPoseScene s = scene(dojo);
    poser_.key(s, selected(dojo));
}

void DojoPoseTools::draw_rig(const DojoContext& dojo, const ViewCamera& view, Vec2 corner, int hovered_node) {
    const anim::Rig& rig = dojo.playback.rig();
    const std::vector<Mat4> world = pose_world(rig, shown_pose(dojo.playback, edits_));
    ImDrawList* draw = ImGui::GetWindowDrawList();
    joints_.assign(static_cast<std::size_t>(rig.size()), Vec2(0.0f));
    std::vector<bool> visible(joints_.size(), false);
    for (int i = 0; i < rig.size(); ++i)
        visible[static_cast<std::size_t>(i)] =
            view.project(joint_position(world, i), joints_[static_cast<std::size_t>(i)]);
    auto at = [&](int i) {
        const Vec2 p = joints_[static_cast<std::size_t>(i)] + corner;
        return ImVec2(p.x, p.y);
    };
    const int chosen = selected(dojo);
    for (int i = 0; i < rig.size(); ++i) {
        const int parent = rig.node(i).parent;
        if (parent < 0 || !visible[static_cast<std::size_t>(i)] || !visible[static_cast<std::size_t>(parent)])
            continue;
        draw->AddLine(at(parent), at(i), parent == chosen ? kSelected : kBone,
                      parent == chosen ? 3.0f : 2.0f);
    }
    for (int i = 0; i < rig.size(); ++i) {
        if (!visible[static_cast<std::size_t>(i)]) continue;
        const ImU32 colour = i == chosen ? kSelected : i == hovered_node ? kHovered : kJoint;
        draw->AddCircleFilled(at(i), i == chosen ? 6.0f : 4.5f, colour);
        draw->AddCircle(at(i), i == chosen ? 6.0f : 4.5f, IM_COL32(20, 20, 30, 255), 0, 1.5f);
    }
    for (Vec2& joint : joints_) joint += corner; // the status file's points are window pixels
}

bool DojoPoseTools::overlay(const DojoContext& dojo, const ViewCamera& view, Vec2 corner, bool hovered) {
    rings_ = {};
    if (dojo.playback.transition() || !dojo.playback.player() || !dojo.shown_def()) {
        joints_.clear();
        return false;
    }
    const ImGuiIO& io = ImGui::GetIO();
    const Vec2 mouse = Vec2(io.MousePos.x, io.MousePos.y) - corner;
    DojoPoseScene s = scene(dojo);
    if (poser_.dragging()) {
        if (ImGui::IsMouseDown(ImGuiMouseButton_Left))
            poser_.drag(s, view, mouse, io.KeyCtrl);
        else
            poser_.end(s);
    }
    const anim::Pose pose = shown_pose(dojo.playback, edits_);
    const anim::Rig& rig = dojo.playback.rig();
    const int chosen = selected(dojo);
    const GizmoFrame frame = poser_.frame(rig, pose, chosen);
    const Handle ring = hovered && chosen >= 0 ? poser_.hit(view, frame, mouse) : Handle::None;
    const int under = hovered && ring == Handle::None ? poser_.pick(view, rig, pose, mouse) : -1;
    draw_rig(dojo, view, corner, under);
    if (chosen >= 0 && !poser_.settings.ik) {
        Gizmo shape_only;
        shape_only.mode = GizmoMode::Rotate;
        draw_gizmo(ImGui::GetWindowDrawList(), shape_only, view, corner, frame, ring);
        const GizmoShape shape = gizmo_shape(view, frame);
        for (int k = 0; k < 3; ++k) {
            if (!shape.ring_visible[k]) continue;
            float far = -1.0f; // the ring's point farthest from the centre: clear of the other rings
            for (const Vec2& p : shape.rings[k])
                if (const float d = glm::length(p - shape.centre); d > far) far = d, rings_[k] = p + corner;
        }
    }
    if (under >= 0) ImGui::SetTooltip("%s", rig.node(under).name.c_str());
    if (!poser_.readout().empty())
        ImGui::GetWindowDrawList()->AddText(ImVec2(corner.x + 8, corner.y + view.viewport().y - 44),
                                            IM_COL32(255, 230, 120, 255), poser_.readout().c_str());
    if (poser_.dragging()) return true;
    if (!hovered || !ImGui::IsMouseClicked(ImGuiMouseButton_Left)) return false;
    if (ring != Handle::None) {
        dojo.playback.set_playing(false);
        poser_.begin_turn(s, view, chosen, ring, mouse);
        return true;
    }
    if (under < 0) return false;
    if (poser_.settings.ik && under == chosen) {
        dojo.playback.set_playing(false);
        return poser_.begin_ik(s, view, under, mouse);
    }
    dojo.selection.node = rig.node(under).name;
    return true;
}

void DojoPoseTools::bar(const DojoContext& dojo) {
    DojoPoseSettings& set = poser_.settings;
    // A dark strip under the bar: its labels stay readable over the bright floor.
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(at.x - 4, at.y - 2),
                                              ImVec2(at.x + 440, at.y + ImGui::GetFrameHeight() + 2),
                                              IM_COL32(16, 18, 24, 200), 4.0f);
    const bool key_clicked = ImGui::SmallButton("Key");
    dojo.mark(DojoSpot::KeyPose);
    if (key_clicked) key(dojo);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("K: key the turned nodes (or the selected one) at the playhead; between two keys "
                          "this adds a key there");
    ImGui::SameLine();
    ImGui::Checkbox("Auto-key", &set.auto_key);
    dojo.mark(DojoSpot::AutoKey);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Every drag writes its keys at the playhead (one undo step)");
    ImGui::SameLine();
    bool local = set.space == RotationSpace::Local;
    if (ImGui::Checkbox("Local", &local)) set.space = local ? RotationSpace::Local : RotationSpace::World;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Rings on the node's own axes (off: the world's)");
    ImGui::SameLine();
    ImGui::Checkbox("Snap", &set.snap);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Turns in whole steps; Ctrl while dragging does the opposite");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(52);
    constexpr float kSteps[] = {5.0f, 10.0f, 15.0f, 45.0f};
    int step = static_cast<int>(std::find(std::begin(kSteps), std::end(kSteps), set.snap_degrees) -
                                std::begin(kSteps));
    if (ImGui::Combo("##step", &step,
                     "5 deg\0"
                     "10 deg\0"
                     "15 deg\0"
                     "45 deg\0") &&
        step >= 0 && step < 4)
        set.snap_degrees = kSteps[step];
    ImGui::SameLine();
    ImGui::Checkbox("IK", &set.ik);
    dojo.mark(DojoSpot::Ik);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Drag the selected joint (a hand) and its parent and grandparent follow; the elbow "
                          "keeps its side");
}

} // namespace ks::editor::ui
