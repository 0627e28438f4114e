#pragma once
// The collision shapes a Killswitch scene needs, each modelled exactly (no polygonised curves):
//   Box      oriented box: walls, floors, door leaves, pickups, the control panel
//   Wedge    half-box ramp: the stairs' collision (rises toward local -z, like level StairProps)
//   Capsule  upright capsule: player and robots (characters)
//   Cylinder upright cylinder: gas cylinders, floor-light stands (static props)
//   Hull     convex polyhedron built from a mesh's vertices, for any other prop
//   Mesh     static triangle mesh (two-sided triangles in a BVH): concave models (physics/triangle_mesh.h)
// Every shape is centred on its body's position (the centre of its bounding box), in the body's frame.
// Capsules and cylinders stay upright: their body rotation is ignored except for yaw (a no-op for them).
#include "core/math.h"
#include "core/result.h"
#include "geometry/aabb.h"
#include "geometry/transform.h"

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace ks::physics {

// A convex polyhedron in local coordinates: vertices, polygonal faces (coplanar triangles merged) with
// centre, outward unit normal and plane offset (normal·x = offset on the face), unique edges, and the edge
// directions that are distinct up to sign (what SAT needs for its edge×edge axes).
struct Polyhedron {
    struct Face {
        Vec3 normal{0.0f};
        float offset = 0.0f;
        Vec3 centre{0.0f};
        std::uint16_t first = 0; // into face_vertices, counter-clockwise seen from outside
        std::uint16_t count = 0;
    };
    std::vector<Vec3> vertices;
    std::vector<Face> faces;
    std::vector<std::uint16_t> face_vertices;
    std::vector<std::array<std::uint16_t, 2>> edges;
    std::vector<Vec3> edge_directions; // unit, distinct up to sign
    geometry::Aabb bounds;

    std::span<const std::uint16_t> face_indices(const Face& f) const {
        return {face_vertices.data() + f.first, f.count};
    }
};

// Box with half extents `half`, and the stair wedge inside the same bounding box.
Polyhedron make_box_polyhedron(const Vec3& half);
Polyhedron make_wedge_polyhedron(const Vec3& half);

// Fills `edges` (unique) and `edge_directions` (unit, distinct up to sign) from the faces' vertex lists.
void derive_edges(Polyhedron& p);

// Builds the convex hull of a mesh's vertices (a prop's collision mesh) through brush's convex hull (Qhull,
// in double; brush/convex_hull.h), as a brush's polyhedron. Duplicate vertices are welded, coplanar facets
// merged into polygons. Errors (as values, naming `source`): fewer than 4 distinct
// points, all points coplanar (zero volume), non-finite coordinates or beyond +-65 536
// (brush::kMaxCoordinate), too many points.
Result<Polyhedron> build_convex_hull(std::span<const Vec3> points, const std::string& source);

struct TriangleMesh; // physics/triangle_mesh.h

enum class ShapeKind : std::uint8_t { Box, Wedge, Capsule, Cylinder, Hull, Mesh };

struct Shape {
    ShapeKind kind = ShapeKind::Box;
    Vec3 half_extents{0.5f};  // box/wedge/hull/mesh: half size of the local bounding box
    float radius = 0.0f;      // capsule, cylinder
    float half_height = 0.0f; // capsule: half length of the core segment; cylinder: half height
    std::shared_ptr<const Polyhedron> polyhedron; // wedge and hull (boxes build theirs on demand)
    std::shared_ptr<const TriangleMesh> mesh;     // Mesh (built by mesh_body)

    static Shape box(const Vec3& half);
    static Shape wedge(const Vec3& half);
    // Upright capsule of total height 2·(half_segment + radius).
    static Shape capsule(float radius, float half_segment);
    static Shape cylinder(float radius, float half_height);
    static Shape hull(Polyhedron polyhedron);

    // Validates sizes (finite, > 0, < 1e5): a clear error instead of NaN later.
    Result<void> validate(const std::string& what) const;
    // World bounding box of the shape under `xf` (exact for boxes: |R|·half).
    geometry::Aabb bounds(const geometry::Transform& xf) const;
};

} // namespace ks::physics
