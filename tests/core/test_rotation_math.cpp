// Yaw, pitch, roll back from a rotation (core/math.h): the inverse of quat_from_ypr everywhere, canonical
// (pitch within +-90, yaw and roll within (-180, 180]), and stable at and near gimbal lock.
#include "core/math.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <initializer_list>
#include <utility>

using namespace ks;

namespace {
// Rotations are equal when they turn every axis the same way.
double max_difference(const glm::dquat& a, const glm::dquat& b) {
    const glm::dmat3 ma = glm::mat3_cast(a), mb = glm::mat3_cast(b);
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) worst = std::max(worst, std::abs(ma[c][r] - mb[c][r]));
    return worst;
}
} // namespace

TEST_CASE("yaw, pitch, roll read back from quaternions equal the angles that made them") {
    for (double yaw : {0.0, 30.0, -135.0, 180.0})
        for (double pitch : {0.0, 15.0, -60.0, 89.0})
            for (double roll : {0.0, 45.0, -170.0}) {
                const DVec3 ypr(yaw, pitch, roll);
                const DVec3 back = ypr_degrees_from_quat(dquat_from_ypr_degrees(ypr));
                INFO("ypr " << yaw << " " << pitch << " " << roll << " -> " << back.x << " " << back.y << " "
                            << back.z);
                CHECK(back.x == doctest::Approx(yaw).epsilon(1e-9));
                CHECK(back.y == doctest::Approx(pitch).epsilon(1e-9));
                CHECK(back.z == doctest::Approx(roll).epsilon(1e-9));
            }
    // The float version in the level's order agrees with the double one.
    const Quat f = quat_from_ypr(radians(40.0f), radians(-20.0f), radians(10.0f));
    const glm::dquat d = dquat_from_ypr_degrees(DVec3(40, -20, 10));
    CHECK(max_difference(glm::dquat(f.w, f.x, f.y, f.z), d) < 1e-6);
}

TEST_CASE("angles beyond the canonical ranges come back as the same rotation in them") {
    for (const DVec3 ypr : {DVec3(0, 120, 0), DVec3(200, 10, -190), DVec3(-30, -100, 50), DVec3(720, 0, 0)}) {
        const glm::dquat q = dquat_from_ypr_degrees(ypr);
        const DVec3 back = ypr_degrees_from_quat(q);
        INFO(ypr.x << " " << ypr.y << " " << ypr.z << " -> " << back.x << " " << back.y << " " << back.z);
        CHECK(back.y >= -90.0);
        CHECK(back.y <= 90.0);
        for (int i : {0, 2}) {
            CHECK(back[i] > -180.0);
            CHECK(back[i] <= 180.0);
        }
        CHECK(max_difference(dquat_from_ypr_degrees(back), q) < 1e-12);
    }
    CHECK(ypr_degrees_from_quat(dquat_from_ypr_degrees(DVec3(-180, 0, 0))).x == doctest::Approx(180.0));
}

TEST_CASE("gimbal lock: at pitch +-90 the roll is folded into the yaw, and the rotation is kept") {
    for (double pitch : {90.0, -90.0})
        for (const auto& [yaw, roll] :
             {std::pair{0.0, 0.0}, std::pair{30.0, 20.0}, std::pair{-120.0, 75.0}}) {
            const glm::dquat q = dquat_from_ypr_degrees(DVec3(yaw, pitch, roll));
            const DVec3 back = ypr_degrees_from_quat(q);
            INFO("pitch " << pitch << " yaw " << yaw << " roll " << roll << " -> " << back.x << " " << back.y
                          << " " << back.z);
            CHECK(std::isfinite(back.x));
            CHECK(back.y == doctest::Approx(pitch).epsilon(1e-12));
            CHECK(back.z == 0.0);
            // Only yaw - roll (pitch up) or yaw + roll (pitch down) is defined at the lock.
            const double combined = pitch > 0 ? yaw - roll : yaw + roll;
            CHECK(std::remainder(back.x - combined, 360.0) == doctest::Approx(0.0).epsilon(1e-9));
            CHECK(max_difference(dquat_from_ypr_degrees(back), q) < 1e-12);
        }
    // A hair away from the lock the angles still make the rotation to far below float precision (yaw and
    // roll alone are ill-conditioned there; no asin blow-up on top).
    for (double pitch : {89.9999, 89.999999, -89.99999999}) {
        const glm::dquat q = dquat_from_ypr_degrees(DVec3(25, pitch, 40));
        const DVec3 back = ypr_degrees_from_quat(q);
        INFO("pitch " << pitch << " -> " << back.x << " " << back.y << " " << back.z);
        CHECK(back.y == doctest::Approx(pitch).epsilon(1e-9));
        CHECK(max_difference(dquat_from_ypr_degrees(back), q) < 1e-8);
    }
}
