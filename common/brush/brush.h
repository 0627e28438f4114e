#pragma once
// A convex brush: a convex polyhedron stored as its face planes (double precision), each face with its
// surface attributes. Vertices, edges and ordered face polygons are derived from the planes when the brush
// is made (brush_derive.h says how) and are read-only: every operation makes a new brush or refuses, so a
// Brush value is always valid (closed, convex, positive volume, every plane contributing a face).
//
// Anchor: the planes are kept relative to a point near the brush, its anchor (the origin for brushes made
// from world planes; a whole-number point near the centre for brushes made from points). Why: a plane's
// distance is rounded to the unit in the last place of its size, about 2e-12 at 10 000 units, and a vertex
// where three nearly coplanar faces meet (a snapped, turned brush has them) multiplies that by 1/sin of
// their angles; measured from a nearby anchor the distances are small and exact, so snapped brushes stay
// within 1e-9 of the grid far from the origin too. Operations keep the anchor of the brush they edit.
#include "brush/face.h"
#include "core/result.h"

#include <vector>

namespace ks::brush {

// More planes than this are refused before any work (a million-plane input returns at once).
inline constexpr std::size_t kMaxFaces = 1024;

// What from_faces does with a plane that contributes no face (it lies outside the brush, only touches it
// at a vertex or an edge, or duplicates another face). Input from a file or a user is refused, naming the
// face; operations that add planes which may turn out redundant (intersect, clip) drop them.
enum class RedundantPlanes { refuse, drop };

struct Edge {
    int v0 = 0, v1 = 0;         // vertex indices
    int face_a = 0, face_b = 0; // the two faces meeting at the edge
};

class Brush {
  public:
    // Validates and derives. Errors name the face (faces[i] and the field) and say how to fix it.
    static Result<Brush> from_faces(std::vector<Face> faces,
                                    RedundantPlanes redundant = RedundantPlanes::refuse);
    // The same with planes relative to `anchor` (world plane = local plane moved by the anchor).
    static Result<Brush> from_anchored_faces(const DVec3& anchor, std::vector<Face> local_faces,
                                             RedundantPlanes redundant = RedundantPlanes::refuse);

    // The same brush with face i's attributes replaced by attributes[i]: the planes do not move, so nothing
    // is derived again (equal to from_anchored_faces with the new attributes, at a fraction of its cost).
    // Refused, naming the face, when the count differs from faces() or an attribute is not finite or a
    // scale is zero, as from_faces refuses them.
    Result<Brush> with_attributes(std::vector<FaceAttributes> attributes) const;
    // The brush moved by p -> rotation * p + translation with its derived geometry carried through the
    // motion instead of derived again: planes (and the anchor) exactly as transformed() computes them,
    // vertices rotated (each within a few units in the last place of the re-derived ones), polygons and edges
    // as they are. Linear in the size, where deriving is quadratic in the faces: for placing a stored brush
    // in the world once (a level's brush entities), not for edits repeated on their own results (the rotated
    // vertices are not re-derived from the rotated planes, so errors would add up). `attributes`, when not
    // empty, replace the faces' (one per face, checked as with_attributes checks them). Refused like
    // transformed(): a matrix that is not a proper rotation, a translation that is not finite, a result
    // beyond the world.
    Result<Brush> carried(const glm::dmat3& rotation, const DVec3& translation,
                          std::vector<FaceAttributes> attributes = {}) const;

    // Faces with world planes (each rounded once from its anchored plane).
    const std::vector<Face>& faces() const { return faces_; }
    const DVec3& anchor() const { return anchor_; }
    // Faces with planes relative to anchor(): what operations extend, to keep the precision.
    std::vector<Face> anchored_faces() const;
    const std::vector<DVec3>& vertices() const { return vertices_; }
    // polygons()[i]: the vertex indices of face i, counter-clockwise seen from outside.
    const std::vector<std::vector<int>>& polygons() const { return polygons_; }
    const std::vector<Edge>& edges() const { return edges_; }
    double volume() const { return volume_; }
    DVec3 bounds_min() const { return bounds_min_; }
    DVec3 bounds_max() const { return bounds_max_; }
    // The mean of the vertices (inside the brush, since it is convex).
    DVec3 vertex_centre() const;
    // The face with the same plane as `plane` (same_plane: parallel within kSameNormal, distances within
    // kOnPlaneEpsilon), or -1.
    int find_face(const Plane& plane) const;

    // The same faces (planes and attributes, exactly) about the same anchor; the derived data follows.
    bool operator==(const Brush& other) const { return anchor_ == other.anchor_ && faces_ == other.faces_; }

  private:
    Brush() = default;

    std::vector<Face> faces_;
    DVec3 anchor_{0.0};
    std::vector<Plane> local_planes_;
    std::vector<DVec3> vertices_;
    std::vector<std::vector<int>> polygons_;
    std::vector<Edge> edges_;
    double volume_ = 0.0;
    DVec3 bounds_min_{0.0}, bounds_max_{0.0};
};

// Volume of a closed polyhedron given as outward polygons (fans about the vertex mean, to keep the
// products small).
double polyhedron_volume(const std::vector<DVec3>& vertices, const std::vector<std::vector<int>>& polygons);

} // namespace ks::brush
