// Posing in the dojo's preview (model/dojo_pose.h, model/dojo_pose_keys.h, view/dojo_pose_gizmo.h,
// anim/two_bone_ik.h): joints picked by rays, a gizmo ring dragged turning a node about the ring's axis
// (world and local, snapped), the Euler angles read back nearest the old ones, keys written at the playhead
// (on a key, or between two keys without moving any other key's pose), auto-key as one undo step per drag,
// and two-bone IK reaching its target.
#include "anim/rotation.h"
#include "anim/two_bone_ik.h"
#include "dojo_test_util.h"
#include "model/dojo_edits.h"
#include "model/dojo_pose.h"
#include "view/dojo_pose_gizmo.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace ks;
using namespace ks::editor;
using ks::dojo_test::index_of;
using ks::dojo_test::shipped_clips;
using ks::dojo_test::text;

namespace {
struct PoseSession {
    DojoPlayback playback;
    DojoEdits edits{playback, [](const std::string&, bool) {}};
    DojoPoseEdits pose_edits;
    DojoPoser poser;
    ViewCamera view;
    std::size_t clip = 0;
    double seconds = 0.0;

    explicit PoseSession(const std::string& clip_name, double at) {
        auto rig = anim::build_rig(shipped_clips());
        REQUIRE(rig.ok());
        playback.set_rig(*rig);
        edits.reset(shipped_clips());
        clip = index_of(edits.file(), clip_name);
        seconds = at;
        playback.show_clip(static_cast<int>(clip));
        playback.set_playing(false);
        playback.restart_at(at);
        view.set_viewport(Vec2(640, 480));
        view.camera.fov_y = radians(40.0f);
        view.camera.aspect = 640.0f / 480.0f;
        view.camera.yaw = 0.6f;
        view.camera.pitch = -0.25f;
        view.camera.position = Vec3(0, 1.6f, 0) - view.camera.forward() * 7.0f;
    }
    DojoPoseScene scene() { return {edits, playback, pose_edits, clip, seconds}; }
    int node(const char* name) const { return playback.rig().find(name); }
    anim::Pose pose() const { return shown_pose(playback, pose_edits); }
    Quat world_of(int n) const {
        return world_rotation(pose_world(playback.rig(), pose())[static_cast<std::size_t>(n)]);
    }
};

// A point of ring k on screen, `step` segments (7.5 degrees each) round from its farthest point from the
// centre (clear of the other rings).
Vec2 pose_ring_point(const GizmoShape& shape, int k, int step) {
    int far = 0;
    for (int i = 0; i < kGizmoRingSegments; ++i)
        if (glm::length(shape.rings[k][i] - shape.centre) > glm::length(shape.rings[k][far] - shape.centre))
            far = i;
    return shape.rings[k][(far + step + kGizmoRingSegments) % kGizmoRingSegments];
}

// The angle (degrees) of the turn taking a to b, signed about `axis`.
float pose_turn_about(const Quat& a, const Quat& b, const Vec3& axis) {
    const Quat d = glm::normalize(b * glm::inverse(a));
    const float angle = 2.0f * std::acos(std::clamp(std::abs(d.w), 0.0f, 1.0f));
    const Vec3 v(d.x, d.y, d.z);
    const float sign = glm::dot(v, axis) * (d.w < 0 ? -1.0f : 1.0f) >= 0 ? 1.0f : -1.0f;
    return sign * angle * 57.2957795f;
}

std::vector<std::vector<NodePoseValue>> pose_values_at(const anim::AnimationFile& file, std::size_t clip,
                                                       const std::vector<double>& times) {
    std::vector<std::vector<NodePoseValue>> out;
    for (double t : times) {
        auto values = clip_pose_values(file, clip, t);
        REQUIRE(values.ok());
        out.push_back(*values);
    }
    return out;
}

std::vector<double> pose_key_times(const anim::ClipDef& def) {
    std::vector<double> times;
    double t = 0.0;
    for (const auto& p : def.phases) times.push_back(t += p.duration);
    return times;
}
} // namespace

TEST_CASE("dojo pose: two-bone IK puts the tip on every reachable target, bones keep their lengths") {
    std::mt19937 rng(31);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    const Vec3 root(0, 2, 0.6f), mid(0, 1.34f, 0.6f), tip(0, 0.78f, 0.6f);
    const int runs = test::iterations(400);
    for (int i = 0; i < runs; ++i) {
        const Vec3 target =
            root + glm::normalize(Vec3(u(rng), u(rng), u(rng))) * (0.2f + 1.0f * (u(rng) * 0.5f + 0.5f));
        const Vec3 pole = root + Vec3(1, 0, 0);
        const anim::TwoBoneSolution s = anim::solve_two_bone(root, mid, tip, target, pole);
        REQUIRE(s.reached);
        CHECK(glm::length(s.tip - target) < 1e-4f);
        CHECK(std::abs(glm::length(s.mid - root) - 0.66f) < 1e-4f);
        CHECK(std::abs(glm::length(s.tip - s.mid) - 0.56f) < 1e-4f);
        // The turns move the joints where the solution says.
        CHECK(glm::length(root + s.upper * (mid - root) - s.mid) < 1e-4f);
        const Vec3 tip_after = root + s.upper * (tip - root);
        CHECK(glm::length(s.mid + s.lower * (tip_after - s.mid) - s.tip) < 1e-4f);
        // The elbow bends toward the pole.
        const Vec3 dir = glm::normalize(target - root);
        const Vec3 bend = (s.mid - root) - dir * glm::dot(s.mid - root, dir);
        if (glm::length(bend) > 1e-3f)
            CHECK(glm::dot(bend, pole - root - dir * glm::dot(pole - root, dir)) > 0.0f);
    }
    // Out of reach: the chain points straight at the target.
    const anim::TwoBoneSolution far =
        anim::solve_two_bone(root, mid, tip, root + Vec3(3, 0, 0), root + Vec3(0, 1, 0));
    CHECK_FALSE(far.reached);
    CHECK(glm::length(far.tip - (root + Vec3(1.22f, 0, 0))) < 1e-4f);
}

TEST_CASE("dojo pose: IK on the right hand turns arm_r and forearm_r so the wrist reaches the target") {
    PoseSession s("shoot_pose", 0.3);
    const int hand = s.node("hand_r");
    const anim::Pose pose = s.pose();
    const std::vector<Mat4> world = pose_world(s.playback.rig(), pose);
    const Vec3 target = joint_position(world, s.node("arm_r")) + Vec3(0.5f, -0.6f, 0.2f); // 0.8 away
    const auto ik =
        solve_arm_ik(s.playback.rig(), pose, hand, target, joint_position(world, s.node("forearm_r")));
    REQUIRE(ik);
    CHECK(ik->root == s.node("arm_r"));
    CHECK(ik->mid == s.node("forearm_r"));
    CHECK(ik->reached);
    anim::Pose solved = pose;
    solved.euler[static_cast<std::size_t>(ik->root)] = ik->root_euler;
    solved.euler[static_cast<std::size_t>(ik->mid)] = ik->mid_euler;
    solved.update_rotations();
    CHECK(glm::length(joint_position(pose_world(s.playback.rig(), solved), hand) - target) < 1e-3f);
    CHECK_FALSE(solve_arm_ik(s.playback.rig(), pose, s.node("wheel_base"), target, target)); // no grandparent
}

TEST_CASE("dojo pose: a ray picks the joint it passes, a bone picks the node that turns it, else none") {
    PoseSession s("idle", 0.2);
    const anim::Rig& rig = s.playback.rig();
    const std::vector<Mat4> world = pose_world(rig, s.pose());
    const Vec3 eye(4, 2, 5);
    auto ray_to = [&](const Vec3& p) { return geometry::Ray{eye, glm::normalize(p - eye)}; };
    const Vec3 elbow = joint_position(world, s.node("forearm_r"));
    CHECK(pick_joint(rig, world, ray_to(elbow), 0.06f, 0.03f).node == s.node("forearm_r"));
    const Vec3 upper_arm = (joint_position(world, s.node("arm_r")) + elbow) * 0.5f;
    CHECK(pick_joint(rig, world, ray_to(upper_arm), 0.06f, 0.03f).node == s.node("arm_r"));
    CHECK(pick_joint(rig, world, ray_to(Vec3(3, 5, -3)), 0.06f, 0.03f).node == -1);
}

TEST_CASE("dojo pose: Euler angles read back nearest the old ones, whole turns and the twin triple alike") {
    const Vec3 old(radians(170.0f), radians(30.0f), radians(-175.0f));
    const Vec3 turned = turned_local_euler(old, Quat(1, 0, 0, 0), Vec3(0, 0, 1), radians(5.0f));
    // The same rotation as turning by quaternions...
    const Quat expected = glm::angleAxis(radians(5.0f), Vec3(0, 0, 1)) * anim::euler_xyz_to_quat(old);
    CHECK(anim::angle_between(anim::euler_xyz_to_quat(turned), expected) < 1e-4f);
    // ...and a small turn moves no angle far.
    CHECK(glm::length(turned - old) < radians(12.0f));
    const Vec3 spun(radians(720.0f + 10.0f), 0.0f, 0.0f);
    CHECK(euler_nearest(anim::euler_xyz_to_quat(spun), spun).x == doctest::Approx(spun.x).epsilon(1e-4));
}

TEST_CASE("dojo pose: dragging a ring turns the node about it, world or local, snapped to whole steps") {
    for (const RotationSpace space : {RotationSpace::World, RotationSpace::Local}) {
        CAPTURE(rotation_space_name(space));
        PoseSession s("shoot_pose", 0.3);
        s.poser.settings.space = space;
        const int node = s.node("forearm_r");
        const GizmoFrame frame = s.poser.frame(s.playback.rig(), s.pose(), node);
        const GizmoShape shape = gizmo_shape(s.view, frame);
        const Quat before = s.world_of(node);
        int dragged = 0;
        for (int k = 0; k < 3; ++k) {
            if (!shape.ring_visible[k]) continue;
            CAPTURE(k);
            const Vec2 grab = pose_ring_point(shape, k, 0);
            if (ring_axis(s.poser.hit(s.view, frame, grab)) != k) continue; // another ring passes there too
            ++dragged;
            auto scene = s.scene();
            s.poser.begin_turn(scene, s.view, node, s.poser.hit(s.view, frame, grab), grab);
            s.poser.drag(scene, s.view,
                         pose_ring_point(shape, k, 4)); // 4 segments: 30 degrees round the ring
            const float turned = pose_turn_about(before, s.world_of(node), frame.axes[k]);
            CHECK(std::abs(turned) == doctest::Approx(30.0f).epsilon(0.08));
            // The ring's axis is what the node turned about: it stays where it was.
            CHECK(glm::length(s.world_of(node) * (glm::inverse(before) * frame.axes[k]) - frame.axes[k]) <
                  1e-3f);
            s.poser.settings.snap = true;
            s.poser.settings.snap_degrees = 45.0f;
            s.poser.drag(scene, s.view, pose_ring_point(shape, k, 4)); // 30 degrees snaps to 45
            CHECK(std::abs(pose_turn_about(before, s.world_of(node), frame.axes[k])) ==
                  doctest::Approx(45.0f).epsilon(1e-3));
            s.poser.drag(scene, s.view, pose_ring_point(shape, k, 4), true); // Ctrl: free again
            CHECK(std::abs(pose_turn_about(before, s.world_of(node), frame.axes[k])) ==
                  doctest::Approx(turned).epsilon(1e-3));
            s.poser.settings.snap = false;
            s.poser.end(scene);
            CHECK(s.edits.history().undo_count() == 0); // without auto-key the file is untouched
            s.pose_edits.clear();
        }
        CHECK(dragged >= 2);
    }
}

TEST_CASE("dojo pose: Key on a key time sets that key; between keys it splits the phase, other keys kept") {
    const anim::AnimationFile shipped = shipped_clips();
    for (const char* name : {"shooting", "death", "idle"}) {
        CAPTURE(name);
        anim::AnimationFile file = shipped;
        const std::size_t clip = index_of(file, name);
        const std::vector<double> keys = pose_key_times(file.clips[clip]);
        const auto before = pose_values_at(file, clip, keys);
        // Between the first two keys.
        const double at = keys[0] + (keys[1] - keys[0]) * 0.4;
        const NodeRotation turn{"forearm_l", DVec3(10, 20, 30)};
        auto keyed = key_rotations_at(file, clip, at, std::span<const NodeRotation>(&turn, 1));
        REQUIRE(keyed.ok());
        CHECK(*keyed == 1);
        CHECK(file.clips[clip].phases.size() == keys.size() + 1);
        const auto after = pose_values_at(file, clip, keys);
        for (std::size_t k = 0; k < keys.size(); ++k)
            for (std::size_t n = 0; n < before[k].size(); ++n) {
                CAPTURE(keys[k]);
                CAPTURE(before[k][n].node);
                CHECK(glm::length(after[k][n].rot - before[k][n].rot) < 1e-6);
                CHECK(glm::length(after[k][n].pos - before[k][n].pos) < 1e-6);
            }
        auto at_key = clip_pose_values(file, clip, at);
        REQUIRE(at_key.ok());
        for (const NodePoseValue& v : *at_key)
            if (v.node == "forearm_l") CHECK(glm::length(v.rot - DVec3(10, 20, 30)) < 1e-4); // float clips
        // On a key: that key changes, no phase is added.
        const std::size_t phases = file.clips[clip].phases.size();
        auto again = key_rotations_at(file, clip, at + 5e-5, std::span<const NodeRotation>(&turn, 1));
        REQUIRE(again.ok());
        CHECK(*again == 1);
        CHECK(file.clips[clip].phases.size() == phases);
    }
    anim::AnimationFile file = shipped;
    const NodeRotation turn{"arm_r", DVec3(0, 0, 45)};
    const std::size_t shooting = index_of(file, "shooting");
    auto at_start = key_rotations_at(file, shooting, 0.0, std::span<const NodeRotation>(&turn, 1));
    REQUIRE_FALSE(at_start.ok());
    CHECK(at_start.error().message.find("start") != std::string::npos);
    CHECK(text(file) == text(shipped));
    const NodeRotation unknown{"tail", DVec3(0)};
    CHECK_FALSE(key_rotations_at(file, shooting, 0.2, std::span<const NodeRotation>(&unknown, 1)).ok());
    CHECK(key_step_name(std::span<const NodeRotation>(&turn, 1), 0.5) == "Key arm_r at 0.50 s");
}

TEST_CASE("dojo pose: auto-key writes a drag as one undo step; Key writes the turned nodes; undo restores") {
    PoseSession s("shooting", 0.35);
    const std::string original = text(s.edits.file());
    const int node = s.node("forearm_l");
    s.poser.settings.auto_key = true;
    const GizmoFrame frame = s.poser.frame(s.playback.rig(), s.pose(), node);
    const GizmoShape shape = gizmo_shape(s.view, frame);
    int k = 0;
    while (k < 3 && (!shape.ring_visible[k] ||
                     ring_axis(s.poser.hit(s.view, frame, pose_ring_point(shape, k, 0))) != k))
        ++k;
    REQUIRE(k < 3);
    auto scene = s.scene();
    const Vec2 grab = pose_ring_point(shape, k, 0);
    s.poser.begin_turn(scene, s.view, node, s.poser.hit(s.view, frame, grab), grab);
    for (int step = 1; step <= 4; ++step) s.poser.drag(scene, s.view, pose_ring_point(shape, k, step));
    s.poser.end(scene);
    CHECK(s.edits.history().undo_count() == 1);
    CHECK(s.edits.history().undo_name() == "Rotate forearm_l");
    // The key holds what the preview shows.
    const Vec3 shown = s.pose().euler[static_cast<std::size_t>(node)];
    s.pose_edits.clear();
    s.playback.restart_at(s.seconds);
    CHECK(glm::length(s.pose().euler[static_cast<std::size_t>(node)] - shown) < 1e-4f);
    REQUIRE(s.edits.undo());
    CHECK(text(s.edits.file()) == original);

    // Without auto-key: a drag edits the pose only; Key writes it as one step.
    s.poser.settings.auto_key = false;
    s.poser.begin_turn(scene, s.view, node, s.poser.hit(s.view, frame, grab), grab);
    s.poser.drag(scene, s.view, pose_ring_point(shape, k, 3));
    s.poser.end(scene);
    CHECK(text(s.edits.file()) == original);
    REQUIRE(s.pose_edits.edits().size() == 1);
    REQUIRE(s.poser.key(scene, node));
    CHECK(s.edits.history().undo_name() == "Key forearm_l at 0.35 s");
    CHECK(s.pose_edits.empty());
    const std::vector<std::string> steps = s.edits.history().step_names();
    CHECK(steps.back() == "Key forearm_l at 0.35 s");
    CHECK(steps.front() == "Key forearm_l at 0.35 s"); // the undone drag was dropped
}
