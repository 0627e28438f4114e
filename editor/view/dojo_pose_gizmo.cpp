// The dojo preview's posing tools (dojo_pose_gizmo.h).
#include "view/dojo_pose_gizmo.h"

#include <cmath>
#include <cstdio>

namespace ks::editor {

namespace {
constexpr float kJointPixels = 8.0f, kBonePixels = 4.0f;
constexpr float kDegrees = 57.2957795f;
} // namespace

anim::Pose shown_pose(const DojoPlayback& playback, const DojoPoseEdits& pose_edits) {
    anim::Pose pose;
    if (playback.player()) {
        pose = playback.player()->pose();
    } else {
        pose.set_rest(playback.rig());
    }
    pose_edits.apply(pose);
    return pose;
}

GizmoFrame DojoPoser::frame(const anim::Rig& rig, const anim::Pose& pose, int node) const {
    GizmoFrame f;
    f.three_axes = true;
    if (node < 0 || node >= rig.size()) return f;
    const std::vector<Mat4> world = pose_world(rig, pose);
    f.pivot = joint_position(world, node);
    if (settings.space == RotationSpace::Local)
        f.axes = glm::mat3_cast(world_rotation(world[static_cast<std::size_t>(node)]));
    return f;
}

Handle DojoPoser::hit(const ViewCamera& view, const GizmoFrame& frame, Vec2 mouse) const {
    if (settings.ik) return Handle::None;
    return gizmo_hit(GizmoMode::Rotate, gizmo_shape(view, frame), mouse);
}

int DojoPoser::pick(const ViewCamera& view, const anim::Rig& rig, const anim::Pose& pose, Vec2 mouse) const {
    const std::vector<Mat4> world = pose_world(rig, pose);
    const geometry::Ray ray = view.ray(mouse);
    // Sized in pixels at the rig's middle: the robot fills the preview at every zoom.
    const float per_pixel = view.world_per_pixel(world.empty() ? Vec3(0.0f) : joint_position(world, 0));
    return pick_joint(rig, world, ray, kJointPixels * per_pixel, kBonePixels * per_pixel).node;
}

void DojoPoser::begin_turn(DojoPoseScene& scene, const ViewCamera& view, int node, Handle handle,
                           Vec2 mouse) {
    const anim::Rig& rig = scene.playback.rig();
    ring_ = ring_axis(handle);
    if (ring_ < 0 || node < 0 || node >= rig.size()) return;
    drag_ = Drag::Turn;
    node_ = node;
    start_pose_ = shown_pose(scene.playback, scene.pose_edits);
    frame_ = frame(rig, start_pose_, node);
    const auto p = plane_point(view.ray(mouse), frame_.pivot, frame_.axes[ring_]);
    start_angle_ = p ? ring_angle(frame_, ring_, *p - frame_.pivot) : 0.0f;
    name_ = "Rotate " + rig.node(node).name;
    origin_ = scene.edits.file();
    recorded_ = false;
    readout_.clear();
}

bool DojoPoser::begin_ik(DojoPoseScene& scene, const ViewCamera& view, int node, Vec2 mouse) {
    const anim::Rig& rig = scene.playback.rig();
    if (node < 0 || node >= rig.size() || rig.node(node).parent < 0 ||
        rig.node(rig.node(node).parent).parent < 0)
        return false;
    start_pose_ = shown_pose(scene.playback, scene.pose_edits);
    const std::vector<Mat4> world = pose_world(rig, start_pose_);
    start_tip_ = joint_position(world, node);
    pole_ = joint_position(world, rig.node(node).parent);
    plane_normal_ = view.forward(); // the joint moves in the plane facing the camera
    start_point_ = plane_point(view.ray(mouse), start_tip_, plane_normal_).value_or(start_tip_);
    drag_ = Drag::Ik;
    node_ = node;
    name_ = "IK " + rig.node(node).name;
    origin_ = scene.edits.file();
    recorded_ = false;
    readout_.clear();
    return true;
}

// The drag's rotations into the shown pose and, with auto-key, into the file from the drag's origin.
void DojoPoser::write(DojoPoseScene& scene, std::span<const NodeRotation> rotations) {
    if (!settings.auto_key) return;
    anim::AnimationFile edited = origin_;
    auto keyed = key_rotations_at(edited, scene.clip, scene.seconds, rotations);
    if (!keyed) {
        scene.edits.show_message(keyed.error().str());
        return;
    }
    if (!recorded_) {
        scene.edits.end_drag(); // a new step, whatever the last drag of a field left open
        scene.edits.record_drag(origin_, name_);
        recorded_ = true;
    }
    scene.edits.replace(std::move(edited));
    scene.pose_edits.follow_revision(scene.edits.revision());
}

void DojoPoser::drag(DojoPoseScene& scene, const ViewCamera& view, Vec2 mouse, bool invert_snap) {
    const anim::Rig& rig = scene.playback.rig();
    const geometry::Ray ray = view.ray(mouse);
    char text[96];
    if (drag_ == Drag::Turn) {
        const auto p = plane_point(ray, frame_.pivot, frame_.axes[ring_]);
        if (!p) return;
        const float angle = ring_angle(frame_, ring_, *p - frame_.pivot) - start_angle_;
        const bool snap = settings.snap != invert_snap;
        const float degrees =
            snap_turn_degrees(std::remainder(angle * kDegrees, 360.0f), snap ? settings.snap_degrees : 0.0f);
        const int parent = rig.node(node_).parent;
        const Quat parent_world =
            parent >= 0 ? world_rotation(pose_world(rig, start_pose_)[static_cast<std::size_t>(parent)])
                        : Quat(1, 0, 0, 0);
        const Vec3 euler = turned_local_euler(start_pose_.euler[static_cast<std::size_t>(node_)],
                                              parent_world, frame_.axes[ring_], degrees / kDegrees);
        scene.pose_edits.set(node_, euler);
        const NodeRotation rotation{rig.node(node_).name, DVec3(euler) * kDegreesPerRadian};
        write(scene, std::span<const NodeRotation>(&rotation, 1));
        std::snprintf(text, sizeof(text), "rotate %c %+.1f deg (%s)", "xyz"[ring_], degrees,
                      rotation_space_name(settings.space));
    } else if (drag_ == Drag::Ik) {
        const auto p = plane_point(ray, start_tip_, plane_normal_);
        if (!p) return;
        const Vec3 target = start_tip_ + (*p - start_point_);
        const auto ik = solve_arm_ik(rig, start_pose_, node_, target, pole_);
        if (!ik) return;
        scene.pose_edits.set(ik->root, ik->root_euler);
        scene.pose_edits.set(ik->mid, ik->mid_euler);
        const NodeRotation rotations[2] = {
            {rig.node(ik->root).name, DVec3(ik->root_euler) * kDegreesPerRadian},
            {rig.node(ik->mid).name, DVec3(ik->mid_euler) * kDegreesPerRadian}};
        write(scene, rotations);
        std::snprintf(text, sizeof(text), "IK %s %s", rig.node(node_).name.c_str(),
                      ik->reached ? "on target" : "out of reach");
    } else {
        return;
    }
    readout_ = text;
}

void DojoPoser::end(DojoPoseScene& scene) {
    if (drag_ == Drag::None) return;
    if (recorded_) scene.edits.end_drag();
    drag_ = Drag::None;
    readout_.clear();
}

bool DojoPoser::key(DojoPoseScene& scene, int node) {
    const anim::Rig& rig = scene.playback.rig();
    std::vector<NodeRotation> rotations = scene.pose_edits.rotations(rig);
    if (rotations.empty() && node >= 0 && node < rig.size()) {
        const anim::Pose pose = shown_pose(scene.playback, scene.pose_edits);
        rotations.push_back(
            {rig.node(node).name, DVec3(pose.euler[static_cast<std::size_t>(node)]) * kDegreesPerRadian});
    }
    if (rotations.empty()) {
        scene.edits.refuse(Error("nothing to key", {}, "select a node (click its joint) or turn one first"));
        return false;
    }
    const std::size_t clip = scene.clip;
    const double seconds = scene.seconds;
    const bool keyed = scene.edits.apply(key_step_name(rotations, seconds), [&](anim::AnimationFile& file) {
        return key_rotations_at(file, clip, seconds, rotations);
    });
    if (keyed) scene.pose_edits.clear();
    return keyed;
}

} // namespace ks::editor
