#pragma once
// Play > Play from start / from camera (F5, Shift+F5): saves the level to a temporary file, starts the
// runtime on it (playtest.h: PlayTest), brings its output into the log and says how it ended. Works through
// the log; the window hands it the level and, from the camera, the viewport's camera.
#include "level/level.h"
#include "ui/editor_log.h"
#include "ui/playtest.h"
#include "ui/playtest_live.h"
#include "view/view_camera.h"

#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ks::editor::ui {

class PlayTestLauncher {
  public:
    PlayTestLauncher(EditorLog& log, std::filesystem::path executable_dir)
        : log_(log), executable_dir_(std::move(executable_dir)) {}

    // `camera` set: the player starts under it, facing where it looks; else at the level's player start.
    void start(const level::Level& level, const ViewCamera* camera);
    // The runtime's output into the log, the exit once it ended, and the live play-test's edits to the game
    // (playtest_live.h). True while an edit waits to be sent (another frame is wanted).
    bool poll(const level::Level& level, std::uint64_t revision);
    bool running() const { return play_.running(); }
    void stop() { play_.stop(); }              // Play > Stop play-test
    void status(nlohmann::json& status) const; // "playtest"

  private:
    void log_line(std::string line, bool error = false) { log_.line(std::move(line), error); }

    EditorLog& log_;
    std::filesystem::path executable_dir_;
    PlayTest play_;
    LivePlayLink live_{log_};
    std::filesystem::path play_file_;
    std::vector<std::string> play_command_; // the last play-test's runtime and arguments
    std::optional<int> play_exit_code_;     // the last play-test's exit code, once it ended
};

} // namespace ks::editor::ui
