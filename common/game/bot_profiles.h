#pragma once
// The autoplay bot's skill profiles (`--bot-profile NAME`, the play-test report's profile): "perfect" (the
// bot as CI always ran it: no reaction time, no aim error, a quick flick), "experienced" and "new-player",
// whose reaction time, aim error, turn rate, click rate and look round at a new goal come from published
// human reaction and pointing figures (docs/game.md, "Bot skill profiles", shows the sums).
#include "core/result.h"
#include "game/autoplay.h"

#include <string>
#include <string_view>
#include <vector>

namespace ks::game {

inline constexpr std::string_view kPerfectProfile = "perfect";
inline constexpr std::string_view kNewPlayerProfile = "new-player";

// The profiles' names, the perfect one first.
const std::vector<std::string>& bot_profile_names();
// The bot's settings for profile `name`; another name is an error at `where` listing the profiles.
Result<AutoplaySettings> bot_profile(std::string_view name, const Location& where);

} // namespace ks::game
