// The player start as a viewport object: its figure (view/player_start_marker.h) drawn over the level, its
// row at the top of the outliner, and its own inspector section when it alone is selected. It is selected,
// moved and turned like an entity (kPlayerStartId in the selection); every change is an Editor edit.
#include "level/entity_shapes.h"
#include "ui/editor_app.h"
#include "ui/panel_style.h"

#include <imgui.h>

#include <cctype>
#include <cmath>

namespace ks::editor::ui {
namespace {
const Vec4 kStartColour(0.3f, 1.0f, 0.4f, 1.0f);
const Vec4 kStartSelected(1.0f, 0.62f, 0.1f, 1.0f); // the selection's orange
const ImVec4 kStartText(0.45f, 1.0f, 0.55f, 1.0f);

bool mentions(const char* haystack, const char* needle) {
    if (!*needle) return true;
    for (const char* h = haystack; *h; ++h) {
        size_t i = 0;
        while (needle[i] && h[i] &&
               std::tolower(static_cast<unsigned char>(h[i])) ==
                   std::tolower(static_cast<unsigned char>(needle[i])))
            ++i;
        if (!needle[i]) return true;
    }
    return false;
}
} // namespace

void EditorApp::draw_player_start() {
    if (!overlays_.player_start) return;
    marker_lines_.clear();
    player_start_figure(editor_.level().player_start, marker_lines_);
    const Vec4 colour = editor_.doc().player_start_selected() ? kStartSelected : kStartColour;
    for (const MarkerLine& line : marker_lines_) debug_.line(line.a, line.b, colour);
}

void EditorApp::player_start_row() {
    if (type_filter_ >= 0 || !mentions("player start", search_)) return;
    ImGui::PushStyleColor(ImGuiCol_Text, kStartText);
    const bool clicked = ImGui::Selectable("     Player start", editor_.doc().player_start_selected(),
                                           ImGuiSelectableFlags_AllowDoubleClick);
    ImGui::PopStyleColor();
    spots_.here("outliner.player_start");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Where the player starts: click to select, then move and turn it");
    if (!clicked) return;
    const ImGuiIO& io = ImGui::GetIO();
    const SelectMode mode = io.KeyCtrl    ? SelectMode::Toggle
                            : io.KeyShift ? SelectMode::Add
                                          : SelectMode::Replace;
    report(editor_.select({kPlayerStartId}, mode), "select");
    if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) focus_selection();
}

void EditorApp::player_start_section() {
    ImGui::TextColored(kStartText, "Player start");
    ImGui::Separator();
    level::PlayerStart start = editor_.level().player_start;
    ImGui::SetNextItemWidth(-90);
    if (ImGui::DragFloat3("position", &start.position.x, 0.1f, 0.0f, 0.0f, "%g"))
        report(editor_.set_player_start(start, "inspector:player_start"), "player start");
    if (ImGui::IsItemDeactivatedAfterEdit()) editor_.end_merging();
    ImGui::SetNextItemWidth(-90);
    if (ImGui::DragFloat("yaw", &start.yaw, 1.0f, -180.0f, 180.0f, "%.0f deg"))
        report(editor_.set_player_start(start, "inspector:player_start"), "player start");
    if (ImGui::IsItemDeactivatedAfterEdit()) editor_.end_merging();
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped(
        "The player's feet and facing (yaw 0 faces -z). In the viewport: W moves it, E turns it "
        "(the y ring), F focuses on it; F5 play-tests from it.");
    ImGui::PopStyleColor();
    if (ImGui::Button("Player start at camera")) {
        level::PlayerStart at = start;
        at.position = view_.camera.position - Vec3(0, level::kPlayerHeight, 0);
        at.yaw = std::remainder(degrees(view_.camera.yaw), 360.0f);
        report(editor_.set_player_start(at), "player start");
    }
    ImGui::SameLine();
    if (ImGui::Button("Focus")) focus_selection();
}

} // namespace ks::editor::ui
