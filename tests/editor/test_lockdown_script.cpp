// levels/lockdown.json is built by the editor script levels/source/lockdown.kss: the script, run into a
// temporary folder, writes the shipped file byte for byte, and the level it builds has no validation issue
// (no error and no warning) and uses the level logic the campaign's second level is meant to show.
#include "editor_test_util.h"

#include "model/script.h"

#include <algorithm>

using namespace ks;
using namespace ks::editor;

TEST_CASE("levels/source/lockdown.kss rebuilds levels/lockdown.json byte for byte, with no issue") {
    const auto source = ks::test::source_dir() / "levels" / "source" / "lockdown.kss";
    const std::string script = ks::test::read_file(source);
    REQUIRE_FALSE(script.empty());
    ks::test::ScratchDir dir;
    std::filesystem::create_directories(dir / "source"); // the script saves to ../lockdown.json
    Editor ed;
    auto report = run_script_text(script, source.string(), dir / "source", ed);
    REQUIRE_MESSAGE(report.ok(), (report.ok() ? std::string() : report.error().str()));
    REQUIRE(report->saved.size() == 1);
    CHECK(std::filesystem::equivalent(report->saved.front(), dir / "lockdown.json"));
    const std::string built = ks::test::read_file(dir / "lockdown.json");
    const std::string shipped = ks::test::read_file(ks::test::source_dir() / "levels" / "lockdown.json");
    CHECK_MESSAGE(built == shipped, "levels/lockdown.json is not what levels/source/lockdown.kss builds: "
                                    "rebuild it with killswitch-editor --script levels/source/lockdown.kss");

    for (const Issue& issue : ed.issues()) {
        INFO(issue.message);
        CHECK_MESSAGE(false, "issue on entity ", issue.entity_id);
    }

    // What the level is for: a trigger that starts the lockdown, spawners, a locked door opened when the
    // hall is clear, messages, and objectives in order.
    const level::Level& lv = ed.level();
    auto count = [&](level::EntityType type) {
        return std::count_if(lv.entities.begin(), lv.entities.end(),
                             [&](const level::Entity& e) { return e.type() == type; });
    };
    CHECK(count(level::EntityType::Trigger) >= 1);
    CHECK(count(level::EntityType::Spawner) >= 1);
    CHECK(count(level::EntityType::Message) >= 1);
    CHECK(count(level::EntityType::Stair) >= 1);
    CHECK(count(level::EntityType::GasCylinder) >= 1);
    CHECK(count(level::EntityType::Pickup) >= 1);
    REQUIRE(lv.objectives.size() >= 2);
    const level::Objective& clear = lv.objectives.front();
    CHECK(std::find(clear.kill.begin(), clear.kill.end(), "West_pen") != clear.kill.end());
    bool unlocks_locked_door = false;
    for (const level::Link& link : clear.links) {
        const auto found = std::find_if(lv.entities.begin(), lv.entities.end(),
                                        [&](const level::Entity& e) { return e.name == link.target; });
        if (link.action == "unlock" && found != lv.entities.end() && found->type() == level::EntityType::Door)
            unlocks_locked_door = found->as<level::DoorProps>().locked;
    }
    CHECK(unlocks_locked_door);
}
