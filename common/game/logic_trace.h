#pragma once
// The logic trace (docs/game.md, "Logic trace"): the level logic's records (logic_record.h) as text, one line
// per event or action, in a stable format that tests compare with stored traces and the editor's play-test
// log shows. `killswitch --headless --logic-trace FILE` and the windowed game's --logic-trace write it.
#include "core/result.h"
#include "game/game.h"
#include "game/logic_record.h"
#include "level/level.h"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace ks::game {

// The trace's first line: its format and version, and the fields of the lines that follow.
inline constexpr std::string_view kLogicTraceHeader =
    "# killswitch logic trace 1: step time kind what source target link";

// How the trace names a record's ends: `door:12:"Hall door"`, `objective:0:"shutdown"`, `level`, `-`.
class LogicTraceNames {
  public:
    explicit LogicTraceNames(const level::Level& level);
    std::string end(const LogicEnd& end) const;
    // A robot a spawner made (its RobotSpawned event): named as the game names it, after its spawner.
    void add_spawned(int robot_id, int spawner_id);
    // The robots this step spawned, from its events.
    void add_spawned(std::span<const Event> events);

  private:
    std::unordered_map<int, std::string> entities_; // by id
    std::vector<std::string> objectives_;
};

// One record as a line (no newline): `STEP TIME event EVENT SOURCE - -` or
// `STEP TIME action ACTION SOURCE TARGET LINK`, the time in seconds with three decimals.
std::string logic_trace_line(const LogicRecord& record, const LogicTraceNames& names, double step_seconds);

// A trace being written to a file, or to standard output for "-", a line per record, flushed per batch.
class LogicTraceWriter {
  public:
    // Opens the file (replacing it) and writes the header; an unwritable path is an error naming it.
    static Result<LogicTraceWriter> open(const std::filesystem::path& path, const level::Level& level,
                                         double step_seconds);
    // The game's records of this step (its spawned robots named first).
    Result<void> write(const Game& game);

  private:
    struct Close {
        void operator()(std::FILE* f) const;
    };
    LogicTraceWriter(std::filesystem::path path, const level::Level& level, double step_seconds);
    Result<void> put(const std::string& text);

    std::filesystem::path path_;
    LogicTraceNames names_;
    double step_seconds_ = 0.0;
    std::unique_ptr<std::FILE, Close> file_;
};

} // namespace ks::game
