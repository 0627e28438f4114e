#pragma once
// The objective every version-1 level had, made explicit in version 2: shut the simulation down at the
// control panel. The migration from version 1 gives it to old files (level_migrate.cpp); levels built in code
// (tests, generated levels, a new level in the editor) ask for it here.
#include "level/level.h"

namespace ks::level {

inline constexpr const char* kShutdownObjective = "shutdown";
inline constexpr const char* kShutdownObjectiveText = "Shut down the simulation at the control panel";

// The link a control panel gets: using it completes the shutdown objective.
Link shutdown_link();
// Adds the link to every control panel that has none and the objective (unless one with its id exists), so
// using any panel wins a level that has no other objective. A level without a panel is left alone (nothing
// could complete the objective). Returns whether anything was added.
bool add_shutdown_objective(Level& level);

} // namespace ks::level
