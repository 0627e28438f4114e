// File > Add to Campaign (model/campaign_add.h) and the script's `campaign add` / `expect campaign`: the
// open, saved level goes to the end of a campaign file, by a path relative to the campaign's folder;
// untitled, unsaved and erroneous levels and duplicates are refused with a message and leave the campaign
// unchanged.
#include "editor_test_util.h"
#include "model/edit_entities.h"
#include "model/edit_files.h"
#include "model/edit_logic.h"

#include "level/campaign.h"
#include "model/campaign_add.h"
#include "model/script.h"

#include <fstream>

using namespace ks;
using namespace ks::editor;
namespace fs = std::filesystem;

namespace {

// Builds the two-room level and saves it at `file`.
void build_and_save(Editor& ed, const fs::path& file) {
    auto built = run_script_text(editor_test::kTwoRoomScript, "two_rooms.kss", file.parent_path(), ed);
    REQUIRE_MESSAGE(built.ok(), (built.ok() ? std::string() : built.error().str()));
    fs::create_directories(file.parent_path());
    auto saved = save_as(ed, file);
    REQUIRE_MESSAGE(saved.ok(), (saved.ok() ? std::string() : saved.error().str()));
}

// A campaign in `folder` listing one level that exists.
fs::path one_level_campaign(const fs::path& folder) {
    fs::create_directories(folder);
    const fs::path first = folder / "first.json";
    level::Level level;
    level.name = "First";
    REQUIRE(level::save_level_file(first, level).ok());
    const fs::path file = folder / "campaign.json";
    REQUIRE(level::save_campaign({"Test campaign", {{"first.json", "First Light"}}}, file).ok());
    return file;
}

std::string error_of(const Result<CampaignAddReport>& r) {
    return r.ok() ? std::string("(no error)") : r.error().str();
}

} // namespace

TEST_CASE("add to campaign: the saved level becomes the campaign's next level, relative to its folder") {
    test::ScratchDir dir;
    const fs::path campaign = one_level_campaign(dir / "campaigns");
    Editor ed;
    build_and_save(ed, dir / "mine" / "two rooms.json");

    auto added = add_to_campaign(ed, campaign);
    REQUIRE_MESSAGE(added.ok(), error_of(added));
    CHECK(added->position == 2);
    CHECK(added->file == "../mine/two rooms.json");
    CHECK(added->title == "Two rooms"); // the level's name by default
    CHECK_FALSE(added->created);
    auto loaded = level::load_campaign(campaign);
    REQUIRE_MESSAGE(loaded.ok(), (loaded.ok() ? std::string() : loaded.error().str()));
    CHECK(loaded->name == "Test campaign");
    REQUIRE(loaded->levels.size() == 2);
    CHECK(loaded->levels[0].title == "First Light");
    CHECK(loaded->levels[1].file == "../mine/two rooms.json");
    CHECK(fs::equivalent(level::campaign_level_path(campaign, loaded->levels[1]),
                         dir / "mine" / "two rooms.json"));

    // Listed once: a second add, however the campaign path is spelled, is refused and changes nothing.
    const std::string before = test::read_file(campaign);
    auto again = add_to_campaign(ed, dir / "mine" / ".." / "campaigns" / "campaign.json", "Again");
    REQUIRE_FALSE(again.ok());
    CHECK(error_of(again).find("already in") != std::string::npos);
    CHECK(error_of(again).find("as level 2 (\"Two rooms\")") != std::string::npos);
    CHECK(test::read_file(campaign) == before);
}

TEST_CASE("add to campaign: a title given, a level in the campaign's folder, a campaign file started") {
    test::ScratchDir dir;
    Editor ed;
    build_and_save(ed, dir / "levels" / "two.json");
    auto added = add_to_campaign(ed, dir / "levels" / "my_run.json", "The Second Room");
    REQUIRE_MESSAGE(added.ok(), error_of(added));
    CHECK(added->created);
    CHECK(added->position == 1);
    CHECK(added->file == "two.json");
    auto loaded = level::load_campaign(dir / "levels" / "my_run.json");
    REQUIRE(loaded.ok());
    CHECK(loaded->name == "my_run");
    REQUIRE(loaded->levels.size() == 1);
    CHECK(loaded->levels[0].title == "The Second Room");
}

TEST_CASE("add to campaign: refuses untitled, unsaved and erroneous levels and a broken campaign file") {
    test::ScratchDir dir;
    const fs::path campaign = one_level_campaign(dir.path());
    const std::string before = test::read_file(campaign);
    Editor ed;

    auto untitled = add_to_campaign(ed, campaign);
    REQUIRE_FALSE(untitled.ok());
    CHECK(error_of(untitled).find("untitled") != std::string::npos);
    CHECK(error_of(untitled).find("Save As") != std::string::npos);

    build_and_save(ed, dir / "two.json");
    REQUIRE(place(ed, level::EntityType::Pickup, Vec3(0.0f, 0.0f, 12.0f)).ok());
    auto unsaved = add_to_campaign(ed, campaign);
    REQUIRE_FALSE(unsaved.ok());
    CHECK(error_of(unsaved).find("unsaved changes") != std::string::npos);

    // A link to a target that does not exist is a design error: saved as a draft, it should not ship.
    REQUIRE(link_add(ed, LinkOwner::level(), {"on_start", "Nobody", "open"}).ok());
    REQUIRE(save(ed).ok());
    auto draft = add_to_campaign(ed, campaign);
    REQUIRE_FALSE(draft.ok());
    CHECK(error_of(draft).find("design error") != std::string::npos);
    CHECK(test::read_file(campaign) == before);

    ed.undo();
    REQUIRE(save(ed).ok());
    std::ofstream(campaign) << R"({"name": "Broken", "levels": [{"file": "gone.json", "title": "Gone"}]})";
    auto broken = add_to_campaign(ed, campaign);
    REQUIRE_FALSE(broken.ok());
    CHECK(error_of(broken).find("gone.json") != std::string::npos);

    auto no_file = add_to_campaign(ed, fs::path());
    REQUIRE_FALSE(no_file.ok());
    CHECK(error_of(no_file).find("no campaign file") != std::string::npos);
}

TEST_CASE("script: campaign add and expect campaign") {
    test::ScratchDir dir;
    one_level_campaign(dir.path());
    Editor ed;
    const std::string script = std::string(editor_test::kTwoRoomScript) +
                               "save two.json\n"
                               "expect campaign campaign.json 1\n"
                               "campaign add campaign.json title Two Rooms, Shipped\n"
                               "expect campaign campaign.json 2\n";
    auto run = run_script_text(script, "ship.kss", dir.path(), ed);
    REQUIRE_MESSAGE(run.ok(), (run.ok() ? std::string() : run.error().str()));
    auto loaded = level::load_campaign(dir / "campaign.json");
    REQUIRE(loaded.ok());
    REQUIRE(loaded->levels.size() == 2);
    CHECK(loaded->levels[1].file == "two.json");
    CHECK(loaded->levels[1].title == "Two Rooms, Shipped");

    // A duplicate fails the line, naming it; a wrong count fails the expectation.
    Editor ed2;
    auto twice = run_script_text(std::string(editor_test::kTwoRoomScript) +
                                     "save two.json overwrite\ncampaign add campaign.json\n",
                                 "twice.kss", dir.path(), ed2);
    REQUIRE_FALSE(twice.ok());
    CHECK(twice.error().str().find("already in") != std::string::npos);
    auto count = run_script_text("expect campaign campaign.json 5\n", "count.kss", dir.path(), ed2);
    REQUIRE_FALSE(count.ok());
    CHECK(count.error().str().find("lists 2 level(s), expected 5") != std::string::npos);

    // Syntax errors before anything runs.
    for (const char* bad :
         {"campaign\n", "campaign ship campaign.json\n", "campaign add\n", "campaign add c.json name X\n",
          "campaign add c.json title\n", "expect campaign c.json\n", "expect campaign c.json many\n"}) {
        INFO(bad);
        CHECK_FALSE(parse_script(bad, "bad.kss").ok());
    }
}
