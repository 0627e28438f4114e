#pragma once
// The design checks on robot patrols: every point should stand on a floor or stair surface, or the robot
// walks into the air (or into a floor); a point just above or below a surface gets a quick fix that snaps it
// onto that surface. Points on a surface are then asked of the reachability check's navigation mesh: a point
// where nobody can stand (inside a prop, against a wall) snaps to the nearest walkable point, and a point the
// robot can never walk to is reported.
#include "model/validation.h"

namespace ks::nav {
class NavMesh;
}

namespace ks::editor {

void check_patrol_support(const level::Level& level, const ValidationOptions& options,
                          std::vector<Issue>& out);
// `mesh` is the walk check's (the player's body, doors open): a point off it is off the robots' too, in all
// but corridors between 1.6 and 2 units wide.
void check_patrol_on_mesh(const level::Level& level, nav::NavMesh& mesh, const ValidationOptions& options,
                          std::vector<Issue>& out);

} // namespace ks::editor
