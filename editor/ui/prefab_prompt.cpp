// Edit > Save selection as prefab...: one step (edit_prefabs.h, save_prefab) once the name is right.
#include "ui/prefab_prompt.h"
#include "model/edit_prefabs.h"
#include "model/prefab.h"

#include <imgui.h>
#include <nlohmann/json.hpp>

namespace ks::editor::ui {

void PrefabPrompt::open(const Editor& editor) {
    if (editor.doc().selection.empty()) return;
    ask_ = true;
    error_.clear();
    name_[0] = title_[0] = '\0';
}

void PrefabPrompt::draw(const PanelContext& ctx) {
    if (ask_) {
        ImGui::OpenPopup("Save selection as prefab");
        ask_ = false;
    }
    ImGui::SetNextWindowSize(ImVec2(440, 0), ImGuiCond_Appearing);
    open_ = false;
    if (!ImGui::BeginPopupModal("Save selection as prefab", nullptr, ImGuiWindowFlags_AlwaysAutoResize))
        return;
    open_ = true;
    ImGui::TextWrapped("%zu entities become prefabs/NAME.json and a linked instance of it.",
                       ctx.editor.doc().selection.size());
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(300);
    if (ImGui::InputTextWithHint("name", "a-z 0-9 _ -", name_, sizeof(name_))) error_.clear();
    ctx.spots.here("prefab_prompt.name");
    ImGui::SetNextItemWidth(300);
    ImGui::InputTextWithHint("title", "shown in the Prefabs tab", title_, sizeof(title_));
    ctx.spots.here("prefab_prompt.title");
    const std::string problem = prefab_name_problem(name_);
    const bool exists = ctx.editor.prefabs().find(name_) != nullptr;
    if (name_[0] && !problem.empty())
        ImGui::TextColored(ImVec4(1, 0.45f, 0.4f, 1), "%s", problem.c_str());
    else if (exists)
        ImGui::TextColored(ImVec4(1, 0.8f, 0.3f, 1), "A prefab named %s exists: Replace rewrites it.", name_);
    if (!error_.empty()) ImGui::TextColored(ImVec4(1, 0.45f, 0.4f, 1), "%s", error_.c_str());
    auto save = [&](bool replace) {
        auto saved = save_prefab(ctx.editor, name_, title_, replace);
        if (!saved) {
            error_ = saved.error().str();
            return;
        }
        ctx.log.line("saved prefab " + saved->string());
        ImGui::CloseCurrentPopup();
    };
    ImGui::BeginDisabled(!problem.empty() || !name_[0]);
    if (ImGui::Button(exists ? "Replace" : "Save", ImVec2(100, 0))) save(exists);
    ctx.spots.here("prefab_prompt.save");
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("Cancel", ImVec2(100, 0))) ImGui::CloseCurrentPopup();
    ctx.spots.here("prefab_prompt.cancel");
    ImGui::EndPopup();
}

void PrefabPrompt::status(const Editor& editor, nlohmann::json& s) const {
    s["prefab_prompt"] = {{"open", open_},
                          {"name", std::string(name_)},
                          {"problem", name_[0] ? prefab_name_problem(name_) : std::string()},
                          {"exists", editor.prefabs().find(name_) != nullptr},
                          {"error", error_}};
}

} // namespace ks::editor::ui
