#include "model/rotation.h"

#include "jsonio/suggest.h"
#include "level/entity_shapes.h"

#include <cmath>
#include <numbers>

namespace ks::editor {
namespace {
// sin/cos of an angle in degrees, exact at multiples of 90 so that quarter turns keep grid positions exact.
void sin_cos_degrees(float degrees, double& s, double& c) {
    const double wrapped = std::fmod(static_cast<double>(degrees), 360.0);
    if (std::fmod(wrapped, 90.0) == 0.0) {
        const int quarter = (static_cast<int>(wrapped / 90.0) + 4) % 4;
        static constexpr double kSin[4] = {0, 1, 0, -1}, kCos[4] = {1, 0, -1, 0};
        s = kSin[quarter];
        c = kCos[quarter];
        return;
    }
    const double r = wrapped * std::numbers::pi / 180.0;
    s = std::sin(r);
    c = std::cos(r);
}

// Angles read back from a quaternion carry rounding noise (89.99999999); a ten-thousandth of a degree is
// far below anything a designer sets and makes quarter turns whole again.
double rounded_degrees(double degrees) {
    const double r = std::round(degrees * 1e4) / 1e4;
    return r == 0.0 ? 0.0 : r; // no -0
}
} // namespace

const char* rotation_space_name(RotationSpace space) {
    return space == RotationSpace::World ? "world" : "local";
}

float wrap_degrees(float degrees) {
    float w = std::fmod(degrees, 360.0f);
    if (w > 180.0f) w -= 360.0f;
    if (w <= -180.0f) w += 360.0f;
    return w;
}

Vec3 turned_ypr(const Vec3& ypr, int axis, float degrees, RotationSpace space) {
    const bool upright = ypr.y == 0.0f && ypr.z == 0.0f;
    if (axis == 1 && (space == RotationSpace::World || upright))
        return {wrap_degrees(ypr.x + degrees), ypr.y, ypr.z};
    if (axis == 2 && space == RotationSpace::Local) return {ypr.x, ypr.y, wrap_degrees(ypr.z + degrees)};
    DVec3 unit(0.0);
    unit[axis] = 1.0;
    const glm::dquat turn = glm::angleAxis(static_cast<double>(degrees) * std::numbers::pi / 180.0, unit);
    const glm::dquat q = dquat_from_ypr_degrees(DVec3(ypr));
    const DVec3 out = ypr_degrees_from_quat(space == RotationSpace::World ? turn * q : q * turn);
    Vec3 result;
    for (int i = 0; i < 3; ++i) result[i] = wrap_degrees(static_cast<float>(rounded_degrees(out[i])));
    return result;
}

DVec3 turned_offset(const DVec3& d, int axis, float degrees) {
    double s = 0, c = 1;
    sin_cos_degrees(degrees, s, c);
    switch (axis) {
    case 0:
        return {d.x, d.y * c - d.z * s, d.y * s + d.z * c};
    case 1: // a growing yaw turns +x toward -z
        return {d.x * c + d.z * s, d.y, -d.x * s + d.z * c};
    default:
        return {d.x * c - d.y * s, d.x * s + d.y * c, d.z};
    }
}

std::string yaw_only_reason(const Document& doc) {
    for (int id : doc.selection) {
        if (id == kPlayerStartId) return "the player start turns about y only (its yaw)";
        const level::Entity* e = doc.level.find(id);
        if (!e || level::keeps_pitch_and_roll(e->type())) continue;
        std::vector<std::string> three_axes;
        for (level::EntityType type : level::all_types())
            if (level::keeps_pitch_and_roll(type)) three_axes.emplace_back(level::type_name(type));
        return std::string(level::type_name(e->type())) + " " + std::to_string(id) +
               " turns about y only (its yaw); these types also pitch and roll: " + jsonio::join(three_axes);
    }
    return {};
}

bool selection_turns_on_three_axes(const Document& doc) {
    return !doc.selection.empty() && yaw_only_reason(doc).empty();
}

} // namespace ks::editor
