#pragma once
// The logic debugger in the game window (docs/runtime.md, "Logic debugger"): F3 (or Options > Logic
// debugger) shows it; each link event and action as it happens is listed in a panel and drawn in the world as
// a short-lived line from its source to its target; F6 halts and resumes the game, F7 runs one step while
// halted, F8 breaks at the newest listed event (again: no break), a click on a listed row while halted breaks
// at that row's event; `--logic-break SPEC` sets the break from the command line. With --logic-trace FILE the
// same records are written as the logic trace (game/logic_trace.h), "-" to standard output (what the editor's
// play-test log shows). The state and the break are runtime/model/logic_debugger.h's.
#include "core/result.h"
#include "game/game.h"
#include "game/logic_trace.h"
#include "geometry/camera.h"
#include "runtime/model/input_state.h"
#include "runtime/model/logic_debugger.h"

#include <filesystem>
#include <optional>

struct ImDrawList;

namespace ks::shell {
struct Fonts;
}

namespace ks::runtime {

class LogicDebugOverlay {
  public:
    // --logic-trace and --logic-break (a break shows the debugger from the start).
    void configure(std::filesystem::path trace, std::optional<LogicBreak> break_point);
    // A level's game starts: the list is emptied, the trace (re)opened for it.
    void start(const level::Level& level, const game::Game& game);
    bool may_step() { return debugger_.may_step(); }
    void after_step(const game::Game& game);
    // F3, and F6, F7, F8 while shown; true when `visible` changed (the caller saves the option).
    bool handle_keys(InputState& keys, bool& visible);
    // Whether the mouse should be free (halted, with the list shown: its rows take clicks).
    bool wants_mouse(bool visible) const { return visible && debugger_.halted(); }
    void draw(ImDrawList* draw, const game::Game& game, const geometry::Camera& camera,
              const shell::Fonts& fonts, float width, float height);
    const LogicDebugger& debugger() const { return debugger_; }

  private:
    void draw_lines(ImDrawList* draw, const game::Game& game, const geometry::Camera& camera, float width,
                    float height) const;
    void draw_panel(const game::Game& game, const shell::Fonts& fonts, float width, float height);

    LogicDebugger debugger_;
    std::filesystem::path trace_path_;
    std::optional<game::LogicTraceWriter> trace_;
};

} // namespace ks::runtime
