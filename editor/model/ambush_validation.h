#pragma once
// The start-ambush rule: a robot that sees the player start (inside its eye radius, on its level, with
// nothing solid between its eye and the player) and could fire within kAmbushSeconds of the level starting
// (its alert and aim, plus the walk to its shooting distance) gives a warning: a new player has not found
// the mouse yet (issue 29: a robot 5.6 units from the start killed the player in about 10 s while
// validation said "ready to play"). Dormant robots wait for a link and are left out; props and models are
// not counted as cover (a warning too many rather than one too few).
#include "model/validation.h"

namespace ks::editor {

// Seconds from the start within which a robot's first shot makes the start an ambush.
inline constexpr float kAmbushSeconds = 3.0f;
// The robot's alert and shoot-pose times before its first shot on Normal (the robot clips' lengths).
inline constexpr float kRobotSecondsToAim = 0.9f;

void check_start_ambush(const level::Level& level, std::vector<Issue>& out);

} // namespace ks::editor
