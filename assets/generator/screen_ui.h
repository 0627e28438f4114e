#pragma once
// The glowing displays of the control panel: the main "SIMULATION CONTROL" screen and the button desk.
#include "output.h"

namespace ks::assetgen {

struct Display {
    Image basecolor; // what the unlit glass shows (sRGB)
    Image emissive;  // the light it gives (sRGB)
};

Display simulation_control_screen(const Font& font); // 1024 x 512
Display button_desk(const Font& font);               // 512 x 256

} // namespace ks::assetgen
