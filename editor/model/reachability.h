#pragma once
// "Can the player walk from the start to the control panel?" — asked of a navigation mesh (nav::NavMesh,
// the one the autoplay bot plans on) built for the player's body and the game's character limits: radius,
// height, step height and steepest slope. Stairs are the wedges the game collides with; floors, walls, props
// and the panel are the shapes the game builds. Doors count as open (the player opens them); robots and
// pickups do not block; jumps are not counted, so a level that needs a jump to finish is reported (as a
// warning).
#include "model/validation.h"

#include <cstdint>
#include <memory>
#include <string>

namespace ks::nav {
class NavMesh;
}

namespace ks::editor {

struct WalkCheck {
    bool decided = false; // false when the mesh does not build, or there is no panel or no mesh at the start
    bool reachable = false;
    // Points on the mesh beside the panel (one per side where the body can stand): 0 when the panel stands
    // where nobody can walk up to it, from anywhere.
    int panel_approaches = 0;
    int polygons = 0;          // the mesh's size, for the bench
    std::string build_problem; // why the mesh did not build (other rules report the cause to the user)
    std::shared_ptr<nav::NavMesh> mesh; // the player's mesh, every door open (null when it did not build)
};

WalkCheck walk_to_control_panel(const level::Level& level, const ValidationOptions& options);
// A hash of everything the walk check reads (walls, floors, stairs, doors, props and the control panel
// with their boxes, the player start, the options): equal fingerprints give the same answer, so the editor
// skips the check after edits that cannot change it (moving a robot or a pickup, renaming, tuning a light).
std::uint64_t walk_fingerprint(const level::Level& level, const ValidationOptions& options);
// The expensive half of the reachability rules: the mesh build (when the level has a control panel or a
// trigger), its islands (nav::NavMesh::island) and the control panel's answer. The mesh comes back for the
// cheap half, so the editor reruns only that after edits that move robots or triggers.
struct PanelReachability {
    std::vector<Issue> issues;
    std::shared_ptr<nav::NavMesh> mesh;
};
PanelReachability check_panel_reachability(const level::Level& level, const ValidationOptions& options);
// Robots that can never walk to the player's start on `mesh` (doors open): they would only ever shoot from
// where they stand. Robots the mesh does not reach under their feet are the support rule's business.
void check_robot_reach(const level::Level& level, nav::NavMesh& mesh, const ValidationOptions& options,
                       std::vector<Issue>& out);
// Triggers that no one they notice can set off on `mesh` (doors open; islands numbered by
// check_panel_reachability, off the UI thread): the player's feet must reach the box from the player start,
// a robot's from where some robot or spawner stands. Robots are asked on the player's mesh, their body's
// smaller radius added around the box.
void check_trigger_reach(const level::Level& level, nav::NavMesh& mesh, const ValidationOptions& options,
                         std::vector<Issue>& out);
// All of them, for a fresh validation.
void check_reachability(const level::Level& level, const ValidationOptions& options, std::vector<Issue>& out);

} // namespace ks::editor
