#pragma once
// Level logic: the links of an entity, an objective or the level (LinkOwner), the objectives, names for
// link targets; each edit one undoable step (the rules in logic_edit.h).
// Tests: tests/editor/test_edit_logic.cpp.
#include "model/editor.h"
#include "model/logic_edit.h"

#include <string>
#include <vector>

namespace ks::editor {

// Link and objective indices count from 0. A link's event must be one its owner emits, its action a
// known one and its delay in 0 .. 3600 s; its target may name nothing yet (validation reports it).
const std::vector<level::Link>* links_of(const Editor& editor,
                                         const LinkOwner& owner);               // nullptr: no such owner
Result<int> link_add(Editor& editor, const LinkOwner& owner, level::Link link); // returns the new index
Result<void> link_set(Editor& editor, const LinkOwner& owner, int index, level::Link link,
                      std::string merge_key = {});
Result<void> link_remove(Editor& editor, const LinkOwner& owner, int index);
Result<void> objective_add(Editor& editor,
                           level::Objective objective); // appended; id must be new & non-empty
// Renaming the id re-targets the links that named it (complete links), in the same step.
Result<void> objective_set(Editor& editor, int index, level::Objective objective, std::string merge_key = {});
Result<void> objective_remove(Editor& editor, int index);
Result<void> objective_move(Editor& editor, int from, int to);
// The objective every version-1 level had: "shutdown", completed by using any control panel (each panel
// gets the on_use -> complete link); one undoable step. Fails when the level has no control panel.
Result<void> add_shutdown_objective(Editor& editor);
// Name an entity so links can target it: a unique name from its type ("door_2") if it has none (or from
// its name if another entity shares it); returns it. No step when it already has a unique name.
Result<std::string> ensure_link_name(Editor& editor, int entity_id);

} // namespace ks::editor
