#pragma once
// Angle helpers the robots' behaviours share: wrapping, turning at a limited rate, and the level's yaw of a
// direction (0 faces -z).
#include "core/math.h"

#include <algorithm>
#include <cmath>

namespace ks::game {

inline float wrap_angle(float a) {
    return std::remainder(a, 2.0f * kPi);
}

// Turns `yaw` toward `target` by at most `max_step` radians.
inline float turn_toward(float yaw, float target, float max_step) {
    const float d = wrap_angle(target - yaw);
    return wrap_angle(yaw + std::clamp(d, -max_step, max_step));
}

inline float yaw_of(const Vec3& d) {
    return std::atan2(-d.x, -d.z); // level convention: 0 faces -z
}

} // namespace ks::game
