#pragma once
// The dojo preview's posing tools, window-free (model/dojo_pose.h for the maths they share): the rotate
// gizmo's three rings on the selected node (view/gizmo.h's shape, hit test and ring angle, in world space or
// the node's own), a ring dragged turning the node (snapped to whole steps when asked), the hand dragged by
// two-bone IK on its forearm and arm (the elbow keeps the side it had: the pole is where it was when the
// drag began), and keying: the Key button writes the edited nodes (or the selected one) at the playhead;
// with auto-key every drag writes its keys as it goes. Each drag is one undo step of the dojo's history,
// named for what it did ("Rotate forearm_l", "IK hand_r"); a drag without auto-key edits the shown pose
// only (DojoPoseEdits) until Key.
#include "model/dojo_edits.h"
#include "model/dojo_playback.h"
#include "model/dojo_pose.h"
#include "model/rotation.h"
#include "view/gizmo.h"
#include "view/view_camera.h"

#include <string>

namespace ks::editor {

struct DojoPoseSettings {
    RotationSpace space = RotationSpace::Local; // which axes the rings turn about
    bool snap = false;                          // turns in whole steps (Ctrl held does the opposite)
    float snap_degrees = 15.0f;
    bool auto_key = false; // drags write keys at the playhead as they go
    bool ik = false;       // dragging the selected node's joint moves it by IK on its parent and grandparent
};

// What a posing edit reads and changes: the clip file (and its history), the playback (rig, the pose at
// the playhead), the unkeyed edits, the shown clip and the playhead within its pass.
struct DojoPoseScene {
    DojoEdits& edits;
    const DojoPlayback& playback;
    DojoPoseEdits& pose_edits;
    std::size_t clip = 0;
    double seconds = 0.0;
};

// The pose shown: the player's at the playhead with the unkeyed edits in.
anim::Pose shown_pose(const DojoPlayback& playback, const DojoPoseEdits& pose_edits);

class DojoPoser {
  public:
    DojoPoseSettings settings;

    // The gizmo's frame on `node` of `pose`: at its joint, the world's axes or the node's own.
    GizmoFrame frame(const anim::Rig& rig, const anim::Pose& pose, int node) const;
    // The ring under the mouse (Handle::None when none; no ring while IK is on).
    Handle hit(const ViewCamera& view, const GizmoFrame& frame, Vec2 mouse) const;
    // The joint under the mouse (-1 for none): spheres about 8 pixels wide, bones about 4.
    int pick(const ViewCamera& view, const anim::Rig& rig, const anim::Pose& pose, Vec2 mouse) const;

    bool dragging() const { return drag_ != Drag::None; }
    // Starts turning `node` on ring `handle` (a ring of `frame`).
    void begin_turn(DojoPoseScene& scene, const ViewCamera& view, int node, Handle handle, Vec2 mouse);
    // Starts moving `node`'s joint by IK; false (nothing starts) when the node has no grandparent.
    bool begin_ik(DojoPoseScene& scene, const ViewCamera& view, int node, Vec2 mouse);
    // The drag so far, from its start (so snapping never accumulates); `invert_snap`: Ctrl held.
    void drag(DojoPoseScene& scene, const ViewCamera& view, Vec2 mouse, bool invert_snap = false);
    void end(DojoPoseScene& scene);
    // Writes the unkeyed edits, or else `node`'s rotation in the shown pose, as keys at the playhead (one
    // undo step); false with the refusal shown when it cannot.
    bool key(DojoPoseScene& scene, int node);
    // "rotate z +15.0 deg (local)", "IK hand_r 0.012 from target", empty when idle.
    const std::string& readout() const { return readout_; }

  private:
    enum class Drag { None, Turn, Ik };
    void write(DojoPoseScene& scene, std::span<const NodeRotation> rotations);

    Drag drag_ = Drag::None;
    int node_ = -1;
    std::string name_;           // the undo step's name
    anim::AnimationFile origin_; // the file when the drag began (auto-key writes from it)
    bool recorded_ = false;      // the drag's undo step is in the history
    anim::Pose start_pose_;
    GizmoFrame frame_;
    int ring_ = -1;
    float start_angle_ = 0.0f;
    Vec3 plane_normal_{0.0f}, start_point_{0.0f}, start_tip_{0.0f}, pole_{0.0f};
    std::string readout_;
};

} // namespace ks::editor
