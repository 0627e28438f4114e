#include "anim/rotation.h"
#include "core/random.h"

#include <doctest/doctest.h>

using namespace ks;
using namespace ks::anim;

TEST_CASE("Euler XYZ to quaternion is three.js's order: R = Rx Ry Rz") {
    Rng rng(7);
    for (int i = 0; i < 200; ++i) {
        Vec3 e(rng.uniform(-7, 7), rng.uniform(-7, 7), rng.uniform(-7, 7));
        Quat expected = glm::angleAxis(e.x, Vec3(1, 0, 0)) * glm::angleAxis(e.y, Vec3(0, 1, 0)) *
                        glm::angleAxis(e.z, Vec3(0, 0, 1));
        CHECK(angle_between(euler_xyz_to_quat(e), expected) < 1e-5f);
    }
    // A full turn on any axis is the identity rotation (which is why clips keep angles, not quaternions).
    CHECK(angle_between(euler_xyz_to_quat(Vec3(0, 4 * kPi, 0)), Quat(1, 0, 0, 0)) < 1e-5f);
}

TEST_CASE("quaternion to Euler XYZ inverts the conversion, including near gimbal lock") {
    Rng rng(11);
    for (int i = 0; i < 500; ++i) {
        Vec3 e(rng.uniform(-3.1f, 3.1f), rng.uniform(-1.5f, 1.5f), rng.uniform(-3.1f, 3.1f));
        Quat q = euler_xyz_to_quat(e);
        CHECK(angle_between(euler_xyz_to_quat(quat_to_euler_xyz(q)), q) < 2e-5f);
    }
    for (float y : {kPi / 2, -kPi / 2}) {
        Quat q = euler_xyz_to_quat(Vec3(0.3f, y, 0.2f));
        CHECK(angle_between(euler_xyz_to_quat(quat_to_euler_xyz(q)), q) < 1e-3f);
    }
}

TEST_CASE(
    "Euler XYZ -> quaternion -> Euler XYZ gives the same angles, and the same rotation at gimbal lock") {
    // Angles in the canonical ranges come back themselves, including the range ends and near-lock pitches.
    const float hard[] = {0.0f, 1e-7f, -1e-7f, 0.5f, -2.9f, kPi - 1e-4f, -kPi + 1e-4f};
    const float pitches[] = {0.0f, 1e-7f, 0.7f, -1.2f, kPi / 2 - 1e-2f, -kPi / 2 + 1e-2f};
    for (float x : hard)
        for (float y : pitches)
            for (float z : hard) {
                const Vec3 e(x, y, z), back = quat_to_euler_xyz(euler_xyz_to_quat(e));
                CAPTURE(e);
                CAPTURE(back);
                CHECK(std::abs(wrap_angle(back.x - x)) < 2e-4f);
                CHECK(std::abs(back.y - y) < 1e-6f);
                CHECK(std::abs(wrap_angle(back.z - z)) < 2e-4f);
            }
    // At +-90 degrees of pitch x and z turn about the same axis; only their sum (or difference) is defined.
    for (float y : {kPi / 2, -kPi / 2, kPi / 2 - 1e-7f, -kPi / 2 + 1e-7f})
        for (float x : hard)
            for (float z : {0.0f, 0.4f, -2.0f, kPi}) {
                const Vec3 e(x, y, z), back = quat_to_euler_xyz(euler_xyz_to_quat(e));
                CAPTURE(e);
                CAPTURE(back);
                CHECK(std::abs(back.y - y) < 1e-3f);
                CHECK(back.z == 0.0f);
                const float combined = y > 0 ? x + z : x - z;
                CHECK(std::abs(wrap_angle(back.x - combined)) < 1e-3f);
                CHECK(angle_between(euler_xyz_to_quat(back), euler_xyz_to_quat(e)) < 1e-5f);
            }
}

TEST_CASE("wrap_angle keeps the rotation and lands in (-pi, pi]") {
    CHECK(wrap_angle(0.5f) == doctest::Approx(0.5f));
    CHECK(wrap_angle(4 * kPi) == doctest::Approx(0.0f).epsilon(1e-5));
    CHECK(wrap_angle(3 * kPi) == doctest::Approx(kPi).epsilon(1e-5));
    CHECK(wrap_angle(-kPi) == doctest::Approx(kPi).epsilon(1e-6));
    Rng rng(3);
    for (int i = 0; i < 1000; ++i) {
        float a = rng.uniform(-100, 100);
        float w = wrap_angle(a);
        CHECK(w > -kPi - 1e-6f);
        CHECK(w <= kPi + 1e-6f);
        CHECK(angle_between(glm::angleAxis(a, Vec3(0, 1, 0)), glm::angleAxis(w, Vec3(0, 1, 0))) < 2e-5f);
    }
}

TEST_CASE("slerp: unit length, shortest arc, no flips, even for nearly equal or opposite inputs") {
    Rng rng(5);
    auto random_quat = [&] {
        Vec3 axis(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1) + 0.01f);
        return glm::angleAxis(rng.uniform(-10, 10), glm::normalize(axis));
    };
    for (int i = 0; i < 300; ++i) {
        Quat a = random_quat(), b = random_quat();
        if (i % 3 == 0) b = -b;                                             // opposite hemisphere
        if (i % 5 == 0) b = glm::normalize(a + Quat(0, 1e-6f, 0, 0));       // nearly equal
        if (i % 7 == 0) b = a * glm::angleAxis(kPi - 1e-3f, Vec3(1, 0, 0)); // nearly opposite rotations
        const float total = angle_between(a, b);
        CHECK(total <= kPi + 1e-5f);
        Quat prev = a;
        float walked = 0;
        for (int s = 1; s <= 64; ++s) {
            float t = s / 64.0f;
            Quat q = slerp_shortest(a, b, t);
            REQUIRE(std::abs(glm::length(q) - 1.0f) < 1e-6f);
            // Progress along the arc is uniform: angle from a grows linearly in t, no jump back or over.
            CHECK(angle_between(a, q) == doctest::Approx(t * total).epsilon(1e-3).scale(1.0));
            walked += angle_between(prev, q);
            prev = q;
        }
        CHECK(walked == doctest::Approx(total).epsilon(1e-3).scale(1.0));
        CHECK(angle_between(slerp_shortest(a, b, 1.0f), b) < 1e-5f);
    }
}

TEST_CASE("quaternion track samples its keys and eases between them") {
    Quat a(1, 0, 0, 0), b = glm::angleAxis(kPi / 2, Vec3(0, 1, 0)), c = glm::angleAxis(kPi, Vec3(0, 1, 0));
    QuatTrack track({{1.0f, b, Ease::linear()},
                     {0.0f, a, Ease::named(EaseFamily::Quadratic, EaseMode::In)},
                     {2.0f, c, Ease::linear()}}); // out of order on purpose: sorted on construction
    CHECK(track.duration() == 2.0f);
    CHECK(angle_between(track.sample(-1), a) < 1e-6f);
    CHECK(angle_between(track.sample(1.0f), b) < 1e-6f);
    CHECK(angle_between(track.sample(5.0f), c) < 1e-6f);
    CHECK(angle_between(track.sample(0.5f), glm::angleAxis(kPi / 2 * 0.25f, Vec3(0, 1, 0))) < 1e-5f);
    CHECK(angle_between(track.sample(1.5f), glm::angleAxis(kPi * 0.75f, Vec3(0, 1, 0))) < 1e-5f);
}
