#pragma once
// The runtime Dojo's clip list (top right): every clip of the robot's clip file, the keyed ones with their
// digit, the one playing highlighted, what plays and for how long, and how to pick. While the player picks
// (Tab frees the mouse) the rows are buttons: a click plays that clip. A hint line sits at the bottom.
#include "anim/dojo.h"
#include "shell/app_shell.h"

namespace ks::runtime {

// Draws the list; returns the entry of `dojo.entries()` clicked this frame (only while `picking`), or -1.
int dojo_legend(const anim::DojoController& dojo, bool picking, const shell::Fonts& fonts, float w, float h);

} // namespace ks::runtime
