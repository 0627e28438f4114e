#include "ui/sound_widgets.h"

#include "model/sound_names.h"
#include "ui/ui_spots.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace ks::editor::ui {

bool sound_name_widget(const char* id, std::string& name, std::vector<std::string>& known, UiSpots* spots) {
    ImGui::PushID(id);
    const float arrow = ImGui::GetFrameHeight();
    const float spacing = ImGui::GetStyle().ItemInnerSpacing.x;
    ImGui::SetNextItemWidth(std::max(ImGui::CalcItemWidth() - arrow - spacing, 40.0f));
    char buffer[128];
    std::snprintf(buffer, sizeof(buffer), "%s", name.c_str());
    bool changed = ImGui::InputText("##text", buffer, sizeof(buffer), ImGuiInputTextFlags_EnterReturnsTrue);
    if (changed) name = buffer;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Type a name and press Enter, or pick one from the list");
    ImGui::SameLine(0, spacing);
    if (ImGui::BeginCombo("##list", nullptr, ImGuiComboFlags_NoPreview | ImGuiComboFlags_PopupAlignLeft)) {
        if (ImGui::IsWindowAppearing()) known = shipped_sound_names();
        if (known.empty()) ImGui::TextDisabled("no .wav files in assets/sounds");
        for (const std::string& option : known) {
            if (ImGui::Selectable(option.c_str(), option == name)) name = option, changed = true;
            if (spots) spots->here("combo:" + option);
        }
        ImGui::EndCombo();
    } else if (spots) {
        spots->here("sound_list");
    }
    ImGui::PopID();
    return changed;
}

void audition_button(const SoundAudition& audition, const std::string& sound, float volume) {
    if (!audition || sound.empty()) return;
    if (ImGui::Button("Audition")) audition(sound, volume);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Play %s once at volume %.2f", sound.c_str(), volume);
}

} // namespace ks::editor::ui
