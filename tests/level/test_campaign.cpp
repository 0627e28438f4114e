// Campaign files (level/campaign.h): the shipped campaign, save -> load round trips, and every malformed
// case giving one clear report naming file, line:column, JSON path and fix.
#include "core/files.h"
#include "core/log.h"
#include "core/paths.h"
#include "jsonio/bad_documents.h"
#include "level/campaign.h"
#include "level/level_io.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <cstdlib>
#include <string>
#include <vector>

using namespace ks;
using namespace ks::level;
namespace fs = std::filesystem;

namespace {

// A scratch folder holding two level files (their content does not matter to the campaign loader).
struct CampaignFolder {
    test::ScratchDir dir;
    CampaignFolder() {
        for (const char* name : {"first.json", "second.json"})
            REQUIRE(files::write_atomic(dir / name, "{}").ok());
        fs::create_directories(dir / "more");
        REQUIRE(files::write_atomic(dir / "more" / "third.json", "{}").ok());
    }
    fs::path write(const std::string& text) const {
        const fs::path file = dir / "campaign.json";
        REQUIRE(files::write_atomic(file, text).ok());
        return file;
    }
};

// The report of a file that must fail to load, as one string.
std::string failure_of(const CampaignFolder& folder, const std::string& text) {
    const fs::path file = folder.write(text);
    Result<Campaign> campaign = load_campaign(file);
    REQUIRE_FALSE(campaign.ok());
    CHECK(campaign.error().where.file == file.string());
    return campaign.error().str();
}

void check_contains(const std::string& report, const std::vector<std::string>& expected) {
    for (const std::string& part : expected) CHECK_MESSAGE(report.find(part) != std::string::npos, report);
}

} // namespace

TEST_CASE("campaign: every bad document is refused with its line:column, as in every file kind") {
    CampaignFolder folder;
    for (const test::BadDocument& bad : test::bad_documents()) {
        CAPTURE(bad.name);
        const std::string report = failure_of(folder, bad.text);
        check_contains(report, {"campaign.json" + bad.place + bad.message});
    }
}

TEST_CASE("campaign: the shipped campaign loads, starts with the main level, and every level loads cleanly") {
    const fs::path file = test::source_dir() / "levels" / "campaign.json";
    Result<Campaign> campaign = load_campaign(file);
    REQUIRE_MESSAGE(campaign.ok(), campaign.error().str());
    CHECK(campaign->name == "Killswitch");
    REQUIRE_FALSE(campaign->levels.empty());
    CHECK(campaign->levels[0].file == "main.json");
    CHECK(campaign->levels[0].title == "The Simulation");
    for (const CampaignLevel& level : campaign->levels) {
        CHECK(campaign_level_path(file, level) == test::source_dir() / "levels" / level.file);
        Result<Level> loaded = load_level_file(campaign_level_path(file, level));
        CHECK_MESSAGE(loaded.ok(), (loaded.ok() ? "" : loaded.error().str()));
    }
    // The shipped file is in the writer's form, so the editor can save it without a diff.
    CHECK(save_campaign_string(*campaign) == test::read_file(file));
}

TEST_CASE("campaign: save then load gives the same campaign, byte-identical on a second save") {
    CampaignFolder folder;
    const Campaign campaign{"Test \"run\"", {{"first.json", "One"}, {"more/third.json", "Three: ünïcode"}}};
    const fs::path file = folder.dir / "saved.json";
    REQUIRE(save_campaign(campaign, file).ok());
    Result<Campaign> loaded = load_campaign(file);
    REQUIRE_MESSAGE(loaded.ok(), loaded.error().str());
    CHECK(loaded->name == campaign.name);
    REQUIRE(loaded->levels.size() == 2);
    CHECK(loaded->levels[1].file == "more/third.json");
    CHECK(loaded->levels[1].title == "Three: ünïcode");
    CHECK(campaign_level_path(file, loaded->levels[1]) == folder.dir / "more" / "third.json");
    CHECK(save_campaign_string(*loaded) == test::read_file(file));
}

TEST_CASE("campaign: save refuses what load would refuse and leaves the file alone") {
    CampaignFolder folder;
    const fs::path file = folder.dir / "kept.json";
    REQUIRE(files::write_atomic(file, "kept").ok());
    struct Case {
        Campaign campaign;
        std::string expected;
    };
    const std::vector<Case> cases = {
        {{"", {{"first.json", "One"}}}, "name: the campaign has no name"},
        {{"C", {}}, "levels: the campaign lists no levels"},
        {{"C", {{"", "One"}}}, "levels[0].file: the level file is empty"},
        {{"C", {{"first.json", " "}}}, "levels[0].title: the level has no title"},
        {{"C", {{"/abs/first.json", "One"}}},
         "levels[0].file: level file \"/abs/first.json\" is an absolute path"},
        {{"C", {{"first.json", "One"}, {"./first.json", "Again"}}},
         "levels[1].file: level \"./first.json\" is listed twice (also levels[0])"},
    };
    for (const Case& c : cases) {
        Result<void> saved = save_campaign(c.campaign, file);
        REQUIRE_FALSE(saved.ok());
        CHECK_MESSAGE(saved.error().str().find(c.expected) != std::string::npos, saved.error().str());
        CHECK(test::read_file(file) == "kept");
    }
    // A level file that does not exist yet is fine to save (the level may be saved next).
    CHECK(save_campaign({"C", {{"later.json", "Later"}}}, file).ok());
}

TEST_CASE("campaign: a missing or unreadable campaign file names the file") {
    test::ScratchDir dir;
    Result<Campaign> missing = load_campaign(dir / "nope.json");
    REQUIRE_FALSE(missing.ok());
    CHECK(missing.error().where.file == (dir / "nope.json").string());
    Result<Campaign> folder = load_campaign(dir.path());
    REQUIRE_FALSE(folder.ok());
}

TEST_CASE("campaign: malformed files give every problem with file, line:column, path and fix") {
    CampaignFolder folder;
    const std::string file = (folder.dir / "campaign.json").string();

    SUBCASE("empty") {
        check_contains(failure_of(folder, " \n"), {file + ":1:1: file is empty", "\"levels\""});
    }
    SUBCASE("bad JSON syntax") {
        check_contains(failure_of(folder, "{\n  \"name\": \"C\",\n  \"levels\": [}\n"),
                       {file + ":3:14: JSON syntax error", "fix the JSON syntax"});
    }
    SUBCASE("truncated") {
        check_contains(failure_of(folder, "{\"name\": \"C\", \"levels\": ["),
                       {"file ends early (truncated?)", "complete the file"});
    }
    SUBCASE("not an object") {
        check_contains(failure_of(folder, "[1, 2]"),
                       {file + ":1:1: expected the campaign as a JSON object {...}, found an array"});
    }
    SUBCASE("missing fields") {
        check_contains(failure_of(folder, "{}"), {"2 problems", "name: missing required field \"name\"",
                                                  "levels: missing required field \"levels\""});
        check_contains(failure_of(folder, "{\"name\": \"C\", \"levels\": [\n  {\"file\": \"first.json\"}]}"),
                       {file + ":2:3: levels[0].title: missing required field \"title\"", "summary screen"});
    }
    SUBCASE("wrong types") {
        check_contains(failure_of(folder, "{\"name\": 3,\n\"levels\": {\"file\": \"first.json\"}}"),
                       {":1:2: name: expected a string, found the number 3",
                        ":2:1: levels: expected the levels as an array"});
        check_contains(failure_of(folder, "{\"name\": \"C\", \"levels\": [\"first.json\",\n {\"file\": true, "
                                          "\"title\": \"T\"}]}"),
                       {"levels[0]: expected a level as an object {...}, found the string \"first.json\"",
                        ":2:3: levels[1].file: expected a string, found the boolean true"});
    }
    SUBCASE("empty list, empty name, empty title") {
        check_contains(failure_of(folder, "{\"name\": \"\", \"levels\": []}"),
                       {"name: the campaign has no name", "levels: the campaign lists no levels"});
        check_contains(
            failure_of(folder,
                       "{\"name\": \"C\", \"levels\": [{\"file\": \"first.json\", \"title\": \"\"}]}"),
            {"levels[0].title: the level has no title"});
    }
    SUBCASE("unknown fields are warnings, with did-you-mean, as in every file") {
        const fs::path path = folder.write("{\"name\": \"C\", \"level\": [],\n \"levels\": [{\"file\": "
                                           "\"first.json\", \"titel\": \"T\", \"title\": \"T\"}]}");
        log::Capture capture;
        Result<Campaign> campaign = load_campaign(path);
        REQUIRE(campaign.ok());
        CHECK(campaign->levels.size() == 1);
        check_contains(capture.text(),
                       {file + ":1:15: level: unknown field \"level\" is ignored", "did you mean \"levels\"?",
                        "levels[0].titel: unknown field \"titel\"", "did you mean \"title\"?"});
    }
    SUBCASE("a duplicate key") {
        check_contains(failure_of(folder, "{\"name\": \"C\", \"name\": \"D\", \"levels\": [{\"file\": "
                                          "\"first.json\", \"title\": \"T\"}]}"),
                       {"name: duplicate key (also at line 1:2)"});
    }
    SUBCASE("a level listed twice") {
        check_contains(failure_of(folder,
                                  "{\"name\": \"C\", \"levels\": [\n  {\"file\": \"first.json\", \"title\": "
                                  "\"A\"},\n  {\"file\": \"more/../first.json\", \"title\": \"B\"}]}"),
                       {":3:4: levels[1].file: level \"more/../first.json\" is listed twice (also levels[0])",
                        "remove one"});
    }
    SUBCASE("the same level by two spellings that only the file system can match") {
        const std::string again = "../" + folder.dir.path().filename().string() + "/first.json";
        check_contains(
            failure_of(folder, "{\"name\": \"C\", \"levels\": [\n  {\"file\": \"first.json\", "
                               "\"title\": \"A\"},\n  {\"file\": \"" +
                                   again + "\", \"title\": \"B\"}]}"),
            {":3:4: levels[1].file: level \"" + again + "\" is the same file as levels[0] (\"first.json\")",
             "plays each level once"});
    }
    SUBCASE("the same level by two spellings after entries that could not be read (fuzz finding)") {
        // Entries refused before the two (not objects) are not in the list the check walks: the message
        // must still name the array's indices, and the check must not index that list by them (it read
        // past the end, found by fuzz_campaign_loader: tests/data/fuzz/fuzz_campaign_loader/).
        const std::string again = "../" + folder.dir.path().filename().string() + "/first.json";
        check_contains(
            failure_of(folder, "{\"name\": \"C\", \"levels\": [1, 2, 3,\n  {\"file\": \"first.json\", "
                               "\"title\": \"A\"},\n  {\"file\": \"" +
                                   again + "\", \"title\": \"B\"}]}"),
            {"levels[4].file: level \"" + again + "\" is the same file as levels[3] (\"first.json\")",
             "levels[0]"});
    }
    SUBCASE("a control character in a level's file name") {
        check_contains(
            failure_of(folder, "{\"name\": \"C\", \"levels\": [{\"file\": \"first\\u0007.json\", "
                               "\"title\": \"A\"}]}"),
            {"levels[0].file: level file \"first\\u0007.json\" has a control character in its name"});
    }
    SUBCASE("a missing level file, with did-you-mean among the files beside it") {
        check_contains(failure_of(folder,
                                  "{\"name\": \"C\", \"levels\": [\n  {\"file\": \"frist.json\", \"title\": "
                                  "\"A\"},\n  {\"file\": \"more\", \"title\": \"B\"}]}"),
                       {":2:4: levels[0].file: level file \"frist.json\" not found (looked for " +
                            (folder.dir / "frist.json").string() + ")",
                        "did you mean \"first.json\"?", "relative to the campaign file's folder",
                        "levels[1].file: level file \"more\" is a folder, not a level file"});
    }
    SUBCASE("an absolute level path") {
        check_contains(failure_of(folder, "{\"name\": \"C\", \"levels\": [{\"file\": \"" +
                                              (folder.dir / "first.json").string() +
                                              "\", \"title\": \"A\"}]}"),
                       {"is an absolute path", "relative to the campaign file's folder"});
    }
    SUBCASE("binary garbage never crashes") {
        check_contains(failure_of(folder, std::string("\x89PNG\r\n\x1a\n\0\0", 10)),
                       {":1:1: file is not a text file"});
    }
}

TEST_CASE("campaign: a campaign named relative to the current folder finds its levels and suggests names") {
    CampaignFolder folder;
    const fs::path previous = fs::current_path();
    fs::current_path(folder.dir.path());
    const std::string text = "{\"name\": \"C\", \"levels\": [{\"file\": \"frist.json\", \"title\": \"A\"}]}";
    REQUIRE(files::write_atomic("relative.json", text).ok());
    Result<Campaign> campaign = load_campaign("relative.json");
    fs::current_path(previous);
    REQUIRE_FALSE(campaign.ok());
    check_contains(
        campaign.error().str(),
        {"relative.json:1:27: levels[0].file: level file \"frist.json\" not found (looked for frist.json)",
         "did you mean \"first.json\"?"});
}

TEST_CASE("campaign: the user's levels folder follows XDG_DATA_HOME, else HOME") {
    const char* old_xdg = std::getenv("XDG_DATA_HOME");
    const std::string saved_xdg = old_xdg ? old_xdg : "";
    setenv("XDG_DATA_HOME", "/tmp/xdg-data-test", 1);
    CHECK(paths::user_levels_dir() == fs::path("/tmp/xdg-data-test/killswitch/levels"));
    setenv("XDG_DATA_HOME", "relative/data", 1); // the XDG rule: relative paths are ignored
    if (const char* home = std::getenv("HOME"))
        CHECK(paths::user_levels_dir() == fs::path(home) / ".local" / "share" / "killswitch" / "levels");
    unsetenv("XDG_DATA_HOME");
    if (const char* home = std::getenv("HOME"))
        CHECK(paths::user_levels_dir() == fs::path(home) / ".local" / "share" / "killswitch" / "levels");
    if (old_xdg) setenv("XDG_DATA_HOME", saved_xdg.c_str(), 1);
}
