// The game app's command-line vocabulary (options, flags, --screen names), the screens' names in the status
// file.
#include "game_app_internal.h"

namespace ks::runtime {

const std::vector<std::string>& game_app_options() {
    static const std::vector<std::string> names = {
        "level", "dojo", "screen", "warp",        "dojo-key",     "dojo-time", "seed",
        "msaa",  "help", "fire",   "status-file", "input-script", "audio-out", "campaign"};
    return names;
}
const std::vector<std::string>& game_app_flags() {
    static const std::vector<std::string> flags = {"dojo", "help", "fire"};
    return flags;
}
const std::vector<std::string>& game_app_screens() {
    static const std::vector<std::string> screens = {
        "loading",       "menu",     "howto",          "credits", "options", "pause",
        "death",         "win",      "play",           "dojo",    "summary", "campaign-complete",
        "custom-levels", "controls", "campaign-choice"};
    return screens;
}

const char* screen_name(Screen s) {
    switch (s) {
    case Screen::Loading:
        return "loading";
    case Screen::Menu:
        return "menu";
    case Screen::HowTo:
        return "howto";
    case Screen::Credits:
        return "credits";
    case Screen::Options:
        return "options";
    case Screen::Controls:
        return "controls";
    case Screen::Playing:
        return "playing";
    case Screen::Paused:
        return "paused";
    case Screen::Dead:
        return "dead";
    case Screen::Won:
        return "won";
    case Screen::Summary:
        return "summary";
    case Screen::CampaignComplete:
        return "campaign_complete";
    case Screen::CustomLevels:
        return "custom_levels";
    case Screen::CampaignChoice:
        return "campaign_choice";
    }
    return "?";
}

} // namespace ks::runtime
