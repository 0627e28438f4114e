#pragma once
// The game's screens in one table: each screen's value, the name `--screen NAME` starts on and the name the
// status file writes (`screen paused`). The two vocabularies differ where the command line names what to do
// (`pause`, `death`, `win`, `play`) and the status file what is shown (`paused`, `dead`, `won`, `playing`),
// and in the separator (`custom-levels` / `custom_levels`); --screen takes either, --help and the manual list
// the command-line names. `dojo` is a start rather than a screen: the Dojo level, playing.
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace ks::runtime {

enum class Screen : unsigned char {
    Loading,
    Menu,
    HowTo,
    Credits,
    Options,
    Controls, // Options > Controls
    CustomLevels,
    CampaignChoice, // Campaign with a saved run: Continue or New campaign
    Playing,
    Paused,
    Dead,
    Won,              // a single level won (Play, a custom level)
    Summary,          // a campaign level won, more to come
    CampaignComplete, // the campaign's last level won
};

struct ScreenNames {
    Screen screen;
    std::string_view command_line; // --screen NAME
    std::string_view status;       // the status file's "screen NAME"
};

// Every screen once, in Screen order.
std::span<const ScreenNames> screen_table();
std::string_view command_line_name(Screen s);
std::string_view status_name(Screen s);

// What --screen asks for: the screen to start on, and whether in the Dojo level.
struct ScreenRequest {
    Screen screen = Screen::Menu;
    bool dojo = false;
    bool operator==(const ScreenRequest&) const = default;
};
inline constexpr std::string_view kDojoScreenName = "dojo";

// A screen's command-line or status name, or "dojo" (playing in the Dojo); nothing for any other word.
std::optional<ScreenRequest> parse_screen_request(std::string_view name);
// The names --screen documents, space-separated: the command-line names, then "dojo".
std::string screen_request_names();

} // namespace ks::runtime
