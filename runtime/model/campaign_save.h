#pragma once
// The campaign's progress on disk, so Campaign > Continue resumes at the next level: which campaign file,
// and each level won so far with its result (time, robots, shots, hits). One file,
// $XDG_DATA_HOME/killswitch/campaign_save.json (else ~/.local/share/killswitch/campaign_save.json), written
// atomically after every level won and when a new campaign starts. A save that does not read (not JSON,
// wrong types, NaN, absurd numbers) is reported with the file and field and ignored — never deleted, so a
// hand-edit gone wrong can be fixed. GL-free and header-only so the tests use it directly.
#include "campaign_progress.h"
#include "core/files.h"
#include "core/log.h"
#include "core/paths.h"
#include "core/result.h"
#include "jsonio/describe.h"
#include "jsonio/document.h"
#include "jsonio/json_path.h"
#include "jsonio/object_reader.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ks::runtime {

struct CampaignSave {
    std::filesystem::path campaign; // the campaign file (absolute)
    std::string name;               // the campaign's name, for the Continue button
    std::size_t level_count = 0;    // levels in the campaign when saved
    std::vector<LevelResult> won;   // the levels won, in order; the next to play is won.size()
    bool finished() const { return level_count > 0 && won.size() >= level_count; }
};

inline std::filesystem::path campaign_save_path() {
    const std::filesystem::path data = paths::user_data_dir();
    return data.empty() ? std::filesystem::path(".killswitch") / "campaign_save.json"
                        : data / "campaign_save.json";
}

inline CampaignSave save_of(const CampaignProgress& p) {
    CampaignSave s;
    std::error_code ec;
    s.campaign = std::filesystem::absolute(p.file(), ec);
    if (ec) s.campaign = p.file();
    s.name = p.campaign().name;
    s.level_count = p.count();
    s.won.assign(p.results().begin(), p.results().end());
    return s;
}

inline std::string campaign_save_to_json(const CampaignSave& s) {
    nlohmann::json j;
    j["format"] = "killswitch-campaign-save";
    j["version"] = 1;
    j["campaign"] = s.campaign.string();
    j["name"] = s.name;
    j["level_count"] = s.level_count;
    nlohmann::json levels = nlohmann::json::array();
    for (const LevelResult& r : s.won)
        levels.push_back({{"title", r.title},
                          {"seconds", r.seconds},
                          {"robots_killed", r.robots_killed},
                          {"robots_total", r.robots_total},
                          {"shots", r.shots},
                          {"hits", r.hits}});
    j["levels"] = levels;
    return j.dump(2) + "\n";
}

// Parses a save with the reader every file shares (jsonio/object_reader.h): nullopt when it has an error.
// Every problem, errors and warnings (an unknown field), is appended to `problems`, each naming the file,
// line:column and field ("campaign_save.json:6:20: levels[1].seconds: -5 is out of range (valid: 0 ..
// 10000000)").
inline std::optional<CampaignSave>
campaign_save_from_json(const std::string& text, std::vector<std::string>& problems,
                        const std::string& file_name = "campaign_save.json") {
    using jsonio::Need;
    using jsonio::Range;
    const jsonio::Document document = jsonio::Document::parse(
        text, file_name,
        {"campaign save",
         "a save is {\"format\": \"killswitch-campaign-save\", \"version\": 1, \"campaign\": ..., "
         "\"level_count\": ..., \"levels\": [...]}; a new campaign replaces it"});
    jsonio::Problems found(file_name, &document.positions());
    document.report_to(found);
    CampaignSave s;
    if (const jsonio::Json* root = document.root()) {
        jsonio::ObjectReader in(*root, "", found, "campaign save");
        std::string format;
        in.choice("format", format, {"killswitch-campaign-save"}, Need::Required);
        in.claim("version");
        std::string campaign;
        if (in.text("campaign", campaign, Need::Required, 0, "the campaign file's path")) {
            if (campaign.empty())
                found.report(jsonio::Severity::Error, "campaign", "the campaign file's path is empty",
                             "start the campaign again from the menu");
            s.campaign = campaign;
        }
        in.text("name", s.name);
        int count = 0;
        const bool counted = in.whole("level_count", count, Range{1, 10000}, Need::Required);
        s.level_count = static_cast<std::size_t>(count);
        const jsonio::Json* levels = in.get("levels", Need::Required, "the levels won, in order");
        in.finish();
        if (levels && (!levels->is_array() || (counted && levels->size() > s.level_count)))
            found.report(jsonio::Severity::Error, "levels",
                         "expected a list of at most level_count (" + std::to_string(s.level_count) +
                             ") won levels, found " + jsonio::describe_value(*levels) +
                             (levels->is_array() ? " of " + std::to_string(levels->size()) : ""),
                         "start the campaign again from the menu");
        else if (levels)
            for (std::size_t i = 0; i < levels->size(); ++i) {
                jsonio::ObjectReader level((*levels)[i], jsonio::element_path("levels", i), found,
                                           "a won level");
                LevelResult r;
                level.text("title", r.title);
                level.number("seconds", r.seconds, Range{0, 1.0e7, "s"}, Need::Required);
                level.whole("robots_killed", r.robots_killed, Range{0, 1.0e6}, Need::Required);
                level.whole("robots_total", r.robots_total, Range{0, 1.0e6}, Need::Required);
                level.whole("shots", r.shots, Range{0, 1.0e9}, Need::Required);
                level.whole("hits", r.hits, Range{0, 1.0e9}, Need::Required);
                level.finish();
                s.won.push_back(std::move(r));
            }
    }
    for (const Error& e : found.errors()) problems.push_back(e.str());
    for (const Error& e : found.warnings()) problems.push_back(e.str());
    if (found.has_errors()) return std::nullopt;
    return s;
}

// Reads the save: nullopt silently when there is none, nullopt with one warning naming the file and the
// field when it does not read (the file is left as it is).
inline std::optional<CampaignSave> load_campaign_save(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return std::nullopt;
    auto text = files::read_text(path);
    if (!text) {
        log::warn(text.error().str(), " (campaign progress not loaded)");
        return std::nullopt;
    }
    std::vector<std::string> problems;
    auto save = campaign_save_from_json(*text, problems, path.string());
    for (const std::string& problem : problems)
        log::warn(problem,
                  save ? ""
                       : " - the saved campaign progress is ignored (the file is kept; fix it, or a new "
                         "campaign replaces it)");
    return save;
}

// Writes the save atomically (temporary file + rename), creating the folder.
inline Result<void> write_campaign_save(const std::filesystem::path& path, const CampaignSave& s) {
    std::error_code ec;
    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), ec);
    if (ec)
        return Error("cannot create the save folder: " + ec.message(), Location(path.parent_path().string()),
                     "check the folder's permissions or set XDG_DATA_HOME");
    return files::write_atomic(path, campaign_save_to_json(s));
}

} // namespace ks::runtime
