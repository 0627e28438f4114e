#pragma once
// Edits to one robot's patrol route, checked before anything changes: finite points inside the level
// format's position range, at most level::kMaxPatrolPoints, indices that exist, a known mode, a wait in
// range. edit_patrols.h wraps each in one undoable command; tests call them directly.
#include "core/result.h"
#include "level/level.h"

#include <optional>
#include <string_view>

namespace ks::editor {

// Inserts `point` after index `after` (at the end when none is given; -1 puts it first).
Result<void> add_patrol_point(level::Patrol& patrol, Vec3 point, std::optional<int> after = std::nullopt);
Result<void> move_patrol_point(level::Patrol& patrol, int index, Vec3 point);
// Removing the last point removes the patrol (mode and wait back to their defaults): the robot wanders,
// and the document equals what a save and reload would give.
Result<void> remove_patrol_point(level::Patrol& patrol, int index);
Result<void> set_patrol_mode(level::Patrol& patrol, std::string_view mode);
Result<void> set_patrol_wait(level::Patrol& patrol, float seconds);

} // namespace ks::editor
