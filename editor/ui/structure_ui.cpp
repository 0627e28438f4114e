// Groups, layers and prefabs from the keys and the Edit menu: Ctrl+G / Ctrl+Shift+G, Esc leaving a group,
// the "Save selection as prefab..." menu item (its prompt: prefab_prompt.h) and the "Move selection to
// layer" submenu. The viewport's double click enters a group (viewport_input.cpp) and shows the entered
// group's box and hint (viewport_lines.cpp, viewport.cpp).
// Every edit is an Editor call (edit_groups.h, edit_layers.h, edit_prefabs.h).
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
    if (ImGui::MenuItem("Save selection as prefab...", nullptr, false, any)) prefab_prompt_.open(editor_);
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

} // namespace ks::editor::ui
