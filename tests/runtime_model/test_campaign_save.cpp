// The campaign save (runtime/model/campaign_save.h, tested without a window): the round trip, a run resumed
// at its next level, corrupt and incomplete files reported with the file and field and ignored but kept, a
// failed write that leaves the old save whole, and where the save and the player's levels live
// (XDG_DATA_HOME set, unset, relative).
#include "core/files.h"
#include "core/log.h"
#include "core/paths.h"
#include "jsonio/bad_documents.h"
#include "runtime/model/campaign_save.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <cstdlib>

using namespace ks;
using namespace ks::runtime;
namespace fs = std::filesystem;

namespace {
level::Campaign three_levels() {
    level::Campaign c;
    c.name = "Training";
    for (const char* t : {"One", "Two", "Three"}) {
        level::CampaignLevel l;
        l.file = std::string(t) + ".json";
        l.title = t;
        c.levels.push_back(l);
    }
    return c;
}

LevelResult result(double seconds, int killed, int total, int shots, int hits) {
    LevelResult r;
    r.seconds = seconds;
    r.robots_killed = killed;
    r.robots_total = total;
    r.shots = shots;
    r.hits = hits;
    return r;
}

// Sets XDG_DATA_HOME for one scope and puts the old value back.
struct DataHome {
    std::string saved;
    bool had = false;
    explicit DataHome(const char* value) {
        if (const char* old = std::getenv("XDG_DATA_HOME")) {
            had = true;
            saved = old;
        }
        if (value)
            setenv("XDG_DATA_HOME", value, 1);
        else
            unsetenv("XDG_DATA_HOME");
    }
    ~DataHome() {
        if (had)
            setenv("XDG_DATA_HOME", saved.c_str(), 1);
        else
            unsetenv("XDG_DATA_HOME");
    }
};
} // namespace

TEST_CASE("campaign save: two levels won, saved, loaded, resumed at the third") {
    test::ScratchDir dir;
    CampaignProgress run(three_levels(), dir / "campaign.json");
    run.record_win(result(61.5, 4, 5, 30, 12));
    REQUIRE(run.advance());
    run.record_win(result(90.25, 7, 7, 20, 19));
    const auto path = dir / "data" / "killswitch" / "campaign_save.json"; // a folder that does not exist yet
    REQUIRE(write_campaign_save(path, save_of(run)).ok());
    log::Capture capture;
    const auto loaded = load_campaign_save(path);
    REQUIRE(loaded.has_value());
    CHECK(capture.text().empty());
    CHECK(loaded->campaign == fs::absolute(dir / "campaign.json"));
    CHECK(loaded->name == "Training");
    CHECK(loaded->level_count == 3);
    CHECK_FALSE(loaded->finished());
    REQUIRE(loaded->won.size() == 2);
    CHECK(loaded->won[1].seconds == doctest::Approx(90.25));
    CHECK(loaded->won[0].robots_killed == 4);
    CHECK(loaded->won[0].robots_total == 5);
    CHECK(loaded->won[1].shots == 20);
    CHECK(loaded->won[1].hits == 19);

    CampaignProgress resumed(three_levels(), loaded->campaign);
    resumed.restore(loaded->won);
    CHECK(resumed.index() == 2);
    CHECK(resumed.current().title == "Three");
    CHECK(resumed.results().size() == 2);
    CHECK(resumed.results()[0].title == "One");
    CHECK(resumed.totals().robots_killed == 11);
    resumed.record_win(result(10, 1, 1, 1, 1));
    CHECK(resumed.finished());
    CHECK(save_of(resumed).finished());
    // More results than levels (the campaign lost a level since): the extra ones are dropped.
    std::vector<LevelResult> many(5, result(1, 0, 0, 0, 0));
    CampaignProgress shorter(three_levels(), dir / "campaign.json");
    shorter.restore(many);
    CHECK(shorter.results().size() == 3);
    CHECK(shorter.index() == 2);
    CHECK(shorter.finished());
    // A new run: nothing won, level 1.
    CampaignProgress fresh(three_levels(), dir / "campaign.json");
    fresh.restore({});
    CHECK(fresh.index() == 0);
}

TEST_CASE("campaign save: a corrupt or incomplete save is reported with the field, ignored and kept") {
    test::ScratchDir dir;
    const auto path = dir / "campaign_save.json";
    const std::string good_level = R"({"title": "A", "seconds": 1, "robots_killed": 1, "robots_total": 2,
                                       "shots": 3, "hits": 1})";
    auto save_text = [&](const std::string& levels, const std::string& extra = "") {
        return R"({"format": "killswitch-campaign-save", "version": 1, "campaign": "/x/campaign.json",
                   "level_count": 3, "levels": )" +
               levels + extra + "}";
    };
    struct Case {
        std::string text;
        const char* expect;
    };
    const Case cases[] = {
        {"{ not json", "JSON syntax error"},
        {"", "file is empty"},
        {R"({"format": "killswitch-options"})", "format: unknown value \"killswitch-options\""},
        {R"({"format": "killswitch-campaign-save", "level_count": 3, "levels": []})",
         "campaign: missing required field"},
        {R"({"format": "killswitch-campaign-save", "campaign": 7, "level_count": 3, "levels": []})",
         "campaign: expected a string, found the number 7"},
        {R"({"format": "killswitch-campaign-save", "campaign": "/x.json", "levels": []})", "level_count"},
        {R"({"format": "killswitch-campaign-save", "campaign": "/x.json", "level_count": -2, "levels": []})",
         "level_count"},
        {R"({"format": "killswitch-campaign-save", "campaign": "/x.json", "level_count": 3})", "levels:"},
        {save_text("[" + good_level + "," + good_level + "," + good_level + "," + good_level + "]"),
         "levels:"},
        {save_text("[7]"), "levels[0]: expected a won level as an object"},
        {save_text(R"([{"title": "A", "seconds": 1, "robots_killed": 1, "robots_total": 2, "shots": 3}])"),
         "levels[0].hits: missing required field \"hits\""},
        {save_text("[" + good_level + R"(, {"seconds": -5, "robots_killed": 1, "robots_total": 2, "shots": 3,
                   "hits": 1}])"),
         "levels[1].seconds"},
        {save_text(R"([{"seconds": 1e300, "robots_killed": 1, "robots_total": 2, "shots": 3, "hits": 1}])"),
         "levels[0].seconds"},
        {save_text(R"([{"seconds": "fast", "robots_killed": 1, "robots_total": 2, "shots": 3, "hits": 1}])"),
         "levels[0].seconds"},
    };
    for (const Case& c : cases) {
        REQUIRE(files::write_atomic(path, c.text).ok());
        log::Capture capture;
        CHECK_FALSE(load_campaign_save(path).has_value());
        const std::string text = capture.text();
        CHECK_MESSAGE(text.find(path.string()) != std::string::npos, c.text);
        CHECK_MESSAGE(text.find(c.expect) != std::string::npos, c.text, " -> ", text);
        CHECK(text.find("ignored") != std::string::npos);
        CHECK(fs::exists(path)); // never deleted
        CHECK(*files::read_text(path) == c.text);
    }
    // A good one with unknown extra fields and no titles reads; the unknown field is a warning, as in every
    // file.
    REQUIRE(files::write_atomic(path, save_text("[" + good_level + "]", R"(, "future": true)")).ok());
    {
        log::Capture warned;
        CHECK(load_campaign_save(path).has_value());
        CHECK(warned.text().find("future: unknown field \"future\" is ignored") != std::string::npos);
    }
    // Every bad document: refused with its line:column.
    for (const test::BadDocument& bad : test::bad_documents()) {
        CAPTURE(bad.name);
        std::vector<std::string> problems;
        CHECK_FALSE(campaign_save_from_json(bad.text, problems, "save.json").has_value());
        std::string all;
        for (const std::string& problem : problems) all += problem + "\n";
        CAPTURE(all);
        CHECK(all.find("save.json" + bad.place + bad.message) != std::string::npos);
    }
    // No file: nothing, silently.
    log::Capture capture;
    CHECK_FALSE(load_campaign_save(dir / "none.json").has_value());
    CHECK(capture.text().empty());
}

TEST_CASE("campaign save: a failed write leaves the old save whole") {
    test::ScratchDir dir;
    const auto path = dir / "campaign_save.json";
    CampaignProgress run(three_levels(), dir / "campaign.json");
    run.record_win(result(5, 1, 1, 1, 1));
    REQUIRE(write_campaign_save(path, save_of(run)).ok());
    const std::string before = *files::read_text(path);
    REQUIRE(run.advance());
    run.record_win(result(6, 2, 2, 2, 2));
    for (files::Fault fault :
         {files::Fault::OpenTemp, files::Fault::ShortWrite, files::Fault::BeforeRename}) {
        files::inject_fault(fault);
        const auto written = write_campaign_save(path, save_of(run));
        files::inject_fault(files::Fault::None);
        CHECK_FALSE(written.ok());
        CHECK(*files::read_text(path) == before);
        const auto loaded = load_campaign_save(path);
        REQUIRE(loaded.has_value());
        CHECK(loaded->won.size() == 1);
    }
    REQUIRE(write_campaign_save(path, save_of(run)).ok());
    CHECK(load_campaign_save(path)->won.size() == 2);
}

TEST_CASE("user data: XDG_DATA_HOME when absolute, else ~/.local/share; the save and levels folder inside") {
    const char* home = std::getenv("HOME");
    const fs::path home_data =
        home && *home ? fs::path(home) / ".local" / "share" / "killswitch" : fs::path();
    {
        DataHome env("/tmp/ks-xdg-data");
        CHECK(paths::user_data_dir() == fs::path("/tmp/ks-xdg-data/killswitch"));
        CHECK(campaign_save_path() == fs::path("/tmp/ks-xdg-data/killswitch/campaign_save.json"));
        CHECK(paths::user_levels_dir() == fs::path("/tmp/ks-xdg-data/killswitch/levels"));
    }
    {
        DataHome env("relative/data"); // the XDG rule: a relative path is ignored
        CHECK(paths::user_data_dir() == home_data);
    }
    {
        DataHome env(""); // empty: as unset
        CHECK(paths::user_data_dir() == home_data);
    }
    {
        DataHome env(nullptr);
        CHECK(paths::user_data_dir() == home_data);
        if (!home_data.empty()) CHECK(campaign_save_path() == home_data / "campaign_save.json");
    }
}

TEST_CASE("user data: the editor's folder for new levels is created on demand") {
    test::ScratchDir dir;
    const std::string root = (dir / "xdg").string();
    DataHome env(root.c_str());
    CHECK_FALSE(fs::exists(dir / "xdg" / "killswitch" / "levels"));
    CHECK(paths::ensure_user_levels_dir() == dir / "xdg" / "killswitch" / "levels");
    CHECK(fs::is_directory(dir / "xdg" / "killswitch" / "levels"));
    CHECK(paths::ensure_user_levels_dir() == dir / "xdg" / "killswitch" / "levels"); // already there
    // A file where the folder should be: no folder, an empty answer (the editor falls back to levels/).
    test::ScratchDir blocked;
    REQUIRE(files::write_atomic(blocked / "killswitch", "not a folder").ok());
    DataHome env2(blocked.path().string().c_str());
    CHECK(paths::ensure_user_levels_dir().empty());
}
