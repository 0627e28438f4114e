#pragma once
// Picking a brush face with a viewport ray, window-free: the nearest shown, unlocked brush entity the ray
// enters and the face of its world brush it enters through (brush::ray_entry_face). Faces keep their index
// between an entity's frame and the world, so the index is the one the face selection holds.
#include "model/editor.h"
#include "model/face_drag.h"
#include "view/picking.h"

#include <optional>

namespace ks::editor {

struct FacePick {
    int entity = 0;
    int face = 0;
    float distance = 0.0f;
};
// Nothing when the ray meets no brush, or meets another entity first (a wall in front hides the face).
std::optional<FacePick> pick_face(const Document& doc, const geometry::Ray& ray, const ShownFn& shown);

// Ctrl+Shift+click in the viewport: the face picked joins the face selection, or leaves it when it was in;
// a click on no brush face clears the face selection.
Result<void> click_face(Editor& editor, const std::optional<FacePick>& picked);

// A left press with faces selected: when the ray meets a selected face first, `drag` grabs its texture
// in `mode` (face_drag.h) and true is returned; otherwise nothing happens and false is returned.
bool begin_face_drag(FaceDrag& drag, Editor& editor, const geometry::Ray& ray, const ShownFn& shown,
                     FaceDragMode mode);

} // namespace ks::editor
