#pragma once
// The shipped levels rebuilt from the reference's tables (/work/shared/reference/seed-facts.md, section 4),
// converted to our conventions. Tests compare levels/main.json and levels/dojo.json with these; running
// the tests with KS_WRITE_SHIPPED_LEVELS=1 writes the files from them (the generator).
#include "level/level.h"

namespace ks::test {

level::Level reference_main_level();
level::Level reference_dojo_level();

// The reference's robots face along their local +X with rotY = -atan2(dz, dx); ours face local -z at yaw 0
// (forward = (-sin yaw, 0, -cos yaw)). The same facing needs yaw = rotY - 90 degrees, kept in (-180, 180].
float robot_yaw_from_reference(float rot_y_radians);

} // namespace ks::test
