#pragma once
// "Add to Campaign": ships the open level as the next level of a campaign file, from the editor alone. The
// campaign file is read and written by level/campaign.h (the one home for campaign files); this adds the
// editor's rules: only a saved, titled level without design errors, listed once, by a path relative to the
// campaign's folder. Window-free: the File menu's prompt and the script's `campaign add` both call it.
#include "core/result.h"
#include "model/editor.h"

#include <filesystem>
#include <string>

namespace ks::editor {

// The campaign the prompt offers first: levels/campaign.json, the one the main menu's Campaign plays.
std::filesystem::path default_campaign_file();

struct CampaignAddReport {
    std::filesystem::path campaign_file;
    std::string file;     // as listed: relative to the campaign's folder, with forward slashes
    std::string title;    // as listed
    int position = 0;     // counted from 1: the level's place in the campaign, also its level count now
    bool created = false; // the campaign file did not exist and was started with this level
};

// Appends the editor's level to `campaign_file` under `title` (empty: the level's name). A missing campaign
// file is started, named after its file ("my_campaign.json": "my_campaign"). Refuses, changing nothing: an
// untitled or unsaved level, a level with design errors, a level the campaign already lists, and a
// campaign file that does not load (its errors are passed on).
Result<CampaignAddReport> add_to_campaign(Editor& editor, const std::filesystem::path& campaign_file,
                                          std::string title = {});

} // namespace ks::editor
