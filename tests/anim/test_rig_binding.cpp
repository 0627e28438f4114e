// The pose -> node binding: rig nodes find their targets by name, and a pose's local matrices land in the
// mapped slots only.
#include "anim/rig_binding.h"
#include "anim/rotation.h"

#include <doctest/doctest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <string>
#include <vector>

using namespace ks;
using namespace ks::anim;

TEST_CASE("the binding maps rig nodes to target nodes by name and writes only the mapped slots") {
    std::vector<RigNode> nodes(3);
    nodes[0].name = "root";
    nodes[1].name = "arm";
    nodes[1].parent = 0;
    nodes[1].rest_scale = Vec3(2, 1, 1);
    nodes[2].name = "tail"; // the target has no tail
    nodes[2].parent = 0;
    auto rig = Rig::create(nodes);
    REQUIRE(rig.ok());
    // The target lists its nodes in another order and has one the rig lacks.
    const std::vector<std::string> target_names{"lamp", "arm", "root"};
    const RigBinding binding(*rig, target_names);
    CHECK(binding.mapped() == 2);
    CHECK(binding.target_of(0) == 2);
    CHECK(binding.target_of(1) == 1);
    CHECK(binding.target_of(2) == -1);

    Pose pose;
    pose.set_rest(*rig);
    pose.euler[1] = Vec3(0.3f, -0.2f, 1.0f);
    pose.position[1] = Vec3(0, 1, 0);
    pose.position[0] = Vec3(5, 0, 0);
    pose.update_rotations();
    const Mat4 lamp = glm::translate(Mat4(1), Vec3(7, 7, 7));
    std::vector<Mat4> locals{lamp, Mat4(1), Mat4(1)};
    binding.write_locals(pose, locals);
    CHECK(locals[0] == lamp); // unmapped target nodes keep the caller's transform
    CHECK(locals[2] == glm::translate(Mat4(1), Vec3(5, 0, 0)));
    const Mat4 arm = glm::translate(Mat4(1), Vec3(0, 1, 0)) *
                     glm::mat4_cast(euler_xyz_to_quat(pose.euler[1])) * glm::scale(Mat4(1), Vec3(2, 1, 1));
    CHECK(locals[1] == arm);

    // A shorter target span (a placeholder model) is written where it reaches and nowhere else.
    std::vector<Mat4> short_locals{lamp, lamp};
    binding.write_locals(pose, short_locals);
    CHECK(short_locals[0] == lamp);
    CHECK(short_locals[1] == arm);
}

TEST_CASE("an unbound binding writes nothing") {
    const RigBinding binding;
    Pose pose;
    pose.resize(2);
    std::vector<Mat4> locals{Mat4(3)};
    binding.write_locals(pose, locals);
    CHECK(binding.mapped() == 0);
    CHECK(locals[0] == Mat4(3));
}
