#pragma once
// Preview in context (clip_preview_overlay.cpp): the level robot selected in the viewport plays any of the
// dojo's clips where it stands, lit by the level. The dojo panel's player poses it; the level scene draws
// that robot in the pose instead of its rest pose. Its state: on or off, the robot posed, where the toggle
// is.
#include "core/math.h"
#include "model/editor.h"
#include "render/level_scene.h"

#include <nlohmann/json_fwd.hpp>

namespace ks::editor::ui {

class DojoPanel;

class ClipPreview {
  public:
    static int robot(const Editor& editor); // the primary selection when it is a robot, else 0
    bool on() const { return on_; }
    void turn_on() { on_ = true; }
    // Render pass: advance the dojo's player and hand the pose to the level scene (before it emits).
    void pose(const Editor& editor, DojoPanel& dojo, render::LevelScene& scene, double dt);
    // The bar over the viewport's bottom-left corner, shown while a robot is the primary selection.
    void draw(const Editor& editor, DojoPanel& dojo, Vec2 origin, Vec2 size);
    int posed_robot() const { return posed_robot_; }
    Vec2 toggle_centre() const { return toggle_centre_; }
    void status(nlohmann::json& status) const; // "clip_preview"

  private:
    bool on_ = false;          // "Preview clip" on the selected robot
    int posed_robot_ = 0;      // the robot the level scene draws in the dojo's pose (0: none)
    Vec2 toggle_centre_{0.0f}; // the check box's centre (status file; 0 when hidden)
};

} // namespace ks::editor::ui
