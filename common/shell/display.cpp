#include "shell/display.h"

#include <cstdlib>

namespace ks::shell {

bool display_available() {
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x11 && *x11) || (wayland && *wayland);
}

std::string no_display_message(const std::string& program) {
    return "No display found (DISPLAY is not set), so " + program +
           " cannot open a window.\n"
           "  On a desktop, run it from a terminal inside the graphical session.\n"
           "  Without one, use a virtual display:  xvfb-run -s \"-screen 0 1280x720x24\" " +
           program +
           " ...\n"
           "  or take a picture without looking:   " +
           program +
           " --screenshot out.png --frames 60 "
           "(under xvfb-run).";
}

} // namespace ks::shell
