#pragma once
// "Can the player walk from the start to the control panel?" — a flood fill over a grid of walkable
// surfaces (floor tops and stair ramps, the game's wedge collision), with the game's character limits: a cell
// is open where the player's body (radius, height) fits between the surface and what is above, and the player
// can step up at most step_height between neighbouring cells and drop any distance. Doors count as open (the
// player opens them); robots and pickups do not block; jumps are not counted, so a level that needs a jump to
// finish is reported (as a warning).
#include "model/validation.h"

#include <cstdint>

namespace ks::editor {

struct WalkGridStats {
    bool decided = false; // false when there is no control panel or no ground under the start
    bool reachable = false;
    int columns = 0, rows = 0;
    float cell = 0.0f;
    int open_nodes = 0;    // walkable (cell, surface) nodes
    int visited_nodes = 0; // reached from the start
};

WalkGridStats walk_to_control_panel(const level::Level& level, const ValidationOptions& options);
// A hash of everything the walk check reads (walls, floors, stairs and other blockers with their boxes, the
// control panel, the player start, the options): equal fingerprints give the same answer, so the editor
// skips the check after edits that cannot change it (moving a robot or a pickup, renaming, tuning a light).
std::uint64_t walk_fingerprint(const level::Level& level, const ValidationOptions& options);
void check_reachability(const level::Level& level, const ValidationOptions& options, std::vector<Issue>& out);

} // namespace ks::editor
