#pragma once
// Selecting (view state, not history steps): by id, by a predicate or a box, what a click picks in the
// viewport (a group whole, or inside an entered group its members), and the entity a validation issue names.
// Tests: tests/editor/test_edit_selection.cpp.
#include "geometry/aabb.h"
#include "model/editor.h"

#include <functional>
#include <vector>

namespace ks::editor {

enum class SelectMode { Replace, Add, Toggle, Remove };

// Unknown or locked ids are an error and leave the selection as it was.
Result<void> select(Editor& editor, const std::vector<int>& ids, SelectMode mode = SelectMode::Replace);
// Tools: every visible, unlocked entity the predicate accepts (screen-space box select passes one).
int select_where(Editor& editor, const std::function<bool(const level::Entity&)>& accept,
                 SelectMode mode = SelectMode::Replace);
int select_in_box(Editor& editor, const geometry::Aabb& box, SelectMode mode = SelectMode::Replace);
int select_all_of_type(Editor& editor, level::EntityType type, SelectMode mode = SelectMode::Replace);
int select_all(Editor& editor);
std::vector<const level::Entity*> selected_entities(const Editor& editor);
// What a click in the viewport selects (groups.h pick_unit): the entity's outermost group, or inside an
// entered group its child group or the entity itself. A click outside the entered group leaves it.
Result<void> select_picked(Editor& editor, int entity_id, SelectMode mode = SelectMode::Replace);
// Box select: every visible, unlocked entity the predicate accepts, each with what a click on it picks
// (its whole group); returns how many entities were accepted.
int select_picked_where(Editor& editor, const std::function<bool(const level::Entity&)>& accept,
                        SelectMode mode = SelectMode::Replace);
// The entity (or player start) a validation issue is about; nothing for a level-wide issue.
Result<void> select_issue(Editor& editor, const Issue& issue);

} // namespace ks::editor
