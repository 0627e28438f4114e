#pragma once
// The level logic's rules in the editor: the level's own checks (level/logic_checks.h) find dangling targets,
// zero-delay loops, objectives that can never complete and locked doors nothing frees, and tag what they find
// (level::Diagnostic::Kind); here each finding becomes an Issue with its rule, the entity or objective it is
// about and, where one makes sense, a quick fix. The trigger rule needs the walk mesh: reachability.h.
#include "level/level_io.h"
#include "model/validation.h"

namespace ks::editor {

// A zero-delay loop's quick fix delays one of its links by this much: the doors still set each other off, a
// step or more apart instead of for ever within one step, so the designer sees the loop and the game never
// has to cut it off. (Making a link "once" would end the loop too, but changes what the level does.)
inline constexpr float kLoopBreakDelay = 0.1f; // seconds

// The issue for `diagnostic`, a logic finding (its kind is not Other) of level::validate(level).
Issue logic_issue(const level::Level& level, const level::Diagnostic& diagnostic);

// A level with no objectives and no win link can never be won (a version-2 level is won when its objectives
// are complete; the control panel alone no longer wins it): an `objective` issue, fixed by the shutdown
// objective when the level has a control panel.
void check_level_can_be_won(const level::Level& level, std::vector<Issue>& out);

} // namespace ks::editor
