#pragma once
// The sound names of the audio plan (issue #14): the files assets/sounds/<name>.wav that the game plays and
// ks_assetgen writes. Written out here, not taken from the generator, so a sound it stops making is caught.
#include "test_support.h"

#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace ks::test {

inline const std::vector<std::string>& planned_one_shots() {
    static const std::vector<std::string> names = {"rifle_shot",
                                                   "robot_shot",
                                                   "dry_fire",
                                                   "robot_alert",
                                                   "robot_hit",
                                                   "robot_death",
                                                   "robot_explosion",
                                                   "cylinder_explosion",
                                                   "door_open",
                                                   "door_close",
                                                   "light_switch",
                                                   "pickup_health",
                                                   "pickup_ammo",
                                                   "pickup_shield",
                                                   "player_hurt",
                                                   "shield_hit",
                                                   "player_death",
                                                   "jump",
                                                   "land",
                                                   "footstep_floor",
                                                   "footstep_stairs",
                                                   "impact",
                                                   "ui_hover",
                                                   "ui_click",
                                                   "win_sting",
                                                   "door_locked",
                                                   "objective_complete",
                                                   "message_shown"};
    return names;
}

inline const std::vector<std::string>& planned_loops() {
    static const std::vector<std::string> names = {"robot_motor",   "ambient_facility", "ambient_dojo",
                                                   "machine_hum",   "vent_loop",        "alarm_loop",
                                                   "computer_beeps"};
    return names;
}

// The sounds a designer replaced by hand (assets/sounds/designer_sounds.txt): not the generator's, so they
// are neither compared with a fresh run nor held to the generator's levels.
inline std::set<std::string> designer_sounds() {
    const std::filesystem::path file = source_dir() / "assets" / "sounds" / "designer_sounds.txt";
    std::set<std::string> names;
    if (!std::filesystem::exists(file)) return names;
    std::istringstream lines(read_file(file));
    std::string line;
    while (std::getline(lines, line)) {
        std::istringstream words(line.substr(0, line.find('#')));
        std::string name;
        if (words >> name) names.insert(name);
    }
    return names;
}

} // namespace ks::test
