#include "game/headless_campaign.h"

#include "core/paths.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace ks::game {

namespace {
std::string quoted(const std::string& text) {
    return "\"" + text + "\"";
}
} // namespace

std::string CampaignLevelRun::summary() const {
    char head[64];
    std::snprintf(head, sizeof head, "level %zu/%zu ", index + 1, level_count);
    return head + quoted(level.title) + " (" + level.file + "): " + stats.summary() + ", " +
           std::to_string(hits) + " of " + std::to_string(stats.shots) + " shots hit";
}

bool CampaignRunResult::won() const {
    return !levels.empty() && levels.size() == campaign.levels.size() &&
           std::all_of(levels.begin(), levels.end(), [](const CampaignLevelRun& l) { return l.won(); });
}

std::string CampaignRunResult::summary() const {
    double seconds = 0.0;
    for (const CampaignLevelRun& l : levels) seconds += l.stats.sim_time_s;
    char total[64];
    std::snprintf(total, sizeof total, "%.2f s simulated", seconds);
    if (won())
        return "campaign " + quoted(campaign.name) + ": every level won (" + std::to_string(levels.size()) +
               (levels.size() == 1 ? " level, " : " levels, ") + total + ")";
    if (levels.empty()) return "campaign " + quoted(campaign.name) + ": no level played";
    const CampaignLevelRun& lost = levels.back();
    return "campaign " + quoted(campaign.name) + ": lost level " + std::to_string(lost.index + 1) + " " +
           quoted(lost.level.title) + " (" + lost.level.file + "): " + lost.stats.outcome + " after " +
           std::to_string(static_cast<int>(lost.stats.sim_time_s)) + " s";
}

const std::vector<std::string>& campaign_run_option_names() {
    static const std::vector<std::string> names{"headless", "campaign", "seed", "seconds", "autoplay"};
    return names;
}

Result<CampaignRunOptions> parse_campaign_run_options(const CommandLine& cl) {
    CampaignRunOptions o;
    const std::string campaign = cl.get_or("campaign", "");
    if (campaign.empty())
        return Error("--campaign needs a campaign file", Location("command line", 0, 0, "--campaign"),
                     "e.g. --campaign levels/campaign.json");
    o.campaign = paths::resolve_user_path(campaign);
    if (auto limits = parse_run_limits(cl, o.seconds, o.seed, "each level's simulated time limit"); !limits)
        return limits.error();
    return o;
}

Result<CampaignRunResult>
run_headless_campaign(const CampaignRunOptions& options,
                      const std::function<void(const CampaignLevelRun&)>& on_level) {
    auto campaign = level::load_campaign(options.campaign);
    if (!campaign) return campaign.error();
    CampaignRunResult result;
    result.campaign = *campaign;
    for (std::size_t i = 0; i < campaign->levels.size(); ++i) {
        CampaignLevelRun run;
        run.index = i;
        run.level_count = campaign->levels.size();
        run.level = campaign->levels[i];
        run.file = level::campaign_level_path(options.campaign, run.level);
        HeadlessOptions headless;
        headless.level = run.file;
        headless.seconds = options.seconds;
        headless.seed = options.seed;
        headless.autoplay = true;
        headless.on_finish = [&run](const Game& game) -> Result<void> {
            run.hits = game.player().hits;
            return {};
        };
        auto stats = run_headless(headless);
        if (!stats) return stats.error();
        run.stats = *stats;
        result.levels.push_back(run);
        if (on_level) on_level(result.levels.back());
        if (!result.levels.back().won()) break;
    }
    return result;
}

} // namespace ks::game
