#pragma once
// Groups: Ctrl+G and Ctrl+Shift+G, entering and leaving a group, renaming; each edit one undoable step
// (entering is view state). The questions about groups (pick units, deep members) are in groups.h.
// Tests: tests/editor/test_edit_groups.cpp.
#include "model/editor.h"
#include "model/groups.h"

#include <string>
#include <vector>

namespace ks::editor {

// Ctrl+G: the selection becomes one group (inside the entered group, if any). A group that is partly
// selected joins whole. Returns the new group's id; its frame is the selection's centre at floor level.
Result<int> group_selection(Editor& editor, std::string name = {});
// Ctrl+Shift+G: the groups the selection picks are dissolved (a prefab instance loses its link); their
// members join the parent group.
Result<void> ungroup_selection(Editor& editor);
// Double-click: the group's members become pickable one by one (view state, not a step).
Result<void> enter_group(Editor& editor, int group_id);
void exit_group(Editor& editor); // one level up
Result<void> rename_group(Editor& editor, int group_id, std::string name);
// The groups the selection holds whole and that a click would pick (under the entered group).
std::vector<int> selected_groups(const Editor& editor);

} // namespace ks::editor
