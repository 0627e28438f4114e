#pragma once
// The first-person weapon's camera-space transform: the reference's rest placement (camera-local
// (0.3, -0.25, -1), Euler (0.05, pi/14, 0)) plus a recoil kick driven by `recoil` in 0..1 (1 = the shot's
// peak), which the game animates after each shot.
#include "core/math.h"

namespace ks::render {

Mat4 rifle_view_transform(float recoil);

} // namespace ks::render
