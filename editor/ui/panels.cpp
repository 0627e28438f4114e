// The left column, arranged: the entity palette (place_palette.h) over the Outliner and Layers tabs
// (outliner.h) and the Prefabs tab (prefab_palette.h); a click in the palette or the Prefabs tab arms the
// viewport's place tool (place_tool.h).
#include "ui/editor_app.h"
#include "ui/panel_style.h"

#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>

namespace ks::editor::ui {

void EditorApp::outliner_panel(float x, float y, float w, float h) {
    place_panel(x, y, w, h);
    ImGui::Begin("Outliner", nullptr, kPanelFlags);
    const PanelContext ctx = context();
    if (!dojo_tab_) {
        // The palette takes at most 40 % of the column and scrolls past that, so the tab bar under it stays
        // on screen in a small window; it is measured each frame for the next.
        const float most =
            std::max(ImGui::GetFrameHeightWithSpacing() * 2.0f, ImGui::GetContentRegionAvail().y * 0.4f);
        ImGui::BeginChild("palette", ImVec2(0, std::min(palette_height_, most)));
        PlaceTool& place = viewport_.place_tool();
        const auto type = palette_.draw(place.type());
        palette_height_ = ImGui::GetCursorPosY();
        ImGui::EndChild();
        if (type) {
            logic_.end_pick(); // placing takes the viewport's clicks
            viewport_.disarm_tools();
            place.arm(*type);
        }
        ImGui::Separator();
    }
    outliner_.refresh(editor_); // cheap unless the level changed: the tree, issue badges, layer counts
    if (!ImGui::BeginTabBar("left_tabs")) {
        ImGui::End();
        return;
    }
    const bool outliner = ImGui::BeginTabItem("Outliner");
    spots_.here("tab.outliner");
    if (outliner) {
        shown_left_tab_ = LeftTab::Outliner;
        outliner_.outliner_tab(ctx);
        ImGui::EndTabItem();
    }
    const bool layers = ImGui::BeginTabItem(
        "Layers", nullptr, start_tab_ == LeftTab::Layers ? ImGuiTabItemFlags_SetSelected : 0);
    spots_.here("tab.layers");
    if (layers) {
        shown_left_tab_ = LeftTab::Layers;
        outliner_.layers_tab(ctx);
        ImGui::EndTabItem();
    }
    const bool prefabs = ImGui::BeginTabItem(
        "Prefabs", nullptr, start_tab_ == LeftTab::Prefabs ? ImGuiTabItemFlags_SetSelected : 0);
    spots_.here("tab.prefabs");
    if (prefabs) {
        shown_left_tab_ = LeftTab::Prefabs;
        if (const auto name = prefabs_.draw(ctx, viewport_.place_tool().prefab())) {
            logic_.end_pick(); // placing takes the viewport's clicks
            viewport_.disarm_tools();
            viewport_.place_tool().arm_prefab(*name);
        }
        ImGui::EndTabItem();
    }
    const bool models = ImGui::BeginTabItem("Models");
    spots_.here("tab.models"); // where to click to open it, shown or not
    if (models) {
        if (const auto name = models_.draw(ctx, viewport_.place_tool().model())) {
            logic_.end_pick(); // placing takes the viewport's clicks
            viewport_.disarm_tools();
            viewport_.place_tool().arm_model(*name);
        }
        ImGui::EndTabItem();
    }
    start_tab_ = LeftTab::Outliner;
    ImGui::EndTabBar();
    ImGui::End();
}

} // namespace ks::editor::ui
