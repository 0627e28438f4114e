#pragma once
// Prefabs in the level: saving a selection as a prefab, placing linked instances, applying an instance back
// to its prefab, following prefab files that changed, reverting overrides and unlinking; each one undoable
// step (the prefab file a save or an apply writes stays written). The file format is prefab.h.
// Tests: tests/editor/test_edit_prefabs.cpp.
#include "model/editor.h"

#include <filesystem>
#include <string>

namespace ks::editor {

// The selection as prefabs/NAME.json (origin: the selection's centre at floor level, on the grid); the
// selection becomes a linked instance of it (one step). Refuses a name in use unless `replace`.
Result<std::filesystem::path> save_prefab(Editor& editor, const std::string& name, std::string title = {},
                                          bool replace = false);
// A linked instance with its origin at `position` (snapped) turned by `yaw`; selects it and returns
// its group id. New names are made unique; links inside the prefab follow them.
Result<int> place_prefab(Editor& editor, const std::string& name, Vec3 position, float yaw_degrees = 0.0f);
// The instance's members, as they are now, become the prefab (its file is rewritten); every instance
// in the level follows (one step); the instance's overrides are cleared.
Result<std::filesystem::path> apply_instance_to_prefab(Editor& editor, int group_id);
// Brings every instance in line with its prefab file (after a prefab changed on disk; open does it).
// One step named after the prefabs when anything changed; returns how many entities changed.
Result<int> update_prefab_instances(Editor& editor);
// Drops the instance's overrides (all, or one field of one member): they follow the prefab again.
Result<void> revert_prefab_overrides(Editor& editor, int group_id, int entity_id = 0, std::string field = {});
// The instance becomes a plain group: it no longer follows its prefab.
Result<void> unlink_prefab(Editor& editor, int group_id);
// The instance (group id) entity `entity_id` belongs to, or 0.
int prefab_instance_of(const Editor& editor, int entity_id);

} // namespace ks::editor
