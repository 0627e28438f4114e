#pragma once
// Where a campaign run stands: the campaign, the level being played, and the result of each level won so far
// (time, robots destroyed, shots and hits), for the summary and campaign-complete screens.
#include "level/campaign.h"

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace ks::runtime {

// One level's play, as the win screens show it.
struct LevelResult {
    std::string title;
    double seconds = 0.0;
    int robots_killed = 0;
    int robots_total = 0; // the robots the game had at the win (spawners add some)
    int shots = 0;
    int hits = 0;           // shots that hit a live robot
    std::string difficulty; // "Normal" (game::difficulty_title) when known: the summary says what was played
};

// "75 %" of the shots that hit, or "-" without a shot (nothing to measure).
std::string accuracy_text(int hits, int shots);
// "m:ss.s", the time a level took on the win screens ("0:00.0" for anything not a time).
std::string format_time(double seconds);

class CampaignProgress {
  public:
    // `campaign` as load_campaign read it from `file` (at least one level).
    CampaignProgress(level::Campaign campaign, std::filesystem::path file)
        : campaign_(std::move(campaign)), file_(std::move(file)) {}

    const level::Campaign& campaign() const { return campaign_; }
    const std::filesystem::path& file() const { return file_; }
    std::size_t index() const { return index_; } // the level being played (0-based)
    std::size_t count() const { return campaign_.levels.size(); }
    const level::CampaignLevel& current() const { return campaign_.levels[index_]; }
    std::filesystem::path current_path() const { return level::campaign_level_path(file_, current()); }
    bool on_last_level() const { return index_ + 1 >= count(); }
    // Every level won: the campaign-complete screen.
    bool finished() const { return results_.size() >= count(); }

    // The current level was won with `result` (its title is the campaign's).
    void record_win(LevelResult result);
    // On to the next level after a win; false when there is none (or the current one is not won yet).
    bool advance();

    // Resumes a saved run (campaign_save.h): `won` are the first levels' results; play goes on at the next
    // level (the last one when every level was won). Results past the campaign's end are dropped.
    void restore(std::span<const LevelResult> won);

    std::span<const LevelResult> results() const { return results_; }
    const LevelResult* last_result() const { return results_.empty() ? nullptr : &results_.back(); }
    // The levels won so far, added up (the title is the campaign's name).
    LevelResult totals() const;

  private:
    level::Campaign campaign_;
    std::filesystem::path file_;
    std::size_t index_ = 0;
    std::vector<LevelResult> results_;
};

} // namespace ks::runtime
