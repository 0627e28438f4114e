// The entity palette (place_palette.h).
#include "ui/place_palette.h"

#include "ui/panel_style.h"

#include <imgui.h>
#include <nlohmann/json.hpp>

namespace ks::editor::ui {

void PlacePalette::status(nlohmann::json& s) const {
    nlohmann::json palette = nlohmann::json::object();
    for (auto type : level::all_types()) {
        const ScreenRect& r = rect(type);
        const Vec2 centre = (r.min + r.max) * 0.5f;
        if (r.max.x > r.min.x) palette[std::string(level::type_name(type))] = {centre.x, centre.y};
    }
    s["palette"] = palette;
}

std::optional<level::EntityType> PlacePalette::draw(std::optional<level::EntityType> armed) {
    std::optional<level::EntityType> clicked;
    ImGui::TextDisabled("Place:");
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    bool first = true;
    for (auto type : level::all_types()) {
        const float w = ImGui::CalcTextSize(type_label(type)).x + ImGui::GetStyle().FramePadding.x * 2;
        if (!first) {
            ImGui::SameLine();
            if (ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + w > right) ImGui::NewLine();
        }
        first = false;
        const bool active = armed == type;
        if (active) ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.25f, 0.55f, 0.3f, 1));
        ImGui::PushStyleColor(ImGuiCol_Text, type_colour(type));
        if (ImGui::SmallButton(type_label(type))) clicked = type;
        ImGui::PopStyleColor(active ? 2 : 1);
        rects_[static_cast<size_t>(type)] = {Vec2(ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y),
                                             Vec2(ImGui::GetItemRectMax().x, ImGui::GetItemRectMax().y)};
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "Click, then click in the viewport to place a %s on the surface under the cursor "
                "(snapped to the grid). Shift+click places several.",
                type_label(type));
    }
    return clicked;
}

} // namespace ks::editor::ui
