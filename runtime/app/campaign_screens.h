#pragma once
// The campaign's screens and the custom level list, in the menus' style (menu_style.h): the summary after a
// campaign level is won, the campaign-complete screen with every level and the totals, and the list of
// levels to play one at a time (the shipped levels/ folder and the player's own, each level with its name,
// a broken file with its error instead of a button).
#include "level/level_catalog.h"
#include "runtime/model/campaign_progress.h"
#include "runtime/model/campaign_save.h"
#include "shell/app_shell.h"

#include <string>
#include <vector>

namespace ks::runtime {

enum class MenuAction;

// Time, robots and accuracy as three tiles across the panel (the summary and the single-level win screen).
void result_tiles(const LevelResult& result, const shell::Fonts& fonts);

// After a campaign level other than the last: its title, "Level N of M", the tiles; Next Level or Main Menu.
MenuAction summary_screen(const CampaignProgress& progress, const shell::Fonts& fonts, float w, float h);
// After the last level: one row per level and the totals; Main Menu.
MenuAction campaign_complete_screen(const CampaignProgress& progress, const shell::Fonts& fonts, float w,
                                    float h);

// Campaign with a saved run: Continue (at the next level, with the levels won so far and their totals) or
// New campaign (replaces the save); Back.
MenuAction campaign_choice_screen(const CampaignSave& save, const shell::Fonts& fonts, float w, float h);

// One folder of the custom level list.
struct LevelGroup {
    std::string title; // "Shipped levels", "Your levels"
    level::LevelFolder folder;
};
// The shipped levels (levels/ without dojo.json and campaign.json) and the player's own levels folder
// (paths::user_levels_dir()), each level loaded for its name or its error.
std::vector<LevelGroup> scan_custom_levels();

// The list; a click on a level that loads returns PlayCustom with `chosen` set to it; Back returns Back.
MenuAction custom_levels_screen(const std::vector<LevelGroup>& groups, const level::LevelFileEntry*& chosen,
                                const shell::Fonts& fonts, float w, float h);

} // namespace ks::runtime
