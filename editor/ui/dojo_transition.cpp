// The dojo's transition tester (dojo_timeline.h). The blend grid's cells open it.
#include "ui/dojo_timeline.h"

#include <imgui.h>

namespace ks::editor::ui {

void dojo_transition_tester(const DojoContext& dojo) {
    DojoPlayback& playback = dojo.playback;
    const anim::ClipSet& clips = playback.clips();
    if (clips.clips.empty()) return;
    const DojoPlayPlan& plan = playback.plan();
    bool on = plan.transition;
    int from = plan.from, to = plan.to;
    float switch_at = static_cast<float>(plan.switch_at), blend = plan.blend;
    const bool toggled = ImGui::Checkbox("Transition test", &on);
    dojo.named.here("transition_test");
    if (toggled) {
        playback.set_transition(on, from, to, plan.switch_at, blend);
        playback.restart_at(0.0);
    }
    auto clip_combo = [&](const char* label, int& index) {
        bool changed = false;
        ImGui::SetNextItemWidth(140);
        if (ImGui::BeginCombo(label, clips.clips[static_cast<size_t>(index)].name.c_str())) {
            for (int i = 0; i < static_cast<int>(clips.clips.size()); ++i)
                if (ImGui::Selectable(clips.clips[static_cast<size_t>(i)].name.c_str(), i == index))
                    index = i, changed = true;
            ImGui::EndCombo();
        }
        return changed;
    };
    bool changed = clip_combo("from", from);
    ImGui::SameLine();
    changed |= clip_combo("to", to);
    ImGui::SetNextItemWidth(140);
    const bool switch_moved = ImGui::DragFloat("switch at", &switch_at, 0.01f, 0.0f, 10.0f, "%.2f s");
    changed |= switch_moved;
    ImGui::SameLine();
    ImGui::SetNextItemWidth(140);
    changed |= ImGui::DragFloat("blend", &blend, 0.01f, 0.0f, 5.0f, "%.2f s");
    ImGui::SameLine();
    if (ImGui::SmallButton("file's blend")) blend = clips.blend_time(from, to), changed = true;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("The blend time the game uses for this pair (Blends tab)");
    if (!changed) return;
    // The switch time keeps its exact value unless its own widget moved it.
    playback.set_transition(on, from, to, switch_moved ? static_cast<double>(switch_at) : plan.switch_at,
                            blend);
    if (on) playback.restart_at(0.0);
}

} // namespace ks::editor::ui
