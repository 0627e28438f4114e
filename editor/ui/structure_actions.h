#pragma once
// Group and prefab actions as the window's keys, menus and panels do them: each an Editor call whose
// outcome goes to the log (structure_actions.cpp).
#include "model/edit_selection.h"
#include "ui/editor_log.h"

#include <string>

namespace ks::editor::ui {

void group_selection(Editor& editor, EditorLog& log);   // Ctrl+G
void ungroup_selection(Editor& editor, EditorLog& log); // Ctrl+Shift+G
// Esc inside a group: up one level, the group just left selected as a whole.
void leave_group(Editor& editor, EditorLog& log);
// The group as a click would pick it: its parent is entered first (or every group left for a top-level
// one), so a nested group's row in the outliner selects that group and not its outermost ancestor.
void select_group(Editor& editor, EditorLog& log, int group_id, SelectMode mode = SelectMode::Replace);
// A double click on an entity in the viewport: enters the group it belongs to; true when one was entered.
bool double_click_enter(Editor& editor, EditorLog& log, int entity_id);
// Rewrites the instance's prefab file from it (every instance follows).
void apply_to_prefab(Editor& editor, EditorLog& log, int instance);
std::string group_label(const level::Group& group); // its name (or "group ID"), then [prefab]

} // namespace ks::editor::ui
