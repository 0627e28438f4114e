// Groups, layers and prefabs from the viewport, the keys and the Edit menu: Ctrl+G / Ctrl+Shift+G, a
// double click entering a group and Esc leaving it, the entered group's outline and hint, the "Save
// selection as prefab..." menu item (its prompt: prefab_prompt.h) and the "Move selection to layer" submenu.
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
