#pragma once
// Idle-time autosave to a sidecar folder with rotation, and finding an autosave to recover after a crash.
// A level `dir/main.json` autosaves to `dir/.autosave/main.<n>.json` (n counts up; the `keep` newest stay);
// an untitled level autosaves to `<config dir>/autosave/untitled.<n>.json`. Autosaves are ordinary level
// files.
#include "core/result.h"
#include "model/editor.h"

#include <filesystem>
#include <functional>
#include <optional>
#include <vector>

namespace ks::editor {

struct AutosaveConfig {
    double idle_seconds = 5.0;          // save once the user has paused this long after a change...
    double max_delay_seconds = 60.0;    // ...or once a change has waited this long, even mid-work
    int keep = 5;                       // newest autosaves kept per level
    std::filesystem::path untitled_dir; // where untitled levels go (empty: paths::user_config_dir()/autosave)
};

// Seconds on a monotonic clock; tests inject their own.
using Clock = std::function<double()>;
double steady_seconds();

std::filesystem::path autosave_dir_for(const std::filesystem::path& level_file);
// The autosaves of `stem` in `dir`, oldest first (by their counter n).
std::vector<std::filesystem::path> list_autosaves(const std::filesystem::path& dir, const std::string& stem);
// The newest autosave of level_file if it is newer than the file and differs from it.
std::optional<RecoveryOffer> find_recovery(const std::filesystem::path& level_file);
// After a crash with an untitled level: the newest untitled autosave (offer it with Editor::offer_recovery
// at start-up; the offer's level_file is empty).
std::optional<RecoveryOffer> find_untitled_recovery(const AutosaveConfig& config);
// Deletes the autosaves of `stem` in `dir` (after the user declined an untitled recovery, or saved it).
void remove_autosaves(const std::filesystem::path& dir, const std::string& stem);
// Where untitled levels autosave: config.untitled_dir, else <config dir>/autosave.
std::filesystem::path untitled_autosave_dir(const AutosaveConfig& config);

class Autosaver {
  public:
    explicit Autosaver(AutosaveConfig config = {}, Clock clock = steady_seconds);
    // Call every frame (or after every script line). Returns the file written, if it wrote one now.
    Result<std::optional<std::filesystem::path>> update(const Editor& editor);
    const AutosaveConfig& config() const { return config_; }

  private:
    Result<std::filesystem::path> write(const Editor& editor);

    AutosaveConfig config_;
    Clock clock_;
    std::uint64_t seen_revision_ = ~0ull;
    std::uint64_t saved_revision_ = ~0ull;
    double last_change_ = 0;
    double retry_after_ = 0; // after a failed write: no new attempt before this time
    std::optional<double> pending_since_;
};

} // namespace ks::editor
