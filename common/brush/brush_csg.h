#pragma once
// Constructive solid geometry on convex brushes: subtract, intersect, merge (convex union), hollow.
//
// Subtract A - B is the standard successive clipping: A is split by B's face planes in turn; each piece in
// front of a plane (outside B) is a fragment, the piece behind goes on to the next plane, and what is left
// after the last plane is A n B (removed). The fragments tile A - B exactly (shared planes, no gaps or
// overlaps, A's volume conserved) and there is one per plane of B that cuts what is left of A, so the count
// depends on the order: planes are taken greedily, the one cutting off the most volume first, which lets
// a big cut swallow what a later plane would have cut. Counts for a box B (tests/brush/test_brush_csg.cpp):
// window through a wall 4, notch on an edge 2, notch on a corner 3, dent in a face 5, B inside A 6, B
// sharing a face with A (flush cut) 4, no overlap 1 (A itself).
#include "brush/brush.h"

#include <optional>
#include <span>

namespace ks::brush {

struct Subtraction {
    std::vector<Brush> fragments; // A - B as convex pieces; A alone when B does not overlap A
    std::optional<Brush> removed; // A n B; empty when they do not overlap
};

// The order in which B's planes cut: largest_first is the greedy order above; in_order takes B's faces as
// listed (the plain method, the benchmark's baseline).
enum class CutOrder { largest_first, in_order };

// Fragments keep A's faces and attributes; each cut face takes the cutting face of B's material and
// mapping parameters.
Result<Subtraction> subtract(const Brush& a, const Brush& b, CutOrder order = CutOrder::largest_first);

// A n B (faces of both; planes that contribute nothing are dropped). Refused when they do not overlap.
Result<Brush> intersect(const Brush& a, const Brush& b);

// The common part of all `brushes` (at least two), the first one's faces first, so a face two brushes share
// keeps the first one's attributes; it keeps the first brush's anchor. Refused, naming the brushes by index
// (`brushes[i]`), when fewer than two are given, when two of them do not overlap (apart, or only touching
// along a face, an edge or a corner), or when together they leave no volume (each pair overlaps, all do
// not).
Result<Brush> intersect_all(std::span<const Brush> brushes);

// The union when it is convex (the hull of both has the volume of A + B - A n B), each face keeping the
// attributes of the face of A or B it lies on; refused otherwise.
Result<Brush> merge(const Brush& a, const Brush& b);

// Walls of `thickness` inside the brush: the brush minus itself shrunk by `thickness` (every plane moved
// inward), so one wall per face of the inner brush. Inner faces keep the attributes of the face they face.
// Refused when the thickness is not positive or leaves no inside.
Result<std::vector<Brush>> hollow(const Brush& brush, double thickness);

} // namespace ks::brush
