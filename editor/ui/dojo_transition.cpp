// The dojo's transition tester: play `from`, switch to `to` at a time with a blend time (the file's, or
// one being tried), looping, so the hand-over can be watched and scrubbed. The blend grid's cells open it.
#include "ui/dojo_panel.h"

#include <imgui.h>

namespace ks::editor::ui {

void DojoPanel::test_transition(int from, int to) {
    const int count = static_cast<int>(clips_.clips.size());
    if (from < 0 || to < 0 || from >= count || to >= count) return;
    from_clip_ = from;
    to_clip_ = to;
    blend_time_ = clips_.blend_time(from, to);
    transition_mode_ = true;
    playing_ = true;
    restart_at(0.0);
}

void DojoPanel::transition_tester() {
    if (clips_.clips.empty()) return;
    ImGui::Checkbox("Transition test", &transition_mode_);
    if (ImGui::IsItemEdited()) restart_at(0.0);
    auto clip_combo = [&](const char* label, int& index) {
        bool changed = false;
        ImGui::SetNextItemWidth(140);
        if (ImGui::BeginCombo(label, clips_.clips[static_cast<size_t>(index)].name.c_str())) {
            for (int i = 0; i < static_cast<int>(clips_.clips.size()); ++i)
                if (ImGui::Selectable(clips_.clips[static_cast<size_t>(i)].name.c_str(), i == index))
                    index = i, changed = true;
            ImGui::EndCombo();
        }
        return changed;
    };
    bool changed = clip_combo("from", from_clip_);
    ImGui::SameLine();
    changed |= clip_combo("to", to_clip_);
    ImGui::SetNextItemWidth(140);
    changed |= ImGui::DragFloat("switch at", &switch_time_, 0.01f, 0.0f, 10.0f, "%.2f s");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(140);
    changed |= ImGui::DragFloat("blend", &blend_time_, 0.01f, 0.0f, 5.0f, "%.2f s");
    ImGui::SameLine();
    if (ImGui::SmallButton("file's blend"))
        blend_time_ = clips_.blend_time(from_clip_, to_clip_), changed = true;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("The blend time the game uses for this pair (Blends tab)");
    if (changed && transition_mode_) restart_at(0.0);
}

} // namespace ks::editor::ui
