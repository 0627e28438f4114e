#pragma once
// Two-bone inverse kinematics, solved analytically (law of cosines): a chain root -> mid -> tip (a shoulder,
// an elbow, a wrist) turned so the tip reaches a target, bending in the plane of the root, the target and a
// pole point (where the elbow should point). A target out of reach is met as nearly as the chain allows: the
// chain straightens toward it (or folds, for a target closer than the bones' difference). The result is two
// world-space turns, the upper bone's about the root and then the lower bone's about the moved mid joint;
// the caller turns them into its nodes' local rotations (the dojo bakes them into keys).
#include "core/math.h"

namespace ks::anim {

struct TwoBoneSolution {
    Quat upper{1, 0, 0, 0}; // world turn of the upper bone (and all below it) about the root joint
    Quat lower{1, 0, 0, 0}; // then the world turn of the lower bone about the mid joint
    Vec3 mid{0.0f};         // where the mid joint ends
    Vec3 tip{0.0f};         // where the tip ends: the target when reachable
    bool reached = false;   // the target lies within the chain's reach
};

// Root, mid and tip are the joints' world positions now; `pole` picks the bending plane (the mid joint's
// side); when the pole lies on the root-target line the chain keeps its present bending plane.
TwoBoneSolution solve_two_bone(const Vec3& root, const Vec3& mid, const Vec3& tip, const Vec3& target,
                               const Vec3& pole);

} // namespace ks::anim
