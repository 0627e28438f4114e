#pragma once
// A robot's patrol route (the robot named by id); each edit one undoable step, the maths in patrol_edit.h.
// Tests: tests/editor/test_edit_patrols.cpp.
#include "model/editor.h"

#include <optional>
#include <string>
#include <string_view>

namespace ks::editor {

// Adds after index `after` (at the end when none; -1 puts it first).
Result<void> patrol_add(Editor& editor, int id, Vec3 point, std::optional<int> after = std::nullopt);
// A drag passes a merge key, so the whole drag is one step.
Result<void> patrol_move(Editor& editor, int id, int index, Vec3 point, std::string merge_key = {});
// Removing the last point removes the patrol: the robot wanders again.
Result<void> patrol_remove(Editor& editor, int id, int index);
Result<void> patrol_set_mode(Editor& editor, int id, std::string_view mode);
Result<void> patrol_set_wait(Editor& editor, int id, float seconds, std::string merge_key = {});

} // namespace ks::editor
