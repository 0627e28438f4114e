// game/headless_campaign.h: the bot plays a campaign's levels in order and stops at the first it loses; the
// options and a bad campaign file are errors, not crashes.
#include "core/files.h"
#include "game/headless_campaign.h"
#include "game_test_levels.h"

#include <filesystem>
#include <string>

using namespace ks;
using namespace ks::game;
namespace fs = std::filesystem;

namespace {
fs::path test_campaign() {
    return ks::test::data_dir() / "campaign" / "campaign.json";
}

// A campaign in a scratch folder: the test campaign's two levels, then one nobody can win (no objective
// that completes, no control panel), then the second level again under another name.
fs::path campaign_with_a_lost_level(const ks::test::ScratchDir& dir) {
    for (const char* name : {"one.json", "two.json"})
        fs::copy_file(ks::test::data_dir() / "campaign" / name, dir / name);
    fs::copy_file(ks::test::data_dir() / "campaign" / "two.json", dir / "after.json");
    REQUIRE(files::write_atomic(dir / "endless.json", R"({"format": "killswitch-level", "version": 2,
  "name": "Endless", "player_start": {"position": [0, 0, 0], "yaw": 0},
  "objectives": [{"id": "never", "text": "Wait for nothing"}],
  "entities": [{"id": 1, "type": "floor", "position": [0, 0, 0], "props": {"size": [20, 20]}}]})")
                .ok());
    const fs::path file = dir / "campaign.json";
    REQUIRE(files::write_atomic(file, R"({"name": "Hard run", "levels": [
  {"file": "one.json", "title": "First Light"}, {"file": "two.json", "title": "Second Wind"},
  {"file": "endless.json", "title": "No Way Out"}, {"file": "after.json", "title": "Never Reached"}]})")
                .ok());
    return file;
}
} // namespace

TEST_CASE("headless campaign: the bot wins every level of the test campaign in order, deterministically") {
    CampaignRunOptions options;
    options.campaign = test_campaign();
    options.seconds = 60.0;
    std::vector<std::string> seen;
    auto result =
        run_headless_campaign(options, [&](const CampaignLevelRun& run) { seen.push_back(run.level.title); });
    REQUIRE_MESSAGE(result.ok(), result.error().str());
    CHECK(result->won());
    REQUIRE(result->levels.size() == 2);
    CHECK(seen == std::vector<std::string>{"First Light", "Second Wind"});
    CHECK(result->levels[0].file == ks::test::data_dir() / "campaign" / "one.json");
    CHECK(result->levels[0].stats.outcome == "win");
    CHECK(result->levels[0].stats.shots >= 1);
    CHECK(result->levels[0].hits >= 1); // the target robot had to be shot down
    CHECK(result->levels[0].summary().find("level 1/2 \"First Light\" (one.json): win after") == 0);
    CHECK(result->summary().find("campaign \"Test run\": every level won (2 levels, ") == 0);
    auto again = run_headless_campaign(options);
    REQUIRE(again.ok());
    CHECK(again->levels[0].stats.state_hash == result->levels[0].stats.state_hash);
    CHECK(again->levels[1].stats.state_hash == result->levels[1].stats.state_hash);
}

TEST_CASE("headless campaign: a level lost stops the run and is named") {
    ks::test::ScratchDir dir;
    CampaignRunOptions options;
    options.campaign = campaign_with_a_lost_level(dir);
    options.seconds = 2.0;
    auto result = run_headless_campaign(options);
    REQUIRE_MESSAGE(result.ok(), result.error().str());
    CHECK_FALSE(result->won());
    REQUIRE(result->levels.size() == 3); // the fourth is never played
    CHECK(result->levels[2].stats.outcome == "timeout");
    CHECK(result->summary() ==
          "campaign \"Hard run\": lost level 3 \"No Way Out\" (endless.json): timeout after 2 s");
}

TEST_CASE("headless campaign: bad options, a bad campaign file and a broken level are errors") {
    auto parse = [](std::vector<const char*> args) {
        args.insert(args.begin(), "killswitch");
        auto cl = CommandLine::parse(static_cast<int>(args.size()), args.data(), headless_flags());
        REQUIRE(cl.ok());
        return parse_campaign_run_options(*cl);
    };
    auto ok = parse({"--headless", "--campaign", "levels/campaign.json", "--seed", "4", "--seconds", "90"});
    REQUIRE(ok.ok());
    CHECK(ok->seed == 4);
    CHECK(ok->seconds == 90.0);
    CHECK_FALSE(parse({"--headless", "--campaign", ""}).ok());
    CHECK_FALSE(parse({"--headless", "--campaign", "c.json", "--seconds", "0"}).ok());
    CHECK_FALSE(parse({"--headless", "--campaign", "c.json", "--seed", "-1"}).ok());

    ks::test::ScratchDir dir;
    CampaignRunOptions options;
    options.campaign = dir / "missing.json";
    CHECK_FALSE(run_headless_campaign(options).ok());
    REQUIRE(files::write_atomic(dir / "broken_level.json", "{\"format\": \"killswitch-level\"").ok());
    REQUIRE(
        files::write_atomic(dir / "campaign.json",
                            R"({"name": "B", "levels": [{"file": "broken_level.json", "title": "Broken"}]})")
            .ok());
    options.campaign = dir / "campaign.json";
    auto broken = run_headless_campaign(options);
    REQUIRE_FALSE(broken.ok());
    CHECK(broken.error().str().find("broken_level.json") != std::string::npos);
}
