#include "game/bot_profiles.h"

#include <cmath>

namespace ks::game {

namespace {

// Half the horizontal field of view of the game's default 75-degree vertical one on a 16:9 screen:
// atan(tan(37.5 deg) * 16/9) = 53.7 deg.
const float kViewHalfAngle = std::atan(std::tan(radians(37.5f)) * 16.0f / 9.0f);

AutoplaySettings experienced() {
    AutoplaySettings s;
    s.reaction_time = 0.3f; // a practised simple reaction: the robot is expected
    s.aim_error = 0.015f;
    s.turn_rate = 5.0f;
    s.fire_interval = 0.18f;
    s.view_half_angle = kViewHalfAngle;
    return s;
}

AutoplaySettings new_player() {
    AutoplaySettings s;
    s.reaction_time = 0.5f;  // choice reaction: simple ~0.25 s plus Hick-Hyman's ~0.15 s per bit
    s.aim_error = 0.035f;    // Fitts's effective width 4.133 sd = a robot's width at fighting distance
    s.turn_rate = 1.5f;      // a 90-degree turn onto a robot (~4 bits) at ~4 bits/s of mouse throughput
    s.fire_interval = 0.25f; // an aimed click, not a tap: ~4 a second
    s.look_around = 1.5f;    // stops to look where to go at every new goal
    s.view_half_angle = kViewHalfAngle; // sees only what is on the screen
    return s;
}

} // namespace

const std::vector<std::string>& bot_profile_names() {
    static const std::vector<std::string> names{std::string(kPerfectProfile), "experienced",
                                                std::string(kNewPlayerProfile)};
    return names;
}

Result<AutoplaySettings> bot_profile(std::string_view name, const Location& where) {
    if (name == kPerfectProfile) return AutoplaySettings{};
    if (name == "experienced") return experienced();
    if (name == kNewPlayerProfile) return new_player();
    return Error("unknown bot profile '" + std::string(name) + "'", where,
                 "use perfect, experienced or new-player");
}

} // namespace ks::game
