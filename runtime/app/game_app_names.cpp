// The game app's command-line vocabulary (options, flags; the --screen names are
// runtime/model/screen_table.h's).
#include "game_app_internal.h"

namespace ks::runtime {

const std::vector<std::string>& game_app_options() {
    static const std::vector<std::string> names = {
        "level",     "dojo",     "screen",      "warp",        "dojo-key",    "dojo-time",
        "seed",      "msaa",     "help",        "fire",        "status-file", "input-script",
        "audio-out", "campaign", "logic-trace", "logic-break", "difficulty", "target-fps"};
    return names;
}
const std::vector<std::string>& game_app_flags() {
    static const std::vector<std::string> flags = {"dojo", "help", "fire"};
    return flags;
}

} // namespace ks::runtime
