#include "runtime/model/screen_table.h"

#include <array>
#include <cstddef>

namespace ks::runtime {

namespace {
constexpr std::array<ScreenNames, 14> kScreens{{
    {Screen::Loading, "loading", "loading"},
    {Screen::Menu, "menu", "menu"},
    {Screen::HowTo, "howto", "howto"},
    {Screen::Credits, "credits", "credits"},
    {Screen::Options, "options", "options"},
    {Screen::Controls, "controls", "controls"},
    {Screen::CustomLevels, "custom-levels", "custom_levels"},
    {Screen::CampaignChoice, "campaign-choice", "campaign_choice"},
    {Screen::Playing, "play", "playing"},
    {Screen::Paused, "pause", "paused"},
    {Screen::Dead, "death", "dead"},
    {Screen::Won, "win", "won"},
    {Screen::Summary, "summary", "summary"},
    {Screen::CampaignComplete, "campaign-complete", "campaign_complete"},
}};
static_assert(kScreens.back().screen == Screen::CampaignComplete, "one row per Screen, in order");

const ScreenNames& row(Screen s) {
    return kScreens[static_cast<std::size_t>(s)];
}
} // namespace

std::span<const ScreenNames> screen_table() {
    return kScreens;
}

std::string_view command_line_name(Screen s) {
    return row(s).command_line;
}

std::string_view status_name(Screen s) {
    return row(s).status;
}

std::optional<ScreenRequest> parse_screen_request(std::string_view name) {
    if (name == kDojoScreenName) return ScreenRequest{Screen::Playing, true};
    for (const ScreenNames& r : kScreens)
        if (name == r.command_line || name == r.status) return ScreenRequest{r.screen, false};
    return std::nullopt;
}

std::string screen_request_names() {
    std::string names;
    for (const ScreenNames& r : kScreens) names += std::string(r.command_line) + " ";
    return names + std::string(kDojoScreenName);
}

} // namespace ks::runtime
