// The glTF rig reader: rest transforms reproduce each node's local matrix (rotations through the Euler XYZ
// convention of anim/rotation.h), hierarchy order, stand-in names, and errors that name the bad value.
#include "anim/gltf_rig.h"
#include "anim/rotation.h"
#include "anim_test_support.h"
#include "core/files.h"
#include "test_support.h"

#include <doctest/doctest.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <string>

using namespace ks;
using namespace ks::anim;

namespace {

float max_difference(const Mat4& a, const Mat4& b) {
    float d = 0;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) d = std::max(d, std::abs(a[c][r] - b[c][r]));
    return d;
}

Mat4 rest_local(const Rig& rig, int index) {
    Pose pose;
    pose.set_rest(rig);
    return local_matrix(rig, pose, index);
}

std::string number_list(const float* v, int n) {
    std::string s = "[";
    for (int i = 0; i < n; ++i) s += (i ? ", " : "") + std::to_string(v[i]);
    return s + "]";
}

Result<Rig> rig_from_file(const ks::test::ScratchDir& dir, const std::string& text) {
    const auto path = dir / "model.gltf";
    REQUIRE(files::write_atomic(path, text).ok());
    return load_gltf_rig(path);
}

} // namespace

TEST_CASE("a glTF node's rest rotation, translation and scale give back its local matrix") {
    // A rotation about a skewed axis: its X, Y and Z parts do not commute, so the Euler order matters.
    const Quat q = glm::angleAxis(1.1f, glm::normalize(Vec3(0.3f, -0.8f, 0.5f)));
    const Vec3 t(0.2f, 1.5f, -0.4f), s(1.0f, 2.0f, 0.5f);
    const float q_xyzw[4] = {q.x, q.y, q.z, q.w};
    const Mat4 expected = glm::translate(Mat4(1), t) * glm::mat4_cast(q) * glm::scale(Mat4(1), s);
    // The old reader's glm::eulerAngles decomposes as Rz Ry Rx; read back as XYZ it is another rotation.
    const Mat4 with_glm_order = glm::translate(Mat4(1), t) *
                                glm::mat4_cast(euler_xyz_to_quat(glm::eulerAngles(q))) *
                                glm::scale(Mat4(1), s);
    REQUIRE(max_difference(with_glm_order, expected) > 0.1f);

    ks::test::ScratchDir dir;
    auto rig = rig_from_file(dir, R"({"nodes": [{"name": "root", "children": [1]},
        {"name": "arm", "translation": [0.2, 1.5, -0.4], "rotation": )" +
                                      number_list(q_xyzw, 4) + R"(, "scale": [1, 2, 0.5]}]})");
    if (!rig) FAIL(rig.error().str());
    REQUIRE(rig->size() == 2);
    CHECK(max_difference(rest_local(*rig, rig->find("arm")), expected) < 1e-5f);
    CHECK(max_difference(rest_local(*rig, rig->find("root")), Mat4(1)) == 0.0f);
}

TEST_CASE("a glTF node given as a matrix decomposes into the same local matrix") {
    const Mat4 m = glm::translate(Mat4(1), Vec3(1, 2, 3)) *
                   glm::mat4_cast(glm::angleAxis(-2.3f, glm::normalize(Vec3(1, 1, -2)))) *
                   glm::scale(Mat4(1), Vec3(0.5f, 1.5f, 2.0f));
    ks::test::ScratchDir dir;
    auto rig =
        rig_from_file(dir, R"({"nodes": [{"name": "m", "matrix": )" + number_list(&m[0][0], 16) + "}]}");
    if (!rig) FAIL(rig.error().str());
    CHECK(max_difference(rest_local(*rig, 0), m) < 1e-5f);
}

TEST_CASE("glTF nodes come out parents first, with unique names for unnamed and repeated ones") {
    ks::test::ScratchDir dir;
    // The file lists children before their parents and has two roots.
    auto rig = rig_from_file(dir, R"({"nodes": [{"name": "hand"}, {"name": "arm", "children": [0]},
        {"name": "body", "children": [1, 3]}, {}, {"name": "arm"}]})");
    if (!rig) FAIL(rig.error().str());
    REQUIRE(rig->size() == 5);
    CHECK(rig->node(0).name == "body");
    CHECK(rig->node(rig->find("arm")).parent == rig->find("body"));
    CHECK(rig->node(rig->find("hand")).parent == rig->find("arm"));
    CHECK(rig->node(rig->find("_node3_")).parent == rig->find("body"));
    CHECK(rig->node(rig->find("_node4_arm")).parent == -1);
    for (int i = 0; i < rig->size(); ++i) CHECK(rig->node(i).parent < i);
}

TEST_CASE("bad glTF rigs are errors naming the file and the value") {
    ks::test::ScratchDir dir;
    auto not_nodes = rig_from_file(dir, R"({"nodes": 3})");
    REQUIRE_FALSE(not_nodes.ok());
    CHECK(not_nodes.error().where.file.find("model.gltf") != std::string::npos);

    auto bad_rotation = rig_from_file(dir, R"({"nodes": [{"name": "a", "rotation": [0, 0, 1]}]})");
    REQUIRE_FALSE(bad_rotation.ok());
    CHECK(bad_rotation.error().where.path == "nodes[0].rotation");

    auto zero_rotation = rig_from_file(dir, R"({"nodes": [{"name": "a", "rotation": [0, 0, 0, 0]}]})");
    REQUIRE_FALSE(zero_rotation.ok());
    CHECK(zero_rotation.error().where.path == "nodes[0].rotation");

    auto bad_child = rig_from_file(dir, R"({"nodes": [{"name": "a", "children": [5]}]})");
    REQUIRE_FALSE(bad_child.ok());
    CHECK(bad_child.error().where.path == "nodes[0].children");

    auto two_parents = rig_from_file(dir, R"({"nodes": [{"children": [2]}, {"children": [2]}, {}]})");
    REQUIRE_FALSE(two_parents.ok());
    CHECK(two_parents.error().where.path == "nodes[1].children");

    auto cycle = rig_from_file(dir, R"({"nodes": [{"name": "r"}, {"children": [2]}, {"children": [1]}]})");
    REQUIRE_FALSE(cycle.ok());
    CHECK(cycle.error().message.find("cycle") != std::string::npos);

    CHECK_FALSE(load_gltf_rig(dir / "missing.gltf").ok());
}

TEST_CASE("the robot model's rig has the clip file's nodes, hierarchy and joint offsets") {
    auto rig = load_gltf_rig(ks::test::source_dir() / "assets/models/robot.gltf");
    if (!rig) FAIL(rig.error().str());
    const auto& clip_rig = anim::test::robot_library().rig;
    REQUIRE(rig->size() == clip_rig.size());
    for (const RigNode& node : clip_rig.nodes()) {
        const int i = rig->find(node.name);
        REQUIRE(i >= 0);
        const int parent = rig->node(i).parent;
        CHECK((parent < 0 ? std::string() : rig->node(parent).name) ==
              (node.parent < 0 ? std::string() : clip_rig.node(node.parent).name));
        CHECK(rig->node(i).rest_position == node.rest_position);
    }
}
