#pragma once
// Moving, nudging, turning and scaling the selection; each one undoable step (a drag passes a merge key,
// so the whole drag is one step). Groups held whole keep their frames with their members.
// Tests: tests/editor/test_edit_transforms.cpp.
#include "model/editor.h"
#include "model/rotation.h"

#include <string>

namespace ks::editor {

// With snap, the primary selected entity lands on the grid and the others keep their offsets to it.
Result<void> move_selection(Editor& editor, Vec3 delta, bool snap = false, std::string merge_key = {});
// One grid step along axis 0/1/2 in direction +1/-1 (arrow keys).
Result<void> nudge(Editor& editor, int axis, int direction);
// Yaw about the selection's pivot (the entity itself, or the centre of several); snapped to the rotation
// step when the grid snaps. The same as rotate_selection_about(editor, 1, degrees, RotationSpace::World).
Result<void> rotate_selection(Editor& editor, float degrees, std::string merge_key = {});
// A turn about axis 0 (x), 1 (y) or 2 (z) (maths in rotation.h), snapped like rotate_selection. World:
// the selection turns as one about its pivot (positions too); Local: each entity turns in place about its
// own axis. About x or z only when every selected object keeps pitch and roll
// (selection_turns_on_three_axes); the player start and the other types turn about y only.
// `snap` false: the angle as given (a gizmo drag with Ctrl held), whatever the grid says.
Result<void> rotate_selection_about(Editor& editor, int axis, float degrees, RotationSpace space,
                                    bool snap = true, std::string merge_key = {});
// Multiplies size fields along local x, y, z (types without size fields are left alone).
Result<void> scale_selection(Editor& editor, Vec3 factors, std::string merge_key = {});

} // namespace ks::editor
