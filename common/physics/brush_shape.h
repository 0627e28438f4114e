#pragma once
// A convex brush (brush/brush.h, planes in double) as a collision shape: a Hull-kind Shape whose polyhedron
// takes the brush's derived vertices, ordered face polygons and plane normals, placed by a float position,
// so it goes through every query path hulls take (capsule against convex polyhedron, the ray clipped by the
// face half-spaces, SAT, the character's ground test).
//
// Precision: the body's position is the brush's bounding-box centre rounded to float (exact), and vertices
// and planes are measured from it in double, then rounded to float once. The float shape differs from the
// brush by at most float rounding of local coordinates (half an ulp of the brush's half size: 6e-8 relative)
// plus the normals' rounding (6e-8 rad) times the face's size: about 1e-6 units for a 10-unit brush at any
// place within +-65 536, measured in tests/physics/test_brush_shape.cpp against the double brush.
#include "brush/brush.h"
#include "physics/shapes.h"

namespace ks::physics {

struct BrushBody {
    Shape shape;                   // ShapeKind::Hull
    geometry::Transform transform; // position: the bounding-box centre in float; no rotation
};

// The polyhedron of `b` with coordinates relative to `origin` (planes and vertices shifted in double).
Polyhedron brush_polyhedron(const brush::Brush& b, const DVec3& origin);

// The static body's shape and placement for a brush.
BrushBody brush_body(const brush::Brush& b);

} // namespace ks::physics
