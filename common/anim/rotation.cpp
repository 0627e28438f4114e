#include "anim/rotation.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/quaternion.hpp>

namespace ks::anim {

namespace {
// Below this |cos y| the x and z columns hold only the rounding noise of a float quaternion.
constexpr double kGimbalLockCosine = 1e-6;
} // namespace

Quat euler_xyz_to_quat(const Vec3& e) {
    const float c1 = std::cos(e.x * 0.5f), s1 = std::sin(e.x * 0.5f);
    const float c2 = std::cos(e.y * 0.5f), s2 = std::sin(e.y * 0.5f);
    const float c3 = std::cos(e.z * 0.5f), s3 = std::sin(e.z * 0.5f);
    // three.js Quaternion.setFromEuler, case 'XYZ'.
    return Quat(c1 * c2 * c3 - s1 * s2 * s3,  // w
                s1 * c2 * c3 + c1 * s2 * s3,  // x
                c1 * s2 * c3 - s1 * c2 * s3,  // y
                c1 * c2 * s3 + s1 * s2 * c3); // z
}

Vec3 quat_to_euler_xyz(const Quat& q) {
    // In double, and y from atan2 rather than asin: asin loses half the digits next to +-90 degrees.
    const glm::dmat3 m = glm::mat3_cast(glm::normalize(glm::dquat(q.w, q.x, q.y, q.z))); // m[col][row]
    const double m11 = m[0][0], m12 = m[1][0], m13 = m[2][0];
    const double m22 = m[1][1], m23 = m[2][1];
    const double m32 = m[1][2], m33 = m[2][2];
    const double cos_y = std::hypot(m11, m12);
    double x = 0, z = 0;
    const double y = std::atan2(m13, cos_y);
    if (cos_y > kGimbalLockCosine) {
        x = std::atan2(-m23, m33);
        z = std::atan2(-m12, m11);
    } else { // gimbal lock: only x + z (or x - z) is defined; three.js puts it all in x
        x = std::atan2(m32, m22);
    }
    return Vec3(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
}

float wrap_angle(float radians) {
    if (!std::isfinite(radians)) return radians;
    constexpr double two_pi = 2.0 * 3.14159265358979323846;
    const double r = std::remainder(static_cast<double>(radians), two_pi); // in [-pi, pi]
    // Decide the open end after rounding to float: a double just above -pi can round to -kPi.
    const auto f = static_cast<float>(r);
    return f <= -kPi ? static_cast<float>(r + two_pi) : f;
}

float angle_between(const Quat& a, const Quat& b) {
    double d = std::abs(static_cast<double>(a.w) * b.w + static_cast<double>(a.x) * b.x +
                        static_cast<double>(a.y) * b.y + static_cast<double>(a.z) * b.z);
    double na = std::sqrt(double(a.w) * a.w + double(a.x) * a.x + double(a.y) * a.y + double(a.z) * a.z);
    double nb = std::sqrt(double(b.w) * b.w + double(b.x) * b.x + double(b.y) * b.y + double(b.z) * b.z);
    d = std::min(1.0, d / (na * nb));
    // 2*acos(d) loses precision near d = 1; the half-angle from the cross part is accurate there.
    glm::dquat qa(a.w, a.x, a.y, a.z), qb(b.w, b.x, b.y, b.z);
    glm::dquat rel = glm::conjugate(qa / na) * (qb / nb);
    double s = std::sqrt(rel.x * rel.x + rel.y * rel.y + rel.z * rel.z);
    return static_cast<float>(2.0 * std::atan2(s, std::abs(rel.w)));
}

Quat slerp_shortest(const Quat& a, const Quat& b, float t) {
    glm::dquat qa(a.w, a.x, a.y, a.z), qb(b.w, b.x, b.y, b.z);
    qa = glm::normalize(qa);
    qb = glm::normalize(qb);
    double cos_theta = glm::dot(qa, qb);
    if (cos_theta < 0) { // the other sign of b is the same rotation and lies on the shorter arc
        qb = -qb;
        cos_theta = -cos_theta;
    }
    glm::dquat r;
    if (cos_theta > 0.9995) { // nearly parallel: sin(theta) ~ 0, normalised lerp is exact to ~1e-7
        r = glm::normalize(qa * (1.0 - t) + qb * double(t));
    } else {
        double theta = std::acos(std::min(1.0, cos_theta));
        double s = std::sin(theta);
        r = qa * (std::sin((1.0 - t) * theta) / s) + qb * (std::sin(t * theta) / s);
        r = glm::normalize(r);
    }
    return Quat(float(r.w), float(r.x), float(r.y), float(r.z));
}

QuatTrack::QuatTrack(std::vector<QuatKey> keys) : keys_(std::move(keys)) {
    std::stable_sort(keys_.begin(), keys_.end(), [](auto& a, auto& b) { return a.time < b.time; });
}

Quat QuatTrack::sample(float time) const {
    if (keys_.empty()) return Quat(1, 0, 0, 0);
    if (!(time > keys_.front().time)) return keys_.front().value;
    if (time >= keys_.back().time) return keys_.back().value;
    auto next =
        std::upper_bound(keys_.begin(), keys_.end(), time, [](float t, auto& k) { return t < k.time; });
    const QuatKey& k1 = *next;
    const QuatKey& k0 = *(next - 1);
    float span = k1.time - k0.time;
    float u = span > 0 ? (time - k0.time) / span : 1.0f;
    return slerp_shortest(k0.value, k1.value, static_cast<float>(k0.ease(u)));
}

} // namespace ks::anim
