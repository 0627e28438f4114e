#pragma once
// Vertex, edge and face moves, and snapping to a grid. The new vertex set's convex hull is the new brush;
// its planes are re-derived from the moved points (three points of each face), so vertices on a grid stay
// on it.
//
// The rule that refuses a move (TrenchBroom refuses too, since its issue #298): the move is accepted only
// when (1) every vertex, moved or not, is still a distinct corner of the hull: none goes inside the brush,
// onto a face or onto another vertex; and (2) every old edge still joins two vertices of one face: the
// hull's topology may change only by faces splitting (a quad bent into two triangles) or neighbours becoming
// coplanar and merging, never by a vertex passing over to the other side of the brush and reconnecting;
// and (3) every face none of whose vertices moved keeps its plane, facing the same way: a vertex pushed
// through the opposite face would leave the same topology, mirrored, and is refused.
// Faces keep the attributes of the old face they match (same plane, else most nearly parallel); a face
// whose every vertex moved by the delta keeps its world mapping (texture lock).
#include "brush/brush.h"

#include <span>

namespace ks::brush {

Result<Brush> move_vertices(const Brush& brush, std::span<const int> vertex_indices, const DVec3& delta);
Result<Brush> move_edge(const Brush& brush, int edge_index, const DVec3& delta);
Result<Brush> move_face(const Brush& brush, int face_index, const DVec3& delta);

// A new vertex at `point` (an edge split: its midpoint dragged out): the hull of the vertices and the point.
// Refused unless the point lies outside the brush and every old vertex stays a corner of the new hull.
Result<Brush> add_vertex(const Brush& brush, const DVec3& point);
// The hull of the vertices that are left (a vertex merged into its neighbour, or deleted). Refused when
// what is left spans no volume.
Result<Brush> remove_vertices(const Brush& brush, std::span<const int> vertex_indices);

// Rounds every vertex to the nearest multiple of `grid` (> 0) and re-derives the planes from the rounded
// points; vertices that round to the same point become one. Refused when the rounded points span no volume.
// Afterwards every vertex is within 1e-9 of the grid (tests/brush/test_brush_edit.cpp, the property test).
Result<Brush> snap_to_grid(const Brush& brush, double grid);

} // namespace ks::brush
