// The game's robot rig takes rotated joints from the model in the clip convention (Euler XYZ), so a model
// with a turned hand would move the muzzle where the renderer draws it.
#include "anim/rotation.h"
#include "core/files.h"
#include "game/robot_rig.h"
#include "test_support.h"

#include <doctest/doctest.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <string>
#include <vector>

using namespace ks;

TEST_CASE("a rotated joint in the model reaches the game's robot rig as the same local matrix") {
    auto lib = anim::load_animation_library(ks::test::source_dir() / "assets/animations/robot.json");
    REQUIRE(lib.ok());
    const Quat turn = glm::angleAxis(0.9f, glm::normalize(Vec3(1.0f, 0.5f, -0.7f)));
    ks::test::ScratchDir dir;
    const std::string model = R"({"nodes": [{"name": "hand_r", "translation": [0, -0.56, 0], "rotation": [)" +
                              std::to_string(turn.x) + ", " + std::to_string(turn.y) + ", " +
                              std::to_string(turn.z) + ", " + std::to_string(turn.w) + "]}]}";
    REQUIRE(files::write_atomic(dir / "robot.gltf", model).ok());
    auto rig = game::rig_with_model_offsets(lib->rig, dir / "robot.gltf");
    if (!rig) FAIL(rig.error().str());

    anim::Pose pose;
    pose.set_rest(*rig);
    const int hand = rig->find("hand_r");
    const Mat4 expected = glm::translate(Mat4(1), Vec3(0, -0.56f, 0)) * glm::mat4_cast(turn);
    const Mat4 local = anim::local_matrix(*rig, pose, hand);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) CHECK(local[c][r] == doctest::Approx(expected[c][r]).epsilon(1e-5));

    // The muzzle below the hand turns with it.
    std::vector<Mat4> world(static_cast<std::size_t>(rig->size()));
    anim::compute_world(*rig, pose, world);
    const auto tip = static_cast<std::size_t>(rig->find("hand_r_tip"));
    const auto hand_at = static_cast<std::size_t>(hand);
    const Vec3 offset = Vec3(world[tip][3]) - Vec3(world[hand_at][3]);
    const Vec3 turned = turn * Vec3(0, -0.72f, 0);
    CHECK(glm::length(offset - turned) < 1e-5f);
}
