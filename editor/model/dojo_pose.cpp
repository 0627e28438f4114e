// Posing the rig in the dojo's preview (dojo_pose.h).
#include "model/dojo_pose.h"

#include "anim/rotation.h"
#include "core/math.h"
#include "physics/ray.h"

#include <algorithm>
#include <cmath>

namespace ks::editor {

namespace {
constexpr float kPi = 3.14159265358979f, kTwoPi = 2.0f * kPi;

// `angle` moved by whole turns to lie within half a turn of `reference`.
float nearest_turn(float angle, float reference) {
    return angle + kTwoPi * std::round((reference - angle) / kTwoPi);
}

Vec3 nearest_turns(const Vec3& e, const Vec3& reference) {
    return {nearest_turn(e.x, reference.x), nearest_turn(e.y, reference.y), nearest_turn(e.z, reference.z)};
}

float distance2(const Vec3& a, const Vec3& b) {
    const Vec3 d = a - b;
    return glm::dot(d, d);
}
} // namespace

std::vector<Mat4> pose_world(const anim::Rig& rig, const anim::Pose& pose) {
    std::vector<Mat4> world(static_cast<std::size_t>(rig.size()), Mat4(1.0f));
    anim::compute_world(rig, pose, world);
    return world;
}

Quat world_rotation(const Mat4& world) {
    Mat3 m(world);
    for (int c = 0; c < 3; ++c) {
        const float len = glm::length(m[c]);
        if (len > 0.0f) m[c] /= len;
    }
    return glm::normalize(glm::quat_cast(m));
}

JointPick pick_joint(const anim::Rig& rig, std::span<const Mat4> world, const geometry::Ray& ray,
                     float joint_radius, float bone_radius) {
    JointPick best;
    best.distance = ray.max_distance;
    auto consider = [&](int node, const Vec3& a, const Vec3& b, float radius, float bias) {
        physics::ShapeHit hit;
        if (!physics::ray_capsule(ray, a, b, radius, hit)) return;
        // A joint is preferred over a bone it lies on (the bias): clicking a joint's marker picks it.
        if (hit.distance - bias < best.distance) best.node = node, best.distance = hit.distance - bias;
    };
    for (int i = 0; i < rig.size() && i < static_cast<int>(world.size()); ++i) {
        const Vec3 joint = joint_position(world, i);
        consider(i, joint, joint, joint_radius, joint_radius);
        const int parent = rig.node(i).parent;
        if (parent >= 0) consider(parent, joint_position(world, parent), joint, bone_radius, 0.0f);
    }
    if (best.node >= 0) best.distance = std::max(0.0f, best.distance);
    return best;
}

Vec3 euler_nearest(const Quat& q, const Vec3& reference) {
    const Vec3 e = anim::quat_to_euler_xyz(q);
    const Vec3 a = nearest_turns(e, reference);
    const Vec3 b = nearest_turns(Vec3(e.x + kPi, kPi - e.y, e.z + kPi), reference);
    return distance2(a, reference) <= distance2(b, reference) ? a : b;
}

Vec3 turned_local_euler(const Vec3& local_euler, const Quat& parent_world, const Vec3& axis, float radians) {
    const Quat local = anim::euler_xyz_to_quat(local_euler);
    const Quat turn = glm::angleAxis(radians, glm::normalize(axis));
    const Quat turned = glm::normalize(glm::inverse(parent_world) * turn * parent_world * local);
    return euler_nearest(turned, local_euler);
}

float snap_turn_degrees(float degrees, float step) {
    return step > 0.0f ? std::round(degrees / step) * step : degrees;
}

std::optional<IkPose> solve_arm_ik(const anim::Rig& rig, const anim::Pose& pose, int tip, const Vec3& target,
                                   const Vec3& pole) {
    if (tip < 0 || tip >= rig.size()) return std::nullopt;
    IkPose out;
    out.mid = rig.node(tip).parent;
    out.root = out.mid >= 0 ? rig.node(out.mid).parent : -1;
    if (out.root < 0) return std::nullopt;
    const std::vector<Mat4> world = pose_world(rig, pose);
    const anim::TwoBoneSolution s =
        anim::solve_two_bone(joint_position(world, out.root), joint_position(world, out.mid),
                             joint_position(world, tip), target, pole);
    const int above = rig.node(out.root).parent;
    const Quat parent_world =
        above >= 0 ? world_rotation(world[static_cast<std::size_t>(above)]) : Quat(1, 0, 0, 0);
    const Quat root_world = world_rotation(world[static_cast<std::size_t>(out.root)]);
    const auto r = static_cast<std::size_t>(out.root), m = static_cast<std::size_t>(out.mid);
    // The root's new world rotation is upper * root_world; the mid's is lower * upper * mid_world.
    const Quat root_local = glm::inverse(parent_world) * s.upper * root_world;
    const Quat mid_local = glm::inverse(s.upper * root_world) * s.lower * s.upper * world_rotation(world[m]);
    out.root_euler = euler_nearest(glm::normalize(root_local), pose.euler[r]);
    out.mid_euler = euler_nearest(glm::normalize(mid_local), pose.euler[m]);
    out.tip = s.tip;
    out.reached = s.reached;
    return out;
}

void DojoPoseEdits::sync(int clip, double time, std::uint64_t revision) {
    if (clip != clip_ || std::abs(time - time_) > 1e-9 || revision != revision_) edits_.clear();
    clip_ = clip, time_ = time, revision_ = revision;
}

void DojoPoseEdits::set(int node, const Vec3& euler) {
    for (auto& [n, e] : edits_)
        if (n == node) {
            e = euler;
            return;
        }
    edits_.emplace_back(node, euler);
}

void DojoPoseEdits::apply(anim::Pose& pose) const {
    for (const auto& [node, euler] : edits_)
        if (node >= 0 && node < pose.size()) pose.euler[static_cast<std::size_t>(node)] = euler;
    pose.update_rotations();
}

std::vector<NodeRotation> DojoPoseEdits::rotations(const anim::Rig& rig) const {
    std::vector<NodeRotation> out;
    for (const auto& [node, euler] : edits_)
        if (node >= 0 && node < rig.size())
            out.push_back({rig.node(node).name, DVec3(euler) * kDegreesPerRadian});
    return out;
}

} // namespace ks::editor
