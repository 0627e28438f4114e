// Which way a robot faces: the model faces its local +X (conventions.md), a level yaw faces
// (−sin yaw, 0, −cos yaw) (level-format.md). robot_model_yaw() is the one conversion every view uses; the
// muzzle (the right hand's tip, on the model's +Z side) must end up on the robot's right.
#include "game_test_levels.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

using namespace ks;
using namespace ks::game;
using namespace ks::game_test;

TEST_CASE("robot facing: the model's +X turns onto the level's forward for every yaw") {
    for (float degrees_yaw : {0.0f, 90.0f, 180.0f, -90.0f, 135.0f, -45.0f, 721.0f}) {
        CAPTURE(degrees_yaw);
        const float yaw = radians(degrees_yaw);
        const Mat4 model = glm::rotate(Mat4(1.0f), robot_model_yaw(yaw), Vec3(0, 1, 0));
        const Vec3 model_front = Vec3(model * Vec4(1, 0, 0, 0));
        const Vec3 level_forward(-std::sin(yaw), 0.0f, -std::cos(yaw));
        CHECK(glm::length(model_front - level_forward) < 1e-5f);
        // The model's right arm (+Z) is on the robot's right: forward × up.
        const Vec3 model_right = Vec3(model * Vec4(0, 0, 1, 0));
        CHECK(glm::length(model_right - glm::cross(level_forward, Vec3(0, 1, 0))) < 1e-5f);
    }
    // Known values: yaw 0 (faces −z) is the reference's rotY = 90°; yaw −90 (faces +x) is rotY 0.
    CHECK(robot_model_yaw(0.0f) == doctest::Approx(kPi / 2));
    CHECK(robot_model_yaw(-kPi / 2) == doctest::Approx(0.0f));
}

TEST_CASE("robot facing: a robot's muzzle is in front of it and on its right, as its level yaw says") {
    auto lv = flat_level();
    add_robot(lv, Vec3(0, 0, -100), 90.0f); // faces −x; far from the player (no alert turn)
    auto g = make_game(lv);
    g->step({});
    const Vec3 muzzle = g->robot_muzzle(0);
    const Vec3 feet = g->robots()[0].feet;
    CHECK(g->robots()[0].model_yaw() == doctest::Approx(robot_model_yaw(g->robots()[0].yaw)));
    // The hand hangs beside the body on the robot's right: facing −x, right is forward × up = −z.
    CHECK(muzzle.z - feet.z < -0.3f);
    CHECK(std::abs(muzzle.x - feet.x) < 1.0f);
}
