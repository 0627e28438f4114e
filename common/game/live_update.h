#pragma once
// The live play-test's rebuild (docs/game.md, "Live edits"): a game built on the edited level that takes
// over the running game's state for everything that still exists, so the designer's edit shows up without
// starting again. Entities are matched by level id. The rule: the edited level decides what an entity is
// and where it stands when the edit moved it (its position or rotation changed in the file); the running
// game decides what has happened to it (a door's opening, a light switched, a pickup taken, a cylinder gone
// off, a robot's health, mode and, unless the edit moved it, its place; a spawner's wave; an objective done,
// a trigger's state, a once link fired). The player keeps place, view, health, shield, ammo and statistics
// (a moved player start does not move a player already playing); the step count, the random sequence and
// the phase go on. Robots a spawner made come along while alive and their spawner still exists. Delayed
// link actions still waiting go on at their due step while the edit kept their link (same owner, event,
// action and target; dropped with it otherwise), and the message on screen is kept when
// its entity is. A moved door keeps how open it is. The navigation mesh is copied from the running game
// when the edit left what it is made of alone (solids, doors, brushes, models, level settings); else only
// its tiles whose input changed are built again (nav::NavMesh::rebuild), the rest copied.
#include "core/result.h"
#include "game/game.h"
#include "level/level.h"

#include <memory>
#include <string>

namespace ks::game {

struct LiveRebuild {
    std::unique_ptr<Game> game;
    int kept = 0;    // entities whose running state was carried over
    int added = 0;   // entities new in the edit
    int removed = 0; // entities of the running level that the edit deleted
    std::string summary() const;
};

// `before` is the level `running` was built (or last rebuilt) from; `options` are those of a new game
// (the seed is not used again: the running game's random sequence goes on). Errors are the game build's,
// naming the entity; `running` is untouched either way.
Result<LiveRebuild> rebuild_for_edit(const Game& running, const level::Level& before,
                                     const level::Level& edited, GameOptions options);

} // namespace ks::game
