#pragma once
// What the level logic did, for observers (the headless logic trace, the in-game logic debugger, the
// editor's play-test log): every link event an entity, an objective or the level emitted, and every action
// run, in the order they happened. Nothing in the game reads these back, so recording them changes no run.
#include "level/logic_names.h"

#include <cstdint>

namespace ks::game {

// One end of a record: an entity (its level id), an objective (its index in LevelLogic::objectives()), the
// level itself, or nothing (an event's target; an action run from outside the links).
struct LogicEnd {
    enum class Kind : std::uint8_t { None, Entity, Objective, Level };
    Kind kind = Kind::None;
    int id = -1;
    friend bool operator==(const LogicEnd&, const LogicEnd&) = default;
};

struct LogicRecord {
    std::int64_t step = 0; // Game::steps() when it happened (a run_action between steps: the last step)
    bool is_action = false;
    level::LinkEvent event = level::LinkEvent::OnStart; // the event; for an action, its link's event
    level::LinkAction action = level::LinkAction::Win;  // an action's
    LogicEnd source;                                    // who emitted the event; an action's link's owner
    LogicEnd target;                                    // what an action acts on
    int link = -1; // an action's index in LevelLogic::links(); -1 for Game::run_action
};

} // namespace ks::game
