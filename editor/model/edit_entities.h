#pragma once
// Entities and the level's own fields: placing, setting and reverting fields, renaming, duplicating,
// deleting, copy and paste, the level's settings, name and player start; each one undoable step.
// Tests: tests/editor/test_edit_entities.cpp.
#include "model/editor.h"
#include "model/field_access.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ks::editor {

// Snapped to the grid (origin) and rotation step; selects the new entity and returns its id.
Result<int> place(Editor& editor, level::EntityType type, Vec3 position, float yaw_degrees = 0.0f,
                  std::string name = {});
// On every selected entity that has the field (multi-selection edits common fields).
Result<void> set_field(Editor& editor, std::string_view name, const FieldValue& value,
                       std::string merge_key = {});
Result<void> set_field_text(Editor& editor, std::string_view name, std::string_view text);
Result<void> revert_field(Editor& editor, std::string_view name);
Result<void> rename(Editor& editor, int id, std::string name);
// Default offset: one grid step along x, so a copy sits beside its original, selected,
// and one coordinate (or one arrow key) moves it on.
Result<void> duplicate(Editor& editor, std::optional<Vec3> offset = std::nullopt);
Result<void> delete_selection(Editor& editor);
Result<void> delete_entities(Editor& editor, const std::vector<int>& ids);
std::string copy(Editor& editor);   // the selection as JSON text (also the clipboard)
Result<void> paste(Editor& editor); // from the clipboard
Result<void> paste_text(Editor& editor,
                        std::string_view text); // fresh ids; works with text from another level
Result<void> set_setting(Editor& editor, std::string_view name, const FieldValue& value,
                         std::string merge_key = {});
Result<void> set_setting_text(Editor& editor, std::string_view name, std::string_view text);
// Snapped to the grid; a drag of the inspector's fields passes a merge key (one step).
Result<void> set_player_start(Editor& editor, const level::PlayerStart& start, std::string merge_key = {});
Result<void> rename_level(Editor& editor, std::string name);

} // namespace ks::editor
