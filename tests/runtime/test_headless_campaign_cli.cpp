// `killswitch --headless --campaign FILE`: the CI's proof that a campaign can be won. Exit 0 when every level
// was won, 1 naming the level lost, 2 on bad options or a bad file. Needs no display. Also the logic trace
// options of both modes (--logic-trace, --logic-break), refused before a window would open.
#include "core/files.h"
#include "test_support.h"

#include <doctest/doctest.h>

using namespace ks;

namespace {
test::CommandResult killswitch(const std::string& args) {
    return test::run_command("env -u DISPLAY " + (test::bin_dir() / "killswitch").string() + " " + args);
}
} // namespace

TEST_CASE("headless campaign CLI: every level won exits 0 with a line per level") {
    auto run =
        killswitch("--headless --campaign " + (test::data_dir() / "campaign" / "campaign.json").string() +
                   " --seed 3 --seconds 60");
    INFO(run.output);
    CHECK(run.exit_code == 0);
    CHECK(run.output.find("level 1/2 \"First Light\" (one.json): win after") != std::string::npos);
    CHECK(run.output.find("level 2/2 \"Second Wind\" (two.json): win after") != std::string::npos);
    CHECK(run.output.find("campaign \"Test run\": every level won (2 levels, ") != std::string::npos);
}

TEST_CASE("headless campaign CLI: a lost level exits 1 naming it; bad input exits 2") {
    test::ScratchDir dir;
    REQUIRE(files::write_atomic(dir / "endless.json", R"({"format": "killswitch-level", "version": 2,
  "name": "Endless", "objectives": [{"id": "never", "text": "Wait for nothing"}],
  "entities": [{"id": 1, "type": "floor", "position": [0, 0, 0], "props": {"size": [20, 20]}}]})")
                .ok());
    REQUIRE(files::write_atomic(
                dir / "campaign.json",
                R"({"name": "Stuck", "levels": [{"file": "endless.json", "title": "No Way Out"}]})")
                .ok());
    auto lost = killswitch("--headless --campaign " + (dir / "campaign.json").string() + " --seconds 1");
    INFO(lost.output);
    CHECK(lost.exit_code == 1);
    CHECK(lost.output.find("campaign \"Stuck\": lost level 1 \"No Way Out\" (endless.json): timeout") !=
          std::string::npos);

    REQUIRE(files::write_atomic(dir / "typo.json",
                                R"({"name": "T", "levels": [{"file": "endles.json", "title": "X"}]})")
                .ok());
    auto bad = killswitch("--headless --campaign " + (dir / "typo.json").string());
    INFO(bad.output);
    CHECK(bad.exit_code == 2);
    CHECK(bad.output.find("levels[0].file: level file \"endles.json\" not found") != std::string::npos);
    CHECK(bad.output.find("did you mean \"endless.json\"?") != std::string::npos);

    auto unknown = killswitch("--headless --campaign " + (dir / "campaign.json").string() + " --record x");
    CHECK(unknown.exit_code == 2);
    CHECK(unknown.output.find("unknown option --record for --headless --campaign") != std::string::npos);

    auto help = killswitch("--headless --help");
    CHECK(help.exit_code == 0);
    CHECK(help.output.find("--headless --campaign FILE") != std::string::npos);
}

TEST_CASE(
    "logic trace CLI: --logic-trace - writes the trace to stdout; a bad file or --logic-break exits 2") {
    auto run = killswitch("--headless --autoplay --level " +
                          (test::source_dir() / "levels" / "lockdown.json").string() + " --logic-trace -");
    INFO(run.output);
    CHECK(run.exit_code == 0);
    CHECK(run.output.find("# killswitch logic trace 1: step time kind what source target link") !=
          std::string::npos);
    CHECK(run.output.find(" event on_enter trigger:68:\"Hall entry\" - -") != std::string::npos);

    test::ScratchDir dir;
    const std::string unwritable = (dir / "no_folder" / "run.trace").string();
    for (const std::string mode : {"--headless ", ""}) {
        auto refused = killswitch(mode + "--logic-trace " + unwritable);
        CHECK(refused.exit_code == 2);
        CHECK(refused.output.find(unwritable) != std::string::npos);
    }
    auto bad_break = killswitch("--logic-break 68:on_fly");
    CHECK(bad_break.exit_code == 2);
    CHECK(bad_break.output.find("\"on_fly\" is not an event") != std::string::npos);
}
