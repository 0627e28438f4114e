// docs/tutorial.md cannot rot: its editor scripts (docs/tutorial/01_rooms.kss ... 06_ship.kss, run in order
// as one script) build a level the editor's validation finds nothing wrong with, save it, add it to a
// campaign, and the headless bot wins it for seeds 1-6. Here (not tests/editor) because it needs both the
// editor's model and the game.
#include "game/headless.h"
#include "level/campaign.h"
#include "model/script.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <algorithm>

using namespace ks;
namespace fs = std::filesystem;

namespace {

// The tutorial's steps in order: every docs/tutorial/NN_*.kss.
std::vector<fs::path> tutorial_steps() {
    std::vector<fs::path> steps;
    for (const auto& entry : fs::directory_iterator(test::source_dir() / "docs" / "tutorial"))
        if (entry.path().extension() == ".kss") steps.push_back(entry.path());
    std::sort(steps.begin(), steps.end());
    return steps;
}

} // namespace

TEST_CASE("the tutorial's scripts build a valid level, ship it in a campaign, and the bot wins it") {
    const std::vector<fs::path> steps = tutorial_steps();
    REQUIRE(steps.size() == 6);
    CHECK(steps.back().filename() == "06_ship.kss");
    std::string script;
    for (const fs::path& step : steps) script += test::read_file(step) + "\n";

    test::ScratchDir dir;
    editor::Editor ed;
    auto report = editor::run_script_text(script, "docs/tutorial/*.kss", dir.path(), ed);
    REQUIRE_MESSAGE(report.ok(), (report.ok() ? std::string() : report.error().str()));
    REQUIRE(report->saved.size() == 1);
    for (const editor::Issue& issue : ed.issues()) { // no error and no warning either
        INFO(issue.message);
        CHECK_MESSAGE(false, "issue on entity ", issue.entity_id);
    }

    // What the tutorial teaches: a trigger, a spawner, a locked door that an objective unlocks, two
    // objectives.
    const level::Level& lv = ed.level();
    auto count = [&](level::EntityType type) {
        return std::count_if(lv.entities.begin(), lv.entities.end(),
                             [&](const level::Entity& e) { return e.type() == type; });
    };
    CHECK(count(level::EntityType::Trigger) == 1);
    CHECK(count(level::EntityType::Spawner) == 1);
    CHECK(count(level::EntityType::Door) == 1);
    REQUIRE(lv.objectives.size() == 2);
    CHECK(lv.objectives[0].kill == std::vector<std::string>{"Robot_pen"});
    const auto door = std::find_if(lv.entities.begin(), lv.entities.end(),
                                   [](const level::Entity& e) { return e.name == "Exit_door"; });
    REQUIRE(door != lv.entities.end());
    CHECK(door->as<level::DoorProps>().locked);

    const fs::path campaign_file = dir / "campaign.json";
    auto campaign = level::load_campaign(campaign_file);
    REQUIRE_MESSAGE(campaign.ok(), (campaign.ok() ? std::string() : campaign.error().str()));
    REQUIRE(campaign->levels.size() == 1);
    CHECK(campaign->levels[0].title == "The Warehouse");
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
        CAPTURE(seed);
        game::HeadlessOptions o;
        o.level = level::campaign_level_path(campaign_file, campaign->levels[0]);
        o.seconds = 120.0;
        o.seed = seed;
        o.autoplay = true;
        auto stats = game::run_headless(o);
        REQUIRE_MESSAGE(stats.ok(), (stats.ok() ? std::string() : stats.error().str()));
        MESSAGE("tutorial seed " << seed << ": " << stats->summary());
        CHECK(stats->outcome == "win");
        CHECK(stats->robots_killed == 3); // the spawner's three: the objective needs them dead
    }
}
