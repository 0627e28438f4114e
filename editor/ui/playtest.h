#pragma once
// Play-testing from the editor: the level is saved to a temporary file and the runtime (`killswitch`, next to
// the editor binary) is started on it as a child process; its stderr and stdout come back line by line into
// the editor's log without blocking the frame (a non-blocking pipe read every frame).
#include "core/math.h"
#include "core/result.h"

#include <filesystem>
#include <optional>
#include <string>
#include <sys/types.h>
#include <utility>
#include <vector>

namespace ks::editor::ui {

struct PlayStart {
    Vec3 position{0.0f};
    float yaw_degrees = 0.0f;
};

// What the runtime's --help says it understands (asked once per play-test; the runtime is developed
// alongside the editor, so the editor adapts instead of passing options it would reject).
struct RuntimeOptions {
    bool screen = false;      // --screen play: straight into the game, no loading screen or menu
    bool warp = false;        // --warp x,y,z,yaw,pitch: the player's feet and facing, degrees
    bool camera = false;      // --camera x,y,z,yaw,pitch: the older render-only view's eye
    bool logic_trace = false; // --logic-trace -: the level logic's events and actions on stdout, into the log
};
RuntimeOptions parse_runtime_help(const std::string& help_text);
// The runtime to start: $KS_PLAYTEST_COMMAND when set (tests substitute a recorder; a designer can point it
// at another build), else `killswitch` next to the editor.
std::filesystem::path playtest_runtime(const std::filesystem::path& executable_dir);
RuntimeOptions query_runtime_options(const std::filesystem::path& runtime);

// The runtime's command line: --level TMP (+ --screen play, + --logic-trace - so the log lists what the
// level's links do: docs/game.md, "Logic trace") and, for Shift+F5, --warp x,y,z,yaw,0 with the feet under
// the editor camera (or --camera at the eye when the runtime has no --warp).
std::vector<std::string> playtest_arguments(const std::filesystem::path& level,
                                            const std::optional<PlayStart>& start,
                                            const RuntimeOptions& runtime);

class PlayTest {
  public:
    ~PlayTest();
    // `environment`: variables added to the editor's own for the child (the live play-test's channel).
    Result<void> start(const std::filesystem::path& runtime, const std::vector<std::string>& arguments,
                       const std::vector<std::pair<std::string, std::string>>& environment = {});
    // Reads whatever output is waiting and reaps the child when it ended; appends complete lines to `lines`.
    void poll(std::vector<std::string>& lines);
    bool running() const { return pid_ > 0; }
    void stop(); // SIGTERM to the child we started
    std::optional<int> last_exit_code() const { return exit_code_; }

  private:
    pid_t pid_ = -1;
    int pipe_ = -1;
    std::string partial_;
    std::optional<int> exit_code_;
};

} // namespace ks::editor::ui
