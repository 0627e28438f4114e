#include "ui/about_box.h"

#include "view/about_text.h"

#include <imgui.h>
#include <nlohmann/json.hpp>

namespace ks::editor::ui {

namespace {
constexpr const char* kTitle = "About Killswitch Editor";
}

void AboutBox::menu(UiSpots& spots) {
    const bool shown = ImGui::BeginMenu("Help");
    spots.here("menu.help");
    if (!shown) return;
    if (ImGui::MenuItem("About Killswitch Editor")) requested_ = true;
    spots.here("menu.about");
    ImGui::EndMenu();
}

void AboutBox::draw(UiSpots& spots) {
    if (requested_) ImGui::OpenPopup(kTitle);
    requested_ = false;
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    open_ = ImGui::BeginPopupModal(kTitle, nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    if (!open_) return;
    const auto lines = about_lines();
    for (size_t i = 0; i < lines.size(); ++i) {
        if (i == 0)
            ImGui::TextColored(ImVec4(0.16f, 0.67f, 0.89f, 1.0f), "%s", lines[i].c_str());
        else
            ImGui::TextUnformatted(lines[i].c_str());
        if (i == 0 || i == 2) ImGui::Spacing();
    }
    ImGui::Spacing();
    if (ImGui::Button("Close") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)))
        ImGui::CloseCurrentPopup();
    spots.here("about.close");
    ImGui::EndPopup();
}

nlohmann::json AboutBox::status() const {
    return {{"open", open_}, {"lines", about_lines()}};
}

} // namespace ks::editor::ui
