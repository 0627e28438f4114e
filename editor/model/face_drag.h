#pragma once
// Dragging textures on the selected faces with the mouse, window-free: a press on a selected face grabs its
// texture; while the mouse moves over that face's plane every selected face changes live, as one undo step
// for the whole drag (a merged edit of edit_faces.h, sealed by end()). The viewport feeds it the press
// (view/face_picking.h: begin_face_drag) and the mouse's ray each frame.
//
// The modes, chosen by the modifiers held at the press as TrenchBroom's UV editor and Hammer's face edit
// offer them (move by dragging the texture, turn and scale about a centre):
//   plain drag   move: the texel under the grab point follows the mouse; each selected face's texture
//                shifts by the same amount along its own u and v. With Snap on, by whole grid steps.
//   Ctrl+drag    rotate: each face's texture turns about the face's centre by the angle the mouse sweeps
//                about the grabbed face's centre. With Snap on, in steps of the grid's rotation step.
//   Shift+drag   scale: each face's texture grows or shrinks about its centre by the ratio of the mouse's
//                distance from the grabbed face's centre to the grab point's. With Snap on, the ratio in
//                eighths (0.5, 1, 2 exactly), never below one eighth.
// (Ctrl+Shift+click stays the face pick.) Turning and scaling keep the texel at each face's centre where
// it is. Texture lock is not involved: the drag changes attributes only, never a brush's planes.
// Tests: tests/editor/test_edit_faces.cpp.
#include "geometry/ray.h"
#include "model/editor.h"

#include <map>
#include <string>
#include <utility>

namespace ks::editor {

enum class FaceDragMode { move, rotate, scale };

// The mode the modifiers held at the press ask for (Ctrl rotates, Shift scales, none moves).
FaceDragMode face_drag_mode(bool ctrl, bool shift);

class FaceDrag {
  public:
    // A press at `world_point` on face `face` of brush entity `entity`. Grabs the texture when that face is
    // selected and its brush unlocked; returns false (and stays idle) otherwise.
    bool begin(Editor& editor, int entity, int face, const DVec3& world_point, FaceDragMode mode);
    // The mouse's ray now: where it meets the grabbed face's plane drives the drag (a ray along the plane
    // or away from it changes nothing).
    Result<void> drag(Editor& editor, const geometry::Ray& ray);
    // The point the mouse is over, on the grabbed face's plane (world).
    Result<void> drag_to(Editor& editor, const DVec3& world_point);
    // The drag's step is complete: the next edit is a new step.
    void end(Editor& editor);
    // Esc: the faces as they were at the press, and no step left behind.
    void cancel(Editor& editor);

    bool dragging() const { return dragging_; }
    bool changed() const { return changed_; } // the drag has changed a face (a click does not)
    FaceDragMode mode() const { return mode_; }
    // What the drag does now, for the status line: "texture move 0.50, -0.25", "texture turn 15.0 deg",
    // "texture scale x2.000".
    std::string describe() const;

  private:
    struct Grabbed {
        int entity = 0, face = 0;
        DVec3 point{0.0};  // the grab point (world)
        DVec3 centre{0.0}; // the face's centre (world)
        DVec3 normal{0.0}; // its world normal
        glm::dmat3 to_local{1.0};
    };
    Result<void> apply(Editor& editor, const DVec3& world_point);

    bool dragging_ = false, changed_ = false;
    FaceDragMode mode_ = FaceDragMode::move;
    Grabbed grab_;
    std::map<std::pair<int, int>, brush::FaceAttributes> start_; // (entity, face) -> attributes at the press
    glm::dvec2 moved_{0.0};                                      // world units along the grabbed u and v
    double turned_ = 0.0, ratio_ = 1.0;
};

} // namespace ks::editor
