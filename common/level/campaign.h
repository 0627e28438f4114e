#pragma once
// A campaign: levels played in order, each with the title its summary screen shows. The file is JSON,
// {"name": "Killswitch", "levels": [{"file": "main.json", "title": "The Simulation"}, ...]}, level files
// relative to the campaign file's folder (docs/level-format.md, "Campaign file").
#include "core/result.h"

#include <filesystem>
#include <string>
#include <vector>

namespace ks::level {

struct CampaignLevel {
    std::string file; // relative to the campaign file's folder
    std::string title;
};

struct Campaign {
    std::string name;
    std::vector<CampaignLevel> levels;
};

// Reads and checks a campaign: JSON syntax, required fields and their types, unknown fields (with
// did-you-mean), an empty list, a level listed twice, and level files that do not exist. Every problem is
// reported at once, each naming file, line:column and JSON path, with a fix. Level files are not loaded.
Result<Campaign> load_campaign(const std::filesystem::path& file);
// The same from text; level files are looked up relative to `folder`.
Result<Campaign> load_campaign_string(std::string_view text, const std::string& file_name,
                                      const std::filesystem::path& folder);

// Deterministic JSON, written atomically (core/files). Refuses a campaign that load_campaign would refuse
// for its own content (empty name or list, an empty file or title, a level listed twice, an absolute path);
// whether the level files exist is not checked, so a campaign can be saved before its levels.
Result<void> save_campaign(const Campaign& campaign, const std::filesystem::path& file);
std::string save_campaign_string(const Campaign& campaign);

// Where a campaign's level file is: the campaign file's folder joined with the level's relative path.
std::filesystem::path campaign_level_path(const std::filesystem::path& campaign_file,
                                          const CampaignLevel& level);

} // namespace ks::level
