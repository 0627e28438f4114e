#pragma once
// Layers, and hiding and locking one entity: each edit one undoable step on the level's editor section
// (saved in the file, read past by the game); the document's hidden and locked sets follow
// (groups.h refresh_view_sets). Tests: tests/editor/test_edit_layers.cpp.
#include "model/editor.h"

#include <string>

namespace ks::editor {

// Layer 0 is "Default" and holds every entity no other layer lists; adding the first layer creates it.
Result<int> layer_add(Editor& editor, std::string name);
Result<void> layer_rename(Editor& editor, int index, std::string name);
Result<void> layer_remove(Editor& editor, int index); // not the Default layer; its entities go to Default
Result<void> layer_set_visible(Editor& editor, int index, bool visible);
Result<void> layer_set_locked(Editor& editor, int index, bool locked);
Result<void> layer_set_active(Editor& editor, int index); // where new entities go
Result<void> move_selection_to_layer(Editor& editor, int index);

// One entity hidden or locked on its own. Locking drops the entity from the selection. Unknown ids are an
// error.
Result<void> set_hidden(Editor& editor, int id, bool hidden);
Result<void> set_locked(Editor& editor, int id, bool locked);

} // namespace ks::editor
