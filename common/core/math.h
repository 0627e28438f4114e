#pragma once
// The math vocabulary shared by every module: GLM types under short names, plus the few helpers that
// several modules need. Angles are radians in code; level files store degrees.
#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <numbers>

namespace ks {

using Vec2 = glm::vec2;
using Vec3 = glm::vec3;
using Vec4 = glm::vec4;
using Mat3 = glm::mat3;
using Mat4 = glm::mat4;
using Quat = glm::quat;
using DVec3 = glm::dvec3;

inline constexpr float kPi = std::numbers::pi_v<float>;
inline constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

constexpr float radians(float degrees) {
    return degrees * (kPi / 180.0f);
}
constexpr float degrees(float radians) {
    return radians * (180.0f / kPi);
}

// The exact double value of each float component. Why not DVec3(v): GCC 12 at -O3 (its SLP vectorizer)
// folds a double narrowed to float and widened back into the unrounded double for vectorised pairs, so
// DVec3(Vec3(d)) can return d itself (seen: a position of -9999.99995 kept where the float is -10000);
// reading the floats back through volatile memory keeps the rounding.
inline DVec3 exact_double(const Vec3& v) {
    volatile float c[3] = {v.x, v.y, v.z};
    return {c[0], c[1], c[2]};
}

inline bool is_finite(float v) {
    return std::isfinite(v);
}
inline bool is_finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
inline bool is_finite(const Quat& q) {
    return std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z) && std::isfinite(q.w);
}

// Rotation from yaw (about +y), pitch (about +x), roll (about +z), applied roll, then pitch, then yaw
// (radians); the order the level format documents.
inline Quat quat_from_ypr(float yaw, float pitch, float roll) {
    return glm::angleAxis(yaw, Vec3(0, 1, 0)) * glm::angleAxis(pitch, Vec3(1, 0, 0)) *
           glm::angleAxis(roll, Vec3(0, 0, 1));
}

// The same rotation in double precision from degrees, for editing steps that compose rotations (the
// editor's three-axis gizmo) and must not drift.
glm::dquat dquat_from_ypr_degrees(const DVec3& yaw_pitch_roll);
// The inverse of quat_from_ypr, in degrees: yaw and roll in (-180, 180], pitch in [-90, 90] (every rotation
// has one such triple). At gimbal lock (pitch +-90, where yaw and roll turn about the same axis) roll is 0
// and yaw carries the whole turn. Read through the rotation matrix with atan2 only (no asin), so angles near
// the lock stay accurate.
DVec3 ypr_degrees_from_quat(const glm::dquat& rotation);

} // namespace ks
