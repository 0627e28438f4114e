// Fault injection on every writer the game uses (issue 30, item 4): the campaign file, the campaign save,
// options.json and play-test reports (replay recordings write through the same call from inside the
// game module, whose header is internal). Each goes through files::write_atomic; this proves
// each of them, not just the helper: under a read-only folder, a full disk and a kill before the rename, the
// write fails with an error naming the file, the previous file stays byte for byte and a later write works.
// (Levels, clips and the editor's saves and autosaves: tests/{level,anim,editor}/test_fuzz_regressions.cpp.)
#include "core/files.h"
#include "game/playtest_report.h"
#include "hardening/fault_support.h"
#include "level/campaign.h"
#include "runtime/model/campaign_save.h"
#include "runtime/model/options.h"
#include "test_support.h"

#include <doctest/doctest.h>

#include <functional>
#include <string>
#include <vector>

using namespace ks;
namespace fs = std::filesystem;

namespace {

struct Writer {
    std::string what;
    std::string file_name;
    // Writes version `n` of the file (each version's bytes differ).
    std::function<Result<void>(const fs::path&, int)> write;
};

std::vector<Writer> writers() {
    return {
        {"campaign file", "campaign.json",
         [](const fs::path& path, int n) {
             return level::save_campaign({"Campaign " + std::to_string(n), {{"first.json", "One"}}}, path);
         }},
        {"campaign save", "campaign_save.json",
         [](const fs::path& path, int n) {
             runtime::CampaignSave save;
             save.campaign = path.parent_path() / "campaign.json";
             save.name = "Campaign " + std::to_string(n);
             save.level_count = 3;
             return runtime::write_campaign_save(path, save);
         }},
        {"options", "options.json",
         [](const fs::path& path, int n) {
             runtime::Options options;
             options.fov_degrees = 60.0f + static_cast<float>(n);
             return runtime::save_options(path, options);
         }},
        {"play-test report", "report.json",
         [](const fs::path& path, int n) {
             game::PlaytestReport report;
             report.level = "level" + std::to_string(n) + ".json";
             return game::save_playtest_report(path, report);
         }},
    };
}

} // namespace

TEST_CASE("every game writer under every write fault: an error naming the file, the old file intact") {
    for (const Writer& writer : writers()) {
        for (const files::Fault fault : hardening::kSaveFaults) {
            CAPTURE(writer.what);
            CAPTURE(hardening::fault_name(fault));
            test::ScratchDir dir;
            const fs::path path = dir / writer.file_name;
            REQUIRE(writer.write(path, 1).ok());
            const std::string before = test::read_file(path);
            REQUIRE_FALSE(before.empty());
            Result<void> failed = ok();
            {
                hardening::FaultGuard guard(fault);
                failed = writer.write(path, 2);
            }
            REQUIRE_FALSE(failed.ok());
            const std::string message = failed.error().str();
            CHECK_MESSAGE(message.find(path.string()) != std::string::npos, message);
            CHECK_MESSAGE(message.find("previous file was left untouched") != std::string::npos, message);
            CHECK(test::read_file(path) == before);
            // A kill before the rename leaves its temporary file, as a real kill would; the others clean up.
            CHECK(hardening::leftover_temp_files(dir.path()) ==
                  (fault == files::Fault::BeforeRename ? 1 : 0));
            // The next write, with the fault gone, goes through.
            REQUIRE(writer.write(path, 3).ok());
            CHECK(test::read_file(path) != before);
        }
    }
}
