#include "view/about_text.h"

#include "core/version.h"

namespace ks::editor {

std::vector<std::string> about_lines() {
    return {
        "Killswitch Editor " + std::string(version::number()),
        "The level editor of Killswitch, a first-person shooter in a virtual disaster simulator:",
        "build levels and their logic, play-test them, let the bot analyse them, edit the robot's clips.",
        "Licence: " + std::string(version::license()) +
            "; the DejaVu fonts keep the Bitstream Vera licence (assets/fonts/LICENSE-DejaVu.txt).",
        "Every other asset is generated from this project's source (assets/generator/).",
    };
}

} // namespace ks::editor
