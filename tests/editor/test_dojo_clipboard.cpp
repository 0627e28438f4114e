// The dojo's copy/paste of keys and poses, and paste mirrored (left <-> right): the mirrored pose is the
// reflection of the original in the world (the hands swap places across the robot's side plane), each paste
// one undo step, refusals change nothing.
#include "anim/rotation.h"
#include "dojo_test_util.h"
#include "model/dojo_clipboard.h"

#include <cmath>

using namespace ks;
using namespace ks::editor;

namespace {

// World positions of every node for target values on the file's rig.
std::vector<Vec3> world_positions(const anim::AnimationFile& file, const std::vector<NodePoseValue>& values) {
    auto rig = anim::build_rig(file);
    REQUIRE(rig.ok());
    anim::Pose pose;
    pose.set_rest(*rig);
    for (const NodePoseValue& v : values) {
        const int n = rig->find(v.node);
        REQUIRE(n >= 0);
        const auto i = static_cast<std::size_t>(n);
        pose.euler[i] = Vec3(glm::radians(v.rot));
        pose.position[i] = rig->node(n).rest_position + Vec3(v.pos);
    }
    pose.update_rotations();
    std::vector<Mat4> world(static_cast<std::size_t>(rig->size()));
    anim::compute_world(*rig, pose, world);
    std::vector<Vec3> out;
    for (const Mat4& m : world) out.emplace_back(m[3]);
    return out;
}

} // namespace

TEST_CASE("dojo clipboard: side names mirror; a centre node keeps its name") {
    CHECK(mirror_node_name("arm_r") == "arm_l");
    CHECK(mirror_node_name("forearm_l") == "forearm_r");
    CHECK(mirror_node_name("hand.L") == "hand.R");
    CHECK(mirror_node_name("leftFoot") == "rightFoot");
    CHECK(mirror_node_name("hand_r_tip") == "hand_l_tip");
    CHECK(mirror_node_name("chest") == "chest");
}

TEST_CASE("dojo clipboard: a key pasted mirrored swaps sides and reflects the pose in the world") {
    anim::AnimationFile file = dojo_test::shipped_clips();
    const std::size_t shoot = dojo_test::index_of(file, "shoot_pose");
    auto copied = copy_key(file, shoot, 0);
    REQUIRE(copied.ok());
    auto pose = clip_pose_values(file, shoot, file.clips[shoot].duration());
    REQUIRE(pose.ok());

    DojoHistory history;
    auto made = new_clip(file, "mirror");
    REQUIRE(made.ok());
    const std::string before = dojo_test::text(file);
    REQUIRE(apply_dojo_edit(file, history, "paste mirrored", [&] {
                return paste_key(file, *made, 0, mirrored(copy_pose(*pose), file));
            }).ok());
    const anim::TargetDef* arm_l = nullptr;
    for (const anim::TargetDef& t : file.clips[*made].phases[0].targets)
        if (t.node == "arm_l") arm_l = &t;
    REQUIRE(arm_l != nullptr);
    CHECK(arm_l->rot->x == doctest::Approx(0.0));
    CHECK(arm_l->rot->y == doctest::Approx(-22.5));
    CHECK(arm_l->rot->z == doctest::Approx(60.0));

    // The mirrored clip's end pose is the original's reflected across the robot's side plane (z -> -z).
    auto after = clip_pose_values(file, *made, file.clips[*made].duration());
    REQUIRE(after.ok());
    const std::vector<Vec3> a = world_positions(file, *pose), b = world_positions(file, *after);
    auto rig = anim::build_rig(file);
    REQUIRE(rig.ok());
    for (int n = 0; n < rig->size(); ++n) {
        const int m = rig->find(mirror_node_name(rig->node(n).name));
        if (m < 0) continue; // hand_r_tip: the left hand has no tip
        const Vec3 reflected = a[static_cast<std::size_t>(n)] * Vec3(1, 1, -1);
        INFO(rig->node(n).name);
        CHECK(glm::length(b[static_cast<std::size_t>(m)] - reflected) < 1e-4f);
    }

    REQUIRE(history.undo(file));
    CHECK(dojo_test::text(file) == before);

    // A plain paste of the copied key puts shoot_pose's first key into the new clip as it was.
    REQUIRE(paste_key(file, *made, 0, *copied).ok());
    CHECK(file.clips[*made].phases[0].targets.size() == copied->targets.size());
}

TEST_CASE(
    "dojo clipboard: nothing copied, a node the rig has not, a key that is not there: refused, unchanged") {
    anim::AnimationFile file = dojo_test::shipped_clips();
    const std::string before = dojo_test::text(file);
    CHECK_FALSE(paste_key(file, 0, 0, {}).ok());
    DojoKeyClipboard tail;
    tail.targets.push_back({});
    tail.targets.back().node = "tail";
    tail.targets.back().rot = DVec3(0, 10, 0);
    auto refused = paste_key(file, 0, 0, tail);
    REQUIRE_FALSE(refused.ok());
    CHECK(test::contains_text(refused.error().str(), "'tail'"));
    CHECK_FALSE(paste_key(file, 0, 99, tail).ok());
    CHECK_FALSE(copy_key(file, 0, 99).ok());
    CHECK(dojo_test::text(file) == before);
}
