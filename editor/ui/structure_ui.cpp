// Groups, layers and prefabs from the viewport, the keys and the Edit menu: Ctrl+G / Ctrl+Shift+G, a
// double click entering a group and Esc leaving it, the entered group's outline and hint, the "Save
// selection as prefab..." prompt and the "Move selection to layer" submenu. Every edit is an Editor call
// (edit_groups.h, edit_layers.h, edit_prefabs.h).
#include "model/edit_groups.h"
#include "model/edit_layers.h"
#include "model/edit_prefabs.h"
#include "ui/editor_app.h"
#include "ui/structure_actions.h"

#include <imgui.h>

#include <cstdio>

namespace ks::editor::ui {

void EditorApp::structure_menu_items() {
    const bool any = !editor_.doc().selection.empty();
    if (ImGui::MenuItem("Group", "Ctrl+G", false, any)) group_selection(editor_, log_);
    if (ImGui::MenuItem("Ungroup", "Ctrl+Shift+G", false, !selected_groups(editor_).empty()))
        ungroup_selection(editor_, log_);
    if (ImGui::MenuItem("Leave group", "Esc", false, editor_.open_group() != 0)) leave_group(editor_, log_);
    if (ImGui::MenuItem("Save selection as prefab...", nullptr, false, any)) open_prefab_prompt();
    spots_.here("menu.save_prefab");
    const auto& layers = editor_.level().editor.layers;
    if (ImGui::BeginMenu("Move selection to layer", any)) {
        if (layers.empty()) {
            if (ImGui::MenuItem("New layer")) {
                auto added = layer_add(editor_, "Layer 1");
                if (added)
                    report(move_selection_to_layer(editor_, *added), "move to layer");
                else
                    report(added.error(), "layer");
            }
        }
        for (size_t i = 0; i < layers.size(); ++i)
            if (ImGui::MenuItem(layers[i].name.c_str()))
                report(move_selection_to_layer(editor_, static_cast<int>(i)), "move to layer");
        ImGui::EndMenu();
    }
}

void EditorApp::open_prefab_prompt() {
    if (editor_.doc().selection.empty()) return;
    ask_prefab_ = true;
    prefab_error_.clear();
    prefab_name_[0] = prefab_title_[0] = '\0';
}

// Name (the file's stem, checked by the model as it is typed) and title; a name in use offers Replace.
void EditorApp::prefab_prompt() {
    if (ask_prefab_) {
        ImGui::OpenPopup("Save selection as prefab");
        ask_prefab_ = false;
    }
    ImGui::SetNextWindowSize(ImVec2(440, 0), ImGuiCond_Appearing);
    prefab_prompt_open_ = false;
    if (!ImGui::BeginPopupModal("Save selection as prefab", nullptr, ImGuiWindowFlags_AlwaysAutoResize))
        return;
    prefab_prompt_open_ = true;
    ImGui::TextWrapped("%zu entities become prefabs/NAME.json and a linked instance of it.",
                       editor_.doc().selection.size());
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::SetNextItemWidth(300);
    if (ImGui::InputTextWithHint("name", "a-z 0-9 _ -", prefab_name_, sizeof(prefab_name_)))
        prefab_error_.clear();
    spots_.here("prefab_prompt.name");
    ImGui::SetNextItemWidth(300);
    ImGui::InputTextWithHint("title", "shown in the Prefabs tab", prefab_title_, sizeof(prefab_title_));
    spots_.here("prefab_prompt.title");
    const std::string problem = prefab_name_problem(prefab_name_);
    const bool exists = editor_.prefabs().find(prefab_name_) != nullptr;
    if (prefab_name_[0] && !problem.empty())
        ImGui::TextColored(ImVec4(1, 0.45f, 0.4f, 1), "%s", problem.c_str());
    else if (exists)
        ImGui::TextColored(ImVec4(1, 0.8f, 0.3f, 1), "A prefab named %s exists: Replace rewrites it.",
                           prefab_name_);
    if (!prefab_error_.empty()) ImGui::TextColored(ImVec4(1, 0.45f, 0.4f, 1), "%s", prefab_error_.c_str());
    auto save = [&](bool replace) {
        auto saved = save_prefab(editor_, prefab_name_, prefab_title_, replace);
        if (!saved) {
            prefab_error_ = saved.error().str();
            return;
        }
        log_line("saved prefab " + saved->string());
        ImGui::CloseCurrentPopup();
    };
    ImGui::BeginDisabled(!problem.empty() || !prefab_name_[0]);
    if (ImGui::Button(exists ? "Replace" : "Save", ImVec2(100, 0))) save(exists);
    spots_.here("prefab_prompt.save");
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("Cancel", ImVec2(100, 0))) ImGui::CloseCurrentPopup();
    spots_.here("prefab_prompt.cancel");
    ImGui::EndPopup();
}

// The entered group's bounds, a thin box in every view, so the designer sees they are inside it.
void EditorApp::draw_open_group_box() {
    const int open = editor_.open_group();
    if (open == 0) return;
    std::vector<const level::Entity*> members;
    for (int id : group_entities_deep(editor_.level().editor, open))
        if (const level::Entity* e = editor_.level().find(id)) members.push_back(e);
    const geometry::Aabb box = selection_bounds(members);
    if (!box.valid()) return;
    const Vec3 lo = box.min - Vec3(0.25f), hi = box.max + Vec3(0.25f);
    Mat4 m(1.0f);
    m[3] = Vec4((lo + hi) * 0.5f, 1.0f);
    debug_.box(m, (hi - lo) * 0.5f, Vec4(0.55f, 0.75f, 1.0f, 0.9f));
}

// Over a view's top-left corner (under a 4-up pane's name and grid label), clipped to the view.
void EditorApp::open_group_hint(ImDrawList* draw, Vec2 origin, Vec2 size, bool pane) const {
    const int open = editor_.open_group();
    if (open == 0) return;
    const level::Group* group = editor_.level().editor.find_group(open);
    if (!group) return;
    // A 4-up pane is narrow: the group's name alone.
    const std::string text = pane ? "In " + group->name + " (Esc leaves)"
                                  : "Inside group " + group_label(*group) + "  -  Esc to leave";
    const float top = pane ? 46.0f : (placing_ || logic_.picking() ? 28.0f : 8.0f);
    const ImVec2 at(origin.x + 12, origin.y + top);
    const ImVec2 extent = ImGui::CalcTextSize(text.c_str());
    draw->PushClipRect(ImVec2(origin.x, origin.y), ImVec2(origin.x + size.x, origin.y + size.y), true);
    draw->AddRectFilled(ImVec2(at.x - 5, at.y - 3), ImVec2(at.x + extent.x + 5, at.y + extent.y + 3),
                        IM_COL32(20, 35, 60, 210), 3.0f);
    draw->AddText(at, IM_COL32(150, 195, 255, 255), text.c_str());
    draw->PopClipRect();
}

} // namespace ks::editor::ui
