#pragma once
// Brush entities: placing boxes, extruded convex polygons and ramps, and the CSG edits on them (subtract,
// hollow, merge, intersect, clip), each one undoable step built on common/brush. A new brush entity stands on
// the bottom centre of its bounds (like walls) with its faces in its own frame; an edit that cuts a brush
// keeps its id, name, rotation and layer for the first piece and adds the others as new entities beside it.
// Errors name the entity and say what to do; a refused edit changes nothing.
// Tests: tests/editor/test_edit_brushes.cpp.
#include "model/editor.h"

#include <span>
#include <string>
#include <vector>

namespace ks::editor {

// What a placed brush is made of and called; an empty material is level::kDefaultBrushMaterial.
struct BrushLook {
    std::string material;
    std::string name;
};

// The box between two opposite corners, both snapped to the grid; selects it and returns its id.
Result<int> place_box_brush(Editor& editor, Vec3 corner_a, Vec3 corner_b, const BrushLook& look = {});

// The convex polygon `points` (2D, in the plane across `axis`: for x the (y, z) of each point, for y its
// (x, z), for z its (x, y)) swept along `axis` from `from` to `to`. Points are taken as given (an arc's
// points are not on the grid); they must make a convex polygon with no repeated or collinear points.
Result<int> place_extruded_brush(Editor& editor, int axis, float from, float to,
                                 std::span<const glm::vec2> points, const BrushLook& look = {});

// Which side of a ramp is high: +x, -x, +z or -z (axis 0 or 2, sign +1 or -1).
struct RampRise {
    int axis = 2;
    int sign = -1;
};
// A wedge filling the box between two corners (snapped): its floor is the box's bottom, its slope climbs
// from the bottom edge on the low side to the top edge on the `rise` side, so a ramp to a platform 4 high
// over 8 is the box 0,0,0 to W,4,8 rising toward +z.
Result<int> place_ramp_brush(Editor& editor, Vec3 corner_a, Vec3 corner_b, RampRise rise,
                             const BrushLook& look = {});

// The selected brushes cut from every other unlocked brush they overlap; the pieces replace each cut brush
// (its faces keep their materials; the cut faces take the cutter's) and the cutters are removed. Refused
// when nothing brush is selected or a cutter overlaps no brush.
Result<void> subtract_selected_brushes(Editor& editor);
// Each selected brush becomes walls `thickness` thick around its inside.
Result<void> hollow_selected_brushes(Editor& editor, float thickness);
// The selected brushes (two or more) become one, the first selected; refused when their union is not convex.
Result<void> merge_selected_brushes(Editor& editor);

// The selected brushes (two or more) become their common part, kept in the first selected (its id, name
// and frame); the others are removed. Refused, naming the two brushes, when two of them do not overlap in
// a volume, or when all of them have no volume in common.
Result<void> intersect_selected_brushes(Editor& editor);

// The CSG menu's items, and why one does not apply to the selection now (empty when it does): the menu
// greys the item and shows the reason. The edits above refuse the same cases with the same words.
enum class CsgOp { subtract, hollow, merge, intersect };
std::string csg_unavailable(const Document& doc, CsgOp op);

enum class ClipKeep { back, front, both };
// Each selected brush cut by the plane through `point` with `normal` (world): `back` keeps what lies behind
// it (away from the normal), `front` what lies in front, `both` keeps the two as two brushes. Refused when
// a brush would be left with nothing.
Result<void> clip_selected_brushes(Editor& editor, Vec3 point, Vec3 normal, ClipKeep keep);

} // namespace ks::editor
