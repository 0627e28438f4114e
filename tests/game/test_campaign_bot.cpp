// The bot wins every level of the shipped campaign (levels/campaign.json, read with load_campaign) headless,
// for seeds 1-6: a level added to the campaign must be one the bot can finish by following its objectives.
#include "game/headless.h"
#include "level/campaign.h"
#include "test_support.h"

#include <doctest/doctest.h>

using namespace ks;
using namespace ks::game;

TEST_CASE("the bot wins every campaign level for seeds 1-6") {
    const auto file = test::source_dir() / "levels" / "campaign.json";
    auto campaign = level::load_campaign(file);
    REQUIRE_MESSAGE(campaign.ok(), (campaign.ok() ? std::string() : campaign.error().str()));
    REQUIRE(campaign->levels.size() >= 2); // the main level and Lockdown at least
    for (const level::CampaignLevel& entry : campaign->levels) {
        for (std::uint64_t seed = 1; seed <= 6; ++seed) {
            CAPTURE(entry.file);
            CAPTURE(seed);
            HeadlessOptions o;
            o.level = level::campaign_level_path(file, entry);
            o.seconds = 120.0;
            o.seed = seed;
            o.autoplay = true;
            auto stats = run_headless(o);
            REQUIRE_MESSAGE(stats.ok(), (stats.ok() ? std::string() : stats.error().str()));
            MESSAGE(entry.file << " seed " << seed << ": " << stats->summary());
            CHECK(stats->outcome == "win");
            CHECK(stats->robots_killed > 0);
        }
    }
}
