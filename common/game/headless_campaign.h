#pragma once
// Plays a whole campaign without a window, as CI proves it can be won: `killswitch --headless --campaign FILE
// [--seed N] [--seconds S]` runs the autoplay bot on every level in order (each with the same seed and time
// limit) and stops at the first level it does not win. The runtime's main prints each level's line and exits
// 0 when every level was won, 1 naming the level lost, 2 on bad options or a bad campaign file.
#include "core/cli.h"
#include "core/result.h"
#include "game/headless.h"
#include "level/campaign.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace ks::game {

struct CampaignRunOptions {
    std::filesystem::path campaign;
    double seconds = 300.0; // per level
    std::uint64_t seed = 1;
};

struct CampaignLevelRun {
    std::size_t index = 0; // in the campaign, from 0
    std::size_t level_count = 0;
    level::CampaignLevel level;
    std::filesystem::path file; // where the level file is
    HeadlessStats stats;
    int hits = 0; // shots that hit a live robot
    bool won() const { return stats.outcome == "win"; }
    // "level 1/2 \"The Simulation\" (main.json): win after 95.31 s simulated, ..., 40 of 60 shots hit, ..."
    std::string summary() const;
};

struct CampaignRunResult {
    level::Campaign campaign;
    std::vector<CampaignLevelRun> levels; // those played: all of them, or up to the one lost
    bool won() const;
    // "campaign \"Killswitch\": every level won (2 levels, 190.40 s simulated)" or "... lost level 2 ...".
    std::string summary() const;
};

const std::vector<std::string>& campaign_run_option_names(); // headless, campaign, seed, seconds, autoplay
Result<CampaignRunOptions> parse_campaign_run_options(const CommandLine& command_line);
// Errors: the campaign file, a level file that does not load, a level the game cannot build. A level lost is
// not an error: the result says which.
Result<CampaignRunResult>
run_headless_campaign(const CampaignRunOptions& options,
                      const std::function<void(const CampaignLevelRun&)>& on_level = {});

} // namespace ks::game
