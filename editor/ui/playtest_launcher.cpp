// The play-test's temporary level file, the runtime's command line and its end, in the log and the status
// file.
#include "ui/playtest_launcher.h"
#include "core/files.h"
#include "level/level_io.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <unistd.h>

namespace ks::editor::ui {
namespace fs = std::filesystem;

void PlayTestLauncher::start(const level::Level& level, const ViewCamera* camera) {
    if (play_.running()) {
        log_line("a play-test is already running", true);
        return;
    }
    play_file_ = fs::temp_directory_path() / ("killswitch-playtest-" + std::to_string(getpid()) + ".json");
    if (auto r = files::write_atomic(play_file_, level::save_level_string(level)); !r) {
        log_line("play-test: " + r.error().str(), true);
        return;
    }
    std::optional<PlayStart> start;
    if (camera) // feet three units under the eye, facing where the camera looks
        start = PlayStart{camera->camera.position - Vec3(0, 3, 0),
                          std::remainder(degrees(camera->camera.yaw), 360.0f)};
    const fs::path runtime = playtest_runtime(executable_dir_);
    const auto args = playtest_arguments(play_file_, start, query_runtime_options(runtime));
    play_exit_code_.reset();
    std::vector<std::pair<std::string, std::string>> environment;
    if (auto live = live_.open(); !live)
        log_line("live play-test off (the game runs on the saved copy): " + live.error().str(), true);
    else
        environment = std::move(*live);
    if (auto r = play_.start(runtime, args, environment); !r) {
        live_.close();
        log_line("play-test: " + r.error().str(), true);
        return;
    }
    play_command_ = {runtime.string()};
    play_command_.insert(play_command_.end(), args.begin(), args.end());
    std::string line = "play-test:";
    for (const auto& a : play_command_) line += " " + a;
    log_line(line);
}

bool PlayTestLauncher::poll(const level::Level& level, std::uint64_t revision) {
    std::vector<std::string> lines;
    play_.poll(lines);
    for (auto& l : lines) log_line("[game] " + l, l.find("error") != std::string::npos);
    if (!play_.running() && play_.last_exit_code() && !play_file_.empty()) {
        const int code = *play_.last_exit_code();
        log_line(code == 0 ? "play-test ended"
                           : "play-test FAILED with exit code " + std::to_string(code) +
                                 " (its messages are above)",
                 code != 0);
        play_exit_code_ = code;
        play_file_.clear();
        live_.close();
    }
    return live_.poll(level, revision);
}

void PlayTestLauncher::status(nlohmann::json& s) const {
    using nlohmann::json;
    json play;
    play["running"] = play_.running();
    play["command"] = play_command_;
    play["exit_code"] = play_exit_code_ ? json(*play_exit_code_) : json(nullptr);
    live_.status(play);
    s["playtest"] = play;
}

} // namespace ks::editor::ui
