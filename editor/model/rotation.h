#pragma once
// Turning entities about one axis, window-free: which types turn on three axes (level::keeps_pitch_and_roll),
// and an entity's yaw, pitch and roll after a turn about the world's or its own x, y or z axis. Turns compose
// as double-precision quaternions and are read back as yaw, pitch, roll (core/math.h), rounded to 1e-4
// degrees so that quarter turns give whole numbers; the two turns that move one angle alone (about world y:
// the yaw; about the entity's own z: the roll) add to it exactly.
#include "model/document.h"

#include <string>

namespace ks::editor {

enum class RotationSpace { World, Local };
const char* rotation_space_name(RotationSpace space); // "world", "local"

// Into (-180, 180], so repeated turns never walk out of the rotation field's range.
float wrap_degrees(float degrees);

// The yaw, pitch, roll (degrees) of an orientation `ypr` turned by `degrees` about axis 0 (x), 1 (y) or
// 2 (z) of the world or of the orientation itself (right-handed: a positive turn about y takes -z toward -x,
// as a growing yaw does).
Vec3 turned_ypr(const Vec3& ypr, int axis, float degrees, RotationSpace space);

// `offset` turned by `degrees` about world axis 0, 1 or 2 (exact at multiples of 90 degrees).
DVec3 turned_offset(const DVec3& offset, int axis, float degrees);

// Whether every selected object may turn about x and z: the selection is not empty, holds no player start,
// and every selected entity's type keeps pitch and roll.
bool selection_turns_on_three_axes(const Document& doc);
// Why an object of the selection turns about y only ("robot 4 turns about y only ..."), or "" when none.
std::string yaw_only_reason(const Document& doc);

} // namespace ks::editor
