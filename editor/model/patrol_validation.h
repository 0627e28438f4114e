#pragma once
// The design check on robot patrols: every point should stand on a floor or stair surface, or the robot
// walks into the air (or into a floor). A point just above or below a surface gets a quick fix that snaps it
// onto that surface. The navigation mesh's reachability check replaces this once robots follow paths.
#include "model/validation.h"

namespace ks::editor {

void check_patrol_support(const level::Level& level, const ValidationOptions& options,
                          std::vector<Issue>& out);

} // namespace ks::editor
