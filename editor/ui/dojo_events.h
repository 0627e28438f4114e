#pragma once
// The shown clip's events (named markers: muzzle flash, footstep, sound cue): a lane under the timeline
// with a flag at each event's time (drag to move, right-click for its menu, double-click the lane to add
// one there), the Events page listing them (time, name, sound, Audition, remove), and the Add event popup.
// Each change is one undo step through model/dojo_clips.h (a drag is one step). The selected event is the
// context's (DojoSelection::event).
#include "ui/dojo_context.h"

#include <string>
#include <vector>

namespace ks::editor::ui {

class DojoEvents {
  public:
    void begin_frame() { flags_.clear(); }
    void lane(const DojoContext& dojo, Vec2 origin, float width, float height, double length);
    void list(const DojoContext& dojo);  // the Events page
    void popup(const DojoContext& dojo); // Add event, drawn at the window's level
    // Removes the selected event; false when none is selected.
    bool delete_selected(const DojoContext& dojo);
    const std::vector<Vec2>& flags() const { return flags_; } // status: the lane's flags this frame

  private:
    void open_add(const DojoContext& dojo, double seconds);
    void drag_selected(const DojoContext& dojo, double seconds);

    bool drag_ = false, drag_moved_ = false; // a flag on the lane held / moved since pressed
    int editing_ = -1;                       // the Events page row whose time is being dragged
    double editing_time_ = 0.0;
    bool open_add_ = false;
    double add_time_ = 0.0;
    char name_[64] = {};
    std::string sound_;
    std::vector<std::string> sound_names_; // offered by the sound lists (sound_widgets.h)
    std::vector<Vec2> flags_;
};

} // namespace ks::editor::ui
