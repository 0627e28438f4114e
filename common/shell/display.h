#pragma once
// Whether this process can open a window at all, and what to tell the user when it cannot.
#include <string>

namespace ks::shell {

// True when a window can be opened (an X11 or Wayland display is set).
bool display_available();
// The message printed when there is no display: how to run under xvfb-run instead.
std::string no_display_message(const std::string& program);

} // namespace ks::shell
