#pragma once
// Dragging a robot's patrol point in the viewport: the point of the selected robots' routes nearest the
// cursor (within a few pixels) is picked, then moved on the horizontal plane through it, so it keeps its
// height on the floor, its x and z on the grid while Snap is on; the whole drag is one undo step
// (patrol_move, edit_patrols.h, with one merge key per drag). Window-free, like the gizmo: tests drive it
// with a ViewCamera.
#include "model/editor.h"
#include "view/view_camera.h"

#include <optional>
#include <string>

namespace ks::editor {

inline constexpr float kPatrolPickPixels = 9.0f;

struct PatrolPointHit {
    int robot_id = 0;
    int index = 0;
};

// The selected robots' patrol point drawn nearest to `mouse`, within `max_pixels`.
std::optional<PatrolPointHit> pick_patrol_point(const Editor& editor, const ViewCamera& view, Vec2 mouse,
                                                float max_pixels = kPatrolPickPixels);

class PatrolDrag {
  public:
    bool dragging() const { return hit_.has_value(); }
    void begin(const Editor& editor, const ViewCamera& view, PatrolPointHit hit, Vec2 mouse);
    // Moves the point under the cursor; returns the edit's error message, if any.
    std::string drag(Editor& editor, const ViewCamera& view, Vec2 mouse);
    void end() { hit_.reset(); }

  private:
    std::optional<PatrolPointHit> hit_;
    Vec3 start_{0.0f};      // the point where the drag began
    Vec3 grab_{0.0f};       // where the cursor's ray met the point's plane then
    std::string merge_key_; // one undo step per drag
    unsigned long drag_count_ = 0;
};

} // namespace ks::editor
