#pragma once
// Distances in the ground plane (x, z), ignoring height: how far apart things stand on a floor, whatever
// their heights. Walking code (robots, the autoplay bot) measures reach and corners this way.
#include "core/math.h"

#include <algorithm>

namespace ks::geometry {

inline float ground_distance(const Vec3& a, const Vec3& b) {
    return glm::length(Vec2(a.x - b.x, a.z - b.z));
}

// Distance (x, z) from p to the segment a..b.
inline float ground_distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec2 ab(b.x - a.x, b.z - a.z), ap(p.x - a.x, p.z - a.z);
    const float len2 = glm::dot(ab, ab);
    const float t = len2 > 1e-8f ? std::clamp(glm::dot(ap, ab) / len2, 0.0f, 1.0f) : 0.0f;
    return glm::length(ap - t * ab);
}

} // namespace ks::geometry
