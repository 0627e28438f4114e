#pragma once
// Shared by the inspector's sections (inspector_sections.cpp, group_inspector.cpp); not used elsewhere.
#include "ui/inspector.h"

#include <memory>
#include <string>
#include <vector>

namespace ks::editor::ui {

// The prefab instance the primary selected entity belongs to, and the fields it keeps as its own there
// (looked up once a frame for the field table).
struct PrimaryOverrides {
    int instance = 0, entity = 0;
    const std::vector<std::string>* fields = nullptr;
};
PrimaryOverrides primary_overrides(const Editor& editor);
// After a field's name in the table: a mark when the primary keeps the field as its own in its prefab
// instance, and the name's context menu to revert it.
void override_marker(const PanelContext& ctx, const PrimaryOverrides& primary, const std::string& field);

// One whole group selected (its name, Enter, Ungroup), or a prefab instance's member; for a prefab instance
// its prefab, Apply to prefab, Revert all and Unlink (group_inspector.cpp).
std::unique_ptr<InspectorSection> make_group_section();
// The selected brush faces (face_inspector.cpp).
std::unique_ptr<InspectorSection> make_face_section();

} // namespace ks::editor::ui
