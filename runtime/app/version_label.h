#pragma once
// The game's version ("Killswitch 0.9.0", from core/version.h) in the main menu's bottom-right corner.
#include "shell/app_shell.h"

namespace ks::runtime {

// Draws the label over the menu's backdrop (the background draw list), `w` x `h` being the window size.
void version_label(const shell::Fonts& fonts, float w, float h);

} // namespace ks::runtime
