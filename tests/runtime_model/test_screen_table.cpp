// The screens' table (runtime/model/screen_table.h): one row per screen in order, names that read back to
// their screen, and --screen taking the command-line name, the status file's name or "dojo".
#include "runtime/model/screen_table.h"

#include <doctest/doctest.h>

#include <set>
#include <string>

using namespace ks::runtime;

TEST_CASE("screen table: every screen once, in order, with names that are unique and read back") {
    const auto table = screen_table();
    REQUIRE(table.size() == static_cast<std::size_t>(Screen::CampaignComplete) + 1);
    std::set<std::string_view> command_line, status;
    for (std::size_t i = 0; i < table.size(); ++i) {
        const ScreenNames& row = table[i];
        CAPTURE(row.command_line);
        CHECK(static_cast<std::size_t>(row.screen) == i);
        CHECK(command_line_name(row.screen) == row.command_line);
        CHECK(status_name(row.screen) == row.status);
        CHECK(command_line.insert(row.command_line).second);
        CHECK(status.insert(row.status).second);
        CHECK(row.command_line != kDojoScreenName);
        CHECK(parse_screen_request(row.command_line) == ScreenRequest{row.screen, false});
        CHECK(parse_screen_request(row.status) == ScreenRequest{row.screen, false});
    }
    // A command-line name is never another screen's status name: either reading is unambiguous.
    for (const ScreenNames& row : table)
        if (status.count(row.command_line)) CHECK(status_name(row.screen) == row.command_line);
}

TEST_CASE("screen table: the names the command line and the status file have always used") {
    CHECK(command_line_name(Screen::Paused) == "pause");
    CHECK(status_name(Screen::Paused) == "paused");
    CHECK(command_line_name(Screen::Playing) == "play");
    CHECK(status_name(Screen::Playing) == "playing");
    CHECK(command_line_name(Screen::Dead) == "death");
    CHECK(status_name(Screen::Dead) == "dead");
    CHECK(command_line_name(Screen::Won) == "win");
    CHECK(status_name(Screen::Won) == "won");
    CHECK(command_line_name(Screen::CampaignComplete) == "campaign-complete");
    CHECK(status_name(Screen::CampaignComplete) == "campaign_complete");
    CHECK(command_line_name(Screen::CustomLevels) == "custom-levels");
    CHECK(status_name(Screen::CustomLevels) == "custom_levels");
    CHECK(status_name(Screen::CampaignChoice) == "campaign_choice");
}

TEST_CASE("--screen: dojo plays in the Dojo; other words are no screen") {
    CHECK(parse_screen_request("dojo") == ScreenRequest{Screen::Playing, true});
    for (const char* bad : {"", "banana", "Pause", "pause ", "paus", "custom levels"}) {
        CAPTURE(bad);
        CHECK_FALSE(parse_screen_request(bad).has_value());
    }
    const std::string names = screen_request_names();
    for (const ScreenNames& row : screen_table())
        CHECK(names.find(std::string(row.command_line)) != std::string::npos);
    CHECK(names.substr(names.size() - 5) == " dojo");
}
