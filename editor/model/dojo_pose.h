#pragma once
// Posing the rig in the dojo's preview, window-free: the joints' world positions and picking one with a ray
// (its joint sphere, or the bone from it to a child: the node that turns that bone), a node turned about a
// world axis (the rotate gizmo's rings, world or the node's own axes) read back as the Euler XYZ angles
// nearest the ones it had (clip keys interpolate Euler angles per component, so a turn of a few degrees must
// not come back as an equivalent triple 180 degrees away), two-bone IK on a node's parent and grandparent
// (anim/two_bone_ik.h) as those two nodes' local rotations, and the pose edits not keyed yet (DojoPoseEdits:
// the pose shown until the playhead, the clip or the file changes; Key writes them: dojo_pose_keys.h).
#include "anim/rig.h"
#include "anim/two_bone_ik.h"
#include "geometry/ray.h"
#include "model/dojo_pose_keys.h"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace ks::editor {

// World matrices of every node of `pose` (the preview draws the robot at the origin).
std::vector<Mat4> pose_world(const anim::Rig& rig, const anim::Pose& pose);
inline Vec3 joint_position(std::span<const Mat4> world, int node) {
    return Vec3(world[static_cast<std::size_t>(node)][3]);
}
// The rotation part of a world matrix (scale divided out).
Quat world_rotation(const Mat4& world);

// The joint a ray picks: the nearest along the ray of the joint spheres (radius `joint_radius`) and the
// bones (capsules of `bone_radius` from a node's joint to each child's: picking a bone picks the node that
// turns it). -1 when the ray meets none.
struct JointPick {
    int node = -1;
    float distance = 0.0f;
};
JointPick pick_joint(const anim::Rig& rig, std::span<const Mat4> world, const geometry::Ray& ray,
                     float joint_radius, float bone_radius);

// The Euler XYZ angles (radians) of `q` nearest `reference`: of the two triples every rotation has, each
// angle moved by whole turns toward the reference's.
Vec3 euler_nearest(const Quat& q, const Vec3& reference);

// Node `node`'s local Euler angles after turning it by `radians` about world axis `axis` (unit) through its
// joint, its parent's world rotation being `parent_world`; the result nearest its angles now.
Vec3 turned_local_euler(const Vec3& local_euler, const Quat& parent_world, const Vec3& axis, float radians);

// Snaps a turn to whole steps (degrees) when `step` > 0.
float snap_turn_degrees(float degrees, float step);

// Two-bone IK with `tip` as the end: its parent (the mid joint) and grandparent (the root joint) are turned
// so the tip's joint reaches `target`, bending toward `pole`. Returns the two nodes' new local Euler angles
// (root first) and where the tip ends; nullopt when the node has no grandparent.
struct IkPose {
    int root = -1, mid = -1;
    Vec3 root_euler{0.0f}, mid_euler{0.0f};
    Vec3 tip{0.0f};
    bool reached = false;
};
std::optional<IkPose> solve_arm_ik(const anim::Rig& rig, const anim::Pose& pose, int tip, const Vec3& target,
                                   const Vec3& pole);

// The pose edits made in the preview and not keyed yet: local Euler angles (radians) by node. They belong
// to one playhead, clip and file revision: sync() drops them when any of these changes.
class DojoPoseEdits {
  public:
    void sync(int clip, double time, std::uint64_t revision);
    // The file changed by the poser itself (auto-key): the edits stay.
    void follow_revision(std::uint64_t revision) { revision_ = revision; }
    void set(int node, const Vec3& euler);
    void clear() { edits_.clear(); }
    bool empty() const { return edits_.empty(); }
    const std::vector<std::pair<int, Vec3>>& edits() const { return edits_; }
    // `pose` with the edits in (rotations updated).
    void apply(anim::Pose& pose) const;
    // The edited nodes' rotations in degrees, for key_rotations_at.
    std::vector<NodeRotation> rotations(const anim::Rig& rig) const;

  private:
    std::vector<std::pair<int, Vec3>> edits_;
    int clip_ = -1;
    double time_ = -1.0;
    std::uint64_t revision_ = 0;
};

} // namespace ks::editor
