// File > Add to Campaign...: asks for the campaign file and the title the level's summary shows, then ships
// the saved level as the campaign's next level (model/campaign_add.h holds the rules and the refusals).
#include "core/paths.h"
#include "model/campaign_add.h"
#include "ui/file_prompts.h"

#include <imgui.h>

#include <cstdio>

namespace ks::editor::ui {

void FilePrompts::open_campaign_prompt() {
    ask_campaign_ = true;
    if (campaign_input_[0] == '\0')
        std::snprintf(campaign_input_, sizeof(campaign_input_), "%s",
                      default_campaign_file().string().c_str());
    std::snprintf(campaign_title_, sizeof(campaign_title_), "%s", editor_.level().name.c_str());
}

void FilePrompts::campaign_prompt() {
    if (ask_campaign_) ImGui::OpenPopup("Add to campaign");
    ask_campaign_ = false;
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal("Add to campaign", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    const bool saved = !editor_.file_path().empty() && !editor_.has_unsaved_changes();
    if (saved)
        ImGui::Text("Add %s as the campaign's next level.", editor_.file_path().filename().string().c_str());
    else
        ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.3f, 1.0f),
                           "Save the level first: a campaign lists saved files.");
    ImGui::Text("Campaign file (JSON; a new one is started if it does not exist):");
    ImGui::SetNextItemWidth(520);
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::InputText("##campaign", campaign_input_, sizeof(campaign_input_));
    ImGui::Text("Title on the level's summary screen:");
    ImGui::SetNextItemWidth(520);
    const bool entered = ImGui::InputText("##title", campaign_title_, sizeof(campaign_title_),
                                          ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::BeginDisabled(!saved);
    if (entered || ImGui::Button("Add")) {
        auto added = add_to_campaign(editor_, paths::resolve_user_path(campaign_input_), campaign_title_);
        if (!added)
            log_line(added.error().str(), true);
        else
            log_line("added " + added->file + " to " + added->campaign_file.string() + " as level " +
                     std::to_string(added->position) + " (\"" + added->title + "\")" +
                     (added->created ? ", a new campaign" : ""));
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

} // namespace ks::editor::ui
