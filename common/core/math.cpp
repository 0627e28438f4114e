#include "core/math.h"

#include <numbers>

namespace ks {
namespace {
constexpr double kDegrees = 180.0 / std::numbers::pi;
// Below this cos(pitch) the yaw and roll axes coincide to double precision: the lock.
constexpr double kGimbalLockCos = 1e-9;
} // namespace

glm::dquat dquat_from_ypr_degrees(const DVec3& ypr) {
    const DVec3 r = ypr / kDegrees;
    return glm::angleAxis(r.x, DVec3(0, 1, 0)) * glm::angleAxis(r.y, DVec3(1, 0, 0)) *
           glm::angleAxis(r.z, DVec3(0, 0, 1));
}

DVec3 ypr_degrees_from_quat(const glm::dquat& rotation) {
    // R = Ry(yaw) Rx(pitch) Rz(roll); m[column][row]. Row 1 is (cp sr, cp cr, -sp); column 2 holds
    // (sy cp, -sp, cy cp); with cp = 0, m00 = cos(yaw -+ roll) and m20 = -sin(yaw -+ roll).
    const glm::dmat3 m = glm::mat3_cast(glm::normalize(rotation));
    const double sin_pitch = -m[2][1];
    const double cos_pitch = std::hypot(m[0][1], m[1][1]);
    const double pitch = std::atan2(sin_pitch, cos_pitch);
    double yaw = 0.0, roll = 0.0;
    if (cos_pitch > kGimbalLockCos) {
        yaw = std::atan2(m[2][0], m[2][2]);
        roll = std::atan2(m[0][1], m[1][1]);
    } else {
        yaw = std::atan2(-m[0][2], m[0][0]);
    }
    DVec3 out(yaw * kDegrees, pitch * kDegrees, roll * kDegrees);
    for (int i = 0; i < 3; i += 2)
        if (out[i] <= -180.0) out[i] += 360.0; // atan2 gives [-180, 180]: keep -180 as 180
    return out;
}

} // namespace ks
