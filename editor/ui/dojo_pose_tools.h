#pragma once
// Posing in the dojo's preview (ImGui side of view/dojo_pose_gizmo.h): the rig drawn over the picture (a
// joint marker per node, a line to its parent, the selected node highlighted, its name as a tooltip), a
// click on a joint selecting it (shared with the key table: DojoSelection::node), the rotate gizmo's rings on
// the selected node (dragging one turns it; a drag elsewhere still orbits), IK on the hand when IK is on,
// and the posing bar over the preview's bottom edge: Key (K), Auto-key, Local/World, Snap and IK.
#include "ui/dojo_context.h"
#include "view/dojo_pose_gizmo.h"

#include <vector>

namespace ks::editor::ui {

class DojoPoseTools {
  public:
    // Drops the unkeyed edits when the playhead, the clip or the file moved on.
    void sync(const DojoContext& dojo);
    const DojoPoseEdits& edits() const { return edits_; }
    // The overlay and the mouse over the preview image at `corner` (screen pixels), `view` being the
    // preview's camera; true while the tools own the mouse (the preview does not orbit then).
    bool overlay(const DojoContext& dojo, const ViewCamera& view, Vec2 corner, bool hovered);
    // The posing bar: its buttons, at the cursor.
    void bar(const DojoContext& dojo);
    // Key (K): the edited nodes, else the selected one, at the playhead.
    void key(const DojoContext& dojo);

    // For the status file: the joints on screen (rig order), the rings' outermost points ((0, 0): hidden).
    const std::vector<Vec2>& joints() const { return joints_; }
    const std::array<Vec2, 3>& rings() const { return rings_; }
    const DojoPoseSettings& settings() const { return poser_.settings; }

  private:
    DojoPoseScene scene(const DojoContext& dojo);
    int selected(const DojoContext& dojo) const; // the selected node's rig index, -1 for none
    void draw_rig(const DojoContext& dojo, const ViewCamera& view, Vec2 corner, int hovered_node);

    DojoPoser poser_;
    DojoPoseEdits edits_;
    std::vector<Vec2> joints_;
    std::array<Vec2, 3> rings_{};
};

} // namespace ks::editor::ui
