#include "physics/movement.h"

#include <algorithm>
#include <cmath>

namespace ks::physics {

bool sanitize(MovementState& s) {
    bool changed = false;
    auto fix = [&](float& v) {
        if (!std::isfinite(v)) v = 0.0f, changed = true;
    };
    for (int i = 0; i < 3; ++i) fix(s.velocity[i]), fix(s.acceleration[i]);
    fix(s.gravity);
    if (!std::isfinite(s.max_speed) || s.max_speed <= 0.0f) s.max_speed = 1e4f, changed = true;
    return changed;
}

Vec3 integrate(MovementState& s, float dt) {
    const Vec3 a = s.acceleration + Vec3(0.0f, s.gravity, 0.0f);
    const Vec3 v0 = s.velocity;
    Vec3 v1 = v0 + a * dt;
    // Exact for constant acceleration: the average of the two velocities over the step.
    Vec3 displacement = (v0 + v1) * (0.5f * dt);
    // Speed cap, horizontal and vertical separately (a fall is capped without slowing a run).
    const float h = std::sqrt(v1.x * v1.x + v1.z * v1.z);
    if (h > s.max_speed) v1.x *= s.max_speed / h, v1.z *= s.max_speed / h;
    v1.y = std::clamp(v1.y, -s.max_speed, s.max_speed);
    const float hd = std::sqrt(displacement.x * displacement.x + displacement.z * displacement.z);
    const float cap = s.max_speed * dt;
    if (hd > cap) displacement.x *= cap / hd, displacement.z *= cap / hd;
    displacement.y = std::clamp(displacement.y, -cap, cap);
    s.velocity = v1;
    return displacement;
}

} // namespace ks::physics
