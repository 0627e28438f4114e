// Preview in context: the level robot selected in the viewport plays any of the dojo's clips where it
// stands, lit by the level. The dojo panel's player poses it (the clip, the playhead and Play/Pause are the
// dojo tab's own), and the level scene draws that robot in the pose instead of its rest pose.
#include "ui/clip_preview.h"
#include "ui/dojo_panel.h"

#include <imgui.h>
#include <nlohmann/json.hpp>

#include <cstdio>

namespace ks::editor::ui {

void ClipPreview::status(nlohmann::json& s) const {
    s["clip_preview"] = {{"on", on_},
                         {"robot", posed_robot_},
                         {"toggle", nlohmann::json::array({toggle_centre_.x, toggle_centre_.y})}};
}

int ClipPreview::robot(const Editor& editor) {
    const auto& selection = editor.doc().selection;
    if (selection.empty()) return 0;
    const level::Entity* e = editor.level().find(selection.front());
    return e && e->type() == level::EntityType::Robot ? e->id : 0;
}

void ClipPreview::pose(const Editor& editor, DojoPanel& dojo, render::LevelScene& scene, double dt) {
    const int shown_robot = on_ ? robot(editor) : 0;
    if (posed_robot_ != shown_robot && posed_robot_ != 0) scene.set_pose(posed_robot_, nullptr);
    posed_robot_ = shown_robot;
    if (shown_robot == 0) return;
    dojo.ensure_loaded();
    dojo.tick(dt);
    scene.set_pose(shown_robot, &dojo.pose());
}

void ClipPreview::draw(const Editor& editor, DojoPanel& dojo, Vec2 origin, Vec2 size) {
    const int selected_robot = robot(editor);
    toggle_centre_ = Vec2(0.0f);
    if (selected_robot == 0) return;
    const level::Entity* e = editor.level().find(selected_robot);
    const float height = ImGui::GetFrameHeight() + ImGui::GetStyle().WindowPadding.y * 2.0f;
    ImGui::SetCursorScreenPos(ImVec2(origin.x + 6, origin.y + size.y - 32 - height));
    ImGui::PushStyleColor(ImGuiCol_ChildBg, IM_COL32(15, 17, 22, 215));
    ImGui::PushStyleVar(ImGuiStyleVar_ChildRounding, 4.0f);
    ImGui::BeginChild("clip preview", ImVec2(std::min(size.x - 12, 720.0f), height), false,
                      ImGuiWindowFlags_AlwaysUseWindowPadding | ImGuiWindowFlags_NoScrollbar);
    char label[96];
    std::snprintf(label, sizeof(label), "Preview clip on %s",
                  e->name.empty() ? "the robot" : e->name.c_str());
    ImGui::Checkbox(label, &on_);
    toggle_centre_ = Vec2((ImGui::GetItemRectMin().x + ImGui::GetItemRectMax().x) * 0.5f,
                          (ImGui::GetItemRectMin().y + ImGui::GetItemRectMax().y) * 0.5f);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Plays the dojo's clip on this robot where it stands, in the level's light");
    const auto& clips = dojo.clips();
    if (on_ && !clips.empty()) {
        const int shown = dojo.clip();
        ImGui::SameLine();
        ImGui::SetNextItemWidth(150);
        if (ImGui::BeginCombo("##preview clip", clips[static_cast<size_t>(shown)].name.c_str())) {
            for (int i = 0; i < static_cast<int>(clips.size()); ++i)
                if (ImGui::Selectable(clips[static_cast<size_t>(i)].name.c_str(), i == shown))
                    dojo.show_clip(i);
            ImGui::EndCombo();
        }
        ImGui::SameLine();
        if (ImGui::Button(dojo.playing() ? "Pause" : "Play")) dojo.set_playing(!dojo.playing());
        ImGui::SameLine();
        if (ImGui::Button("Restart")) dojo.show_clip(shown);
        ImGui::SameLine();
        ImGui::TextDisabled("%.2f s", dojo.time());
    }
    ImGui::EndChild();
    ImGui::PopStyleVar();
    ImGui::PopStyleColor();
}

} // namespace ks::editor::ui
