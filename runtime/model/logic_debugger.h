#pragma once
// The in-game logic debugger, window-free (docs/runtime.md, "Logic debugger"): the level logic's events and
// actions as they happen (LevelLogic::records(), read after each game step) kept as a list for the overlay,
// where each end sits in the world for the lines drawn from source to target, and the break: the game halts
// after the step in which a chosen event fired, then runs one step at a time or resumes. The app draws it
// (runtime/app/logic_debug_overlay.cpp) and asks may_step() before each game step.
#include "core/math.h"
#include "core/result.h"
#include "game/game.h"
#include "game/logic_trace.h"
#include "level/level.h"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <string_view>

namespace ks::runtime {

// Which events halt the game: one event kind, one entity (its level id), or both.
struct LogicBreak {
    std::optional<level::LinkEvent> event; // any event when empty
    int entity = -1;                       // any source when negative
    bool matches(const game::LogicRecord& record) const;
    std::string text() const; // as --logic-break takes it: "12:on_enter", "on_death", "12"
    // The break on the record's event from the record's entity (an action: the event that set it off).
    static LogicBreak at(const game::LogicRecord& record);
};

// `--logic-break SPEC`: an entity id, an event name, or ID:EVENT; an error says what was wrong and the fix.
Result<LogicBreak> parse_logic_break(std::string_view spec);

struct LogicLogEntry {
    game::LogicRecord record;
    std::string line; // the logic trace's line (game/logic_trace.h)
};

class LogicDebugger {
  public:
    static constexpr std::size_t kMaxEntries = 200;
    static constexpr std::int64_t kLineSteps = 240; // a line stays 2 s of game time (the game halted: on)

    // A new level: the names of its entities, an empty list, running. The break is kept.
    void reset(const level::Level& level, double step_seconds);
    // Whether the game may run its next step now: always while running; halted, only a requested step.
    bool may_step();
    // After every game step: the step's records join the list; a record the break matches halts the game.
    void after_step(const game::Game& game);

    void halt() { halted_ = true; }
    void resume() { halted_ = false, step_requested_ = false, hit_.reset(); }
    void step_once() { step_requested_ = halted_; }
    bool halted() const { return halted_; }
    void set_break(std::optional<LogicBreak> b) { break_ = b; }
    const std::optional<LogicBreak>& break_point() const { return break_; }
    // The record the game halted at (empty when halted by hand, or running).
    const std::optional<LogicLogEntry>& hit() const { return hit_; }
    const std::deque<LogicLogEntry>& entries() const { return entries_; }
    // Where an end of a record is in the world now: a robot's chest, a door's or another entity's place; the
    // level and objectives (which have none) at the player's eye.
    Vec3 place(const game::LogicEnd& end, const game::Game& game) const;

  private:
    const level::Level* level_ = nullptr;
    std::optional<game::LogicTraceNames> names_;
    double step_seconds_ = 0.0;
    std::deque<LogicLogEntry> entries_;
    std::optional<LogicBreak> break_;
    std::optional<LogicLogEntry> hit_;
    bool halted_ = false, step_requested_ = false;
};

} // namespace ks::runtime
