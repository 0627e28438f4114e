// Two-bone IK (two_bone_ik.h).
#include "anim/two_bone_ik.h"

#include <algorithm>
#include <cmath>

namespace ks::anim {

namespace {
constexpr float kTiny = 1e-6f;

// The shortest turn taking direction a to direction b (both unit); a half turn about any perpendicular when
// they are opposite.
Quat turn_between(const Vec3& a, const Vec3& b) {
    const float c = std::clamp(glm::dot(a, b), -1.0f, 1.0f);
    const Vec3 axis = glm::cross(a, b);
    const float sine = glm::length(axis);
    if (sine < 1e-6f && c > 0.0f) return Quat(1, 0, 0, 0);
    if (sine < 1e-6f) {
        Vec3 side = glm::cross(a, Vec3(1, 0, 0));
        if (glm::dot(side, side) < 1e-6f) side = glm::cross(a, Vec3(0, 1, 0));
        return glm::angleAxis(3.14159265f, glm::normalize(side));
    }
    return glm::angleAxis(std::atan2(sine, c), axis / sine);
}

// The part of `v` perpendicular to unit `axis`, normalised; `fallback` when there is none.
Vec3 perpendicular(const Vec3& v, const Vec3& axis, const Vec3& fallback) {
    const Vec3 p = v - axis * glm::dot(v, axis);
    const float len = glm::length(p);
    return len > kTiny ? p / len : fallback;
}
} // namespace

TwoBoneSolution solve_two_bone(const Vec3& root, const Vec3& mid, const Vec3& tip, const Vec3& target,
                               const Vec3& pole) {
    TwoBoneSolution s;
    s.mid = mid;
    s.tip = tip;
    const float upper = glm::length(mid - root), lower = glm::length(tip - mid);
    const Vec3 to_target = target - root;
    const float wanted = glm::length(to_target);
    if (upper < kTiny || lower < kTiny || wanted < kTiny) return s;
    const Vec3 dir = to_target / wanted;
    const float shortest = std::abs(upper - lower), longest = upper + lower;
    s.reached = wanted >= shortest && wanted <= longest;
    const float reach = std::clamp(wanted, shortest, longest);
    // The elbow's side: toward the pole, else where the elbow bends now, else any perpendicular.
    const Vec3 now_side = perpendicular(mid - root, dir, perpendicular(Vec3(0, 1, 0), dir, Vec3(1, 0, 0)));
    const Vec3 side = perpendicular(pole - root, dir, now_side);
    const float cos_root =
        std::clamp((upper * upper + reach * reach - lower * lower) / (2 * upper * reach), -1.0f, 1.0f);
    const float sin_root = std::sqrt(std::max(0.0f, 1.0f - cos_root * cos_root));
    s.mid = root + (dir * cos_root + side * sin_root) * upper;
    s.upper = turn_between(glm::normalize(mid - root), glm::normalize(s.mid - root));
    const Vec3 tip_after_upper = root + s.upper * (tip - root);
    const Vec3 end = root + dir * reach;
    s.lower = turn_between(glm::normalize(tip_after_upper - s.mid), glm::normalize(end - s.mid));
    s.tip = s.mid + s.lower * (tip_after_upper - s.mid);
    return s;
}

} // namespace ks::anim
