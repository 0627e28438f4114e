#pragma once
// The editor's Analyze action (Play > Analyze, the Play-test report panel's button): the autoplay bot plays
// the level being edited N times in the background (game::BackgroundAnalysis on a copy of the document's
// level, not the file), with a progress bar and Cancel; the report is saved beside the level file
// (LEVEL.playtest.json) and shown: the numbers in the panel, and over the viewport a heat map of where the
// bot took damage (cells on the floor, orange to red), where it died (red crosses) and its paths (a thin
// line per run). A report whose level differs from the one being edited is marked stale. Opening a level
// loads the report beside it, if any.
#include "core/math.h"
#include "game/playtest_analysis.h"
#include "model/editor.h"
#include "ui/layout.h"
#include "ui/ui_spots.h"
#include "view/view_camera.h"

#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

struct ImDrawList;

namespace ks::editor::ui {

class AnalysisView {
  public:
    using Log = std::function<void(const std::string& line, bool error)>;
    explicit AnalysisView(Log log) : log_(std::move(log)) {}

    int runs = 20;           // seeds 1..runs
    bool new_player = false; // the new-player bot plays (game/bot_profiles.h), not the perfect one
    bool overlay = true;     // draw the report over the viewport at all
    bool heat = true;        // damage cells
    bool deaths = true;      // death markers
    bool paths = true;       // the bot's paths

    // Analyses a copy of `level`; the report goes beside `level_file` (kept in memory when it is empty).
    void start(const level::Level& level, const std::filesystem::path& level_file);
    void cancel();
    bool running() const { return job_ != nullptr; }
    float progress() const { return job_ ? job_->progress().fraction() : 0.0f; }
    int runs_done() const { return job_ ? job_->progress().runs_done() : 0; }

    // Every frame: takes a finished analysis, loads the report beside a level file opened since the last
    // call, and compares the report with the level when it changed and no edit is under way (`continuous`:
    // a drag, which would hash the level every frame).
    void update(const level::Level& level, std::uint64_t revision, bool continuous,
                const std::filesystem::path& level_file);
    // Shows the report in `file` (--report); false, logged, when it cannot be read.
    bool load(const std::filesystem::path& file);
    const game::PlaytestReport* report() const { return report_ ? &*report_ : nullptr; }
    bool stale() const { return stale_; }
    const std::filesystem::path& report_file() const { return report_file_; }

    // The panel's contents (inside its window): Analyze / Cancel, runs, progress, the numbers, toggles.
    void panel(const level::Level& level, const std::filesystem::path& level_file, UiSpots& spots);
    // Over one view of the level: the heat map, the deaths and the paths (when shown).
    void draw(ImDrawList* draw, const ViewCamera& view, Vec2 origin) const;
    // The Play-test report panel in the bottom strip (analysis_panel.cpp): update, then the panel's window.
    void window(const Editor& editor, UiSpots& spots, const Rect& rect);
    void status(nlohmann::json& status) const; // "analysis"

  private:
    void finish();
    void numbers() const;

    Log log_;
    std::unique_ptr<game::BackgroundAnalysis> job_;
    std::filesystem::path job_level_file_;
    std::optional<game::PlaytestReport> report_;
    std::filesystem::path report_file_;      // where the report shown was read or written ("" in memory)
    std::filesystem::path followed_file_;    // the level file the report was last looked up for
    std::uint64_t checked_revision_ = ~0ull; // the level revision staleness was last computed for
    bool stale_ = false;
};

} // namespace ks::editor::ui
