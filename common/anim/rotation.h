#pragma once
// Rotation conversions and interpolation the clips need. Clip keys are Euler XYZ angles interpolated per
// component, as Tween.js does, so a 4*pi head spin is two turns and not the identity a quaternion would make
// of it; poses hand quaternions to the renderer. Quaternion tracks (shortest-path slerp) are for tools.
#include "anim/easing.h"
#include "core/math.h"

#include <span>
#include <vector>

namespace ks::anim {

// three.js Euler order 'XYZ' (intrinsic X, then Y, then Z): R = Rx * Ry * Rz.
Quat euler_xyz_to_quat(const Vec3& euler);
// The inverse (three.js Euler.setFromRotationMatrix, order 'XYZ'); y in [-pi/2, pi/2].
Vec3 quat_to_euler_xyz(const Quat& q);
// The same angle moved into (-pi, pi]; the rotation about that axis is unchanged.
float wrap_angle(float radians);
// The angle of the rotation taking a to b, in [0, pi] (sign of the quaternions ignored).
float angle_between(const Quat& a, const Quat& b);

// Spherical interpolation along the shorter arc, computed in double and renormalised, so the result is unit
// length and never flips to the long way round when a and b lie in opposite hemispheres.
Quat slerp_shortest(const Quat& a, const Quat& b, float t);

// A keyframed quaternion track: keys at increasing times, each eased into the next along the shortest arc.
struct QuatKey {
    float time = 0;
    Quat value{1, 0, 0, 0};
    Ease ease; // easing from this key to the next
};
class QuatTrack {
  public:
    QuatTrack() = default;
    explicit QuatTrack(std::vector<QuatKey> keys);
    std::span<const QuatKey> keys() const { return keys_; }
    float duration() const { return keys_.empty() ? 0.0f : keys_.back().time; }
    // Before the first key: the first value; after the last: the last value.
    Quat sample(float time) const;

  private:
    std::vector<QuatKey> keys_;
};

} // namespace ks::anim
