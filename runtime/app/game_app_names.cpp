// The game app's command-line vocabulary (options, flags; the --screen names are
// runtime/model/screen_table.h's), and --warp's number list.
#include "game_app_internal.h"

#include <sstream>

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
bool parse_floats(const std::string& text, float* out, int count) {
    std::stringstream ss(text);
    std::string item;
    int n = 0;
    while (std::getline(ss, item, ',')) {
        if (n >= count) return false;
        char* end = nullptr;
        out[n] = std::strtof(item.c_str(), &end);
        if (end == item.c_str() || *end != '\0' || !is_finite(out[n])) return false;
        ++n;
    }
    return n == count;
}

} // namespace ks::runtime
