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

// Parses a save; nullopt with the problem in `problem` ("levels[1].seconds: ...") when it cannot be used.
inline std::optional<CampaignSave> campaign_save_from_json(const std::string& text, std::string& problem) {
    auto j = nlohmann::json::parse(text, nullptr, false);
    if (j.is_discarded() || !j.is_object()) {
        problem = "not a JSON object";
        return std::nullopt;
    }
    if (!j.contains("format") || j["format"] != "killswitch-campaign-save") {
        problem = "format: expected \"killswitch-campaign-save\"";
        return std::nullopt;
    }
    CampaignSave s;
    if (!j.contains("campaign") || !j["campaign"].is_string() || j["campaign"].get<std::string>().empty()) {
        problem = "campaign: expected the campaign file's path";
        return std::nullopt;
    }
    s.campaign = j["campaign"].get<std::string>();
    if (j.contains("name") && j["name"].is_string()) s.name = j["name"].get<std::string>();
    constexpr double kMaxCount = 10000.0;
    auto count = [&](const nlohmann::json& v, double hi, double& out) {
        if (!v.is_number()) return false;
        out = v.get<double>();
        return std::isfinite(out) && out >= 0.0 && out <= hi;
    };
    double n = 0.0;
    if (!j.contains("level_count") || !count(j["level_count"], kMaxCount, n) || n < 1.0) {
        problem =
            "level_count: expected a number of levels in 1.." + std::to_string(static_cast<int>(kMaxCount));
        return std::nullopt;
    }
    s.level_count = static_cast<std::size_t>(n);
    if (!j.contains("levels") || !j["levels"].is_array() || j["levels"].size() > s.level_count) {
        problem = "levels: expected a list of at most level_count won levels";
        return std::nullopt;
    }
    for (std::size_t i = 0; i < j["levels"].size(); ++i) {
        const auto& l = j["levels"][i];
        const std::string where = "levels[" + std::to_string(i) + "]";
        if (!l.is_object()) {
            problem = where + ": expected an object";
            return std::nullopt;
        }
        LevelResult r;
        if (l.contains("title") && l["title"].is_string()) r.title = l["title"].get<std::string>();
        double seconds = 0.0, killed = 0.0, total = 0.0, shots = 0.0, hits = 0.0;
        const struct {
            const char* key;
            double hi;
            double* out;
        } fields[] = {{"seconds", 1.0e7, &seconds},
                      {"robots_killed", 1.0e6, &killed},
                      {"robots_total", 1.0e6, &total},
                      {"shots", 1.0e9, &shots},
                      {"hits", 1.0e9, &hits}};
        for (const auto& f : fields)
            if (!l.contains(f.key) || !count(l[f.key], f.hi, *f.out)) {
                problem = where + "." + f.key + ": expected a number in 0.." +
                          std::to_string(static_cast<long long>(f.hi)) +
                          (l.contains(f.key) ? ", got " + l[f.key].dump() : ", missing");
                return std::nullopt;
            }
        r.seconds = seconds;
        r.robots_killed = static_cast<int>(killed);
        r.robots_total = static_cast<int>(total);
        r.shots = static_cast<int>(shots);
        r.hits = static_cast<int>(hits);
        s.won.push_back(std::move(r));
    }
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
    std::string problem;
    auto save = campaign_save_from_json(*text, problem);
    if (!save)
        log::warn(path.string(), ": ", problem,
                  " - the saved campaign progress is ignored (the file is kept; fix it, or a new campaign "
                  "replaces it)");
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
