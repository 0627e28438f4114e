#pragma once
// What the editor's fixed panels share: their window flags and placement, and each entity type's label and
// colour (outliner rows, palette buttons, inspector titles, link targets).
#include "level/level.h"

#include <imgui.h>

#include <string>

namespace ks::editor::ui {

inline constexpr ImGuiWindowFlags kPanelFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                                ImGuiWindowFlags_NoCollapse |
                                                ImGuiWindowFlags_NoBringToFrontOnFocus;

// Text of an error (a clip that failed to load, a refused edit); warnings use kWarningColour.
inline const ImVec4 kErrorColour(1.0f, 0.4f, 0.35f, 1.0f);
inline const ImVec4 kWarningColour(1.0f, 0.8f, 0.3f, 1.0f);

inline void place_panel(float x, float y, float w, float h) {
    ImGui::SetNextWindowPos(ImVec2(x, y));
    ImGui::SetNextWindowSize(ImVec2(w, h));
}

inline const char* type_label(level::EntityType t) {
    static std::string names[static_cast<size_t>(level::EntityType::Count)];
    auto& n = names[static_cast<size_t>(t)];
    if (n.empty()) n = std::string(level::type_name(t));
    return n.c_str();
}

inline ImVec4 type_colour(level::EntityType t) {
    switch (t) {
    case level::EntityType::Wall:
    case level::EntityType::Floor:
    case level::EntityType::Stair:
        return ImVec4(0.7f, 0.74f, 0.8f, 1);
    case level::EntityType::Door:
        return ImVec4(0.55f, 0.8f, 1.0f, 1);
    case level::EntityType::FloorLight:
    case level::EntityType::TopLight:
        return ImVec4(1.0f, 0.88f, 0.45f, 1);
    case level::EntityType::Robot:
        return ImVec4(1.0f, 0.5f, 0.45f, 1);
    case level::EntityType::Pickup:
        return ImVec4(0.5f, 1.0f, 0.6f, 1);
    case level::EntityType::GasCylinder:
        return ImVec4(1.0f, 0.65f, 0.3f, 1);
    case level::EntityType::ControlPanel:
        return ImVec4(0.8f, 0.6f, 1.0f, 1);
    case level::EntityType::Sound:
        return ImVec4(1.0f, 0.5f, 0.85f, 1);
    case level::EntityType::Trigger:
        return ImVec4(0.45f, 1.0f, 0.6f, 1);
    case level::EntityType::Spawner:
        return ImVec4(1.0f, 0.55f, 0.4f, 1);
    case level::EntityType::Message:
        return ImVec4(0.65f, 0.85f, 1.0f, 1);
    default:
        return ImVec4(1, 1, 1, 1);
    }
}

// "Hall trigger  (trigger #13)", or "trigger #13" for an unnamed one.
inline std::string entity_title(const level::Entity& e) {
    const std::string type(level::type_name(e.type()));
    return e.name.empty() ? type + " #" + std::to_string(e.id)
                          : e.name + "  (" + type + " #" + std::to_string(e.id) + ")";
}

} // namespace ks::editor::ui
