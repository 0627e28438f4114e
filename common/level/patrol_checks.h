#pragma once
// The checks on a robot's patrol that the loader and validate() share: how many points, finite and in
// range, a known mode, a wait in range, and no point far outside the level the robot lives in.
#include "level/diagnostics.h"
#include "level/level.h"

#include <string>
#include <vector>

namespace ks::level {

// `path` is the patrol's JSON path ("entities[3].props.patrol"); messages name the sink's subject.
void check_patrol(const Patrol& patrol, const std::string& path, DiagnosticSink& sink);
// Only the mode and the wait: what the reader still checks when it drops a route over a bad point.
void check_patrol_mode_and_wait(const Patrol& patrol, const std::string& path, DiagnosticSink& sink);

// Every patrol point must lie within kPatrolReach of the box around the level's entities: a point beyond
// it is a typo (a missing minus, an extra digit) that would walk the robot off into the void.
void check_patrol_reach(const Level& level, DiagnosticSink& sink, const std::vector<size_t>& source_index);

} // namespace ks::level
