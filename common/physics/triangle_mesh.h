#pragma once
// A static triangle mesh as a collision shape (ShapeKind::Mesh): a model's own triangles, for concave level
// geometry (an arch, a pipe run, a ramp with a wall) that one convex hull cannot follow. Triangles are
// two-sided and have no inside: a ray hits the first triangle it meets, a capsule touches the nearest.
// Static only: a mesh body cannot move (World::add refuses a kinematic or character mesh).
//
// The triangles are held relative to the body's position (the float centre of their bounding box, like a
// brush body) in one Bvh (physics/bvh.h) over their boxes, stored in its leaf order. Rays and capsules are
// measured in double in the mesh's frame (the world inputs converted exactly, the frame change in double),
// so a contact 10^5 units from the origin is as exact as one at it; results are rounded to float once.
//
// The character controller takes a mesh triangle by triangle (World gathers the triangles near a character
// as obstacles, Obstacle::triangle), so its swept tests stay on convex pieces.
#include "physics/bvh.h"
#include "physics/collide.h"

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace ks::physics {

// More triangles than this are refused (a model that dense is not collision: simplify it or use a hull).
inline constexpr std::size_t kMaxMeshTriangles = 1'000'000;
// Vertices beyond this are refused (a typo, not a place); local coordinates keep their precision to it.
inline constexpr double kMaxMeshCoordinate = 1e6;

struct TriangleMesh {
    std::vector<std::array<Vec3, 3>> triangles; // local coordinates, in the BVH's leaf order
    Bvh bvh;                            // over the triangles' boxes; leaf slot == index in `triangles`
    geometry::Aabb bounds;              // local
    std::size_t dropped_degenerate = 0; // zero-area triangles left out at build
};

struct MeshBody {
    Shape shape;                   // ShapeKind::Mesh
    geometry::Transform transform; // position: the bounding-box centre in float; no rotation
};

// Builds a mesh body from world vertices (double) and index triples. Triangles with zero area (repeated or
// collinear corners: |cross(b - a, c - a)| <= 1e-10 of the longest edge squared, in their float form) are
// dropped and counted. Errors, naming `source`: an index out of range, a non-finite vertex or one beyond
// +-kMaxMeshCoordinate, more than kMaxMeshTriangles triangles, nothing left after dropping.
Result<MeshBody> mesh_body(std::span<const DVec3> vertices,
                           std::span<const std::array<std::uint32_t, 3>> triangles,
                           const std::string& source);

// Closest points between the segment [p0, p1] and the triangle (a, b, c), in double: 0 when they meet.
struct SegmentTriangleDistance {
    double distance = 0.0;
    DVec3 on_segment{0.0};
    DVec3 on_triangle{0.0};
};
SegmentTriangleDistance segment_triangle_distance(const DVec3& p0, const DVec3& p1, const DVec3& a,
                                                  const DVec3& b, const DVec3& c);

// The segment moved into the mesh frame of a body at `xf`, in double (exact inputs, one rounding per step).
struct LocalSegment {
    DVec3 p0, p1;
};
LocalSegment local_segment(const Segment& s, const geometry::Transform& xf);

// Capsule (radius r around s) against one triangle of a mesh body at xf. Apart: the normal runs from the
// triangle's closest point to the segment's, penetration = r - distance. Crossing the triangle (distance
// 0): the normal is the triangle's face normal on the side of the segment's midpoint (+normal when the
// midpoint is in the plane), penetration = r plus how deep the segment's far end lies behind the plane.
std::optional<Contact> collide_capsule_triangle(const Segment& s, float r, const TriangleMesh& mesh,
                                                std::uint32_t triangle, const geometry::Transform& xf,
                                                float contact_margin = 0.0f);
// The deepest of the triangles' contacts (ties to the lower triangle index).
std::optional<Contact> collide_capsule_mesh(const Segment& s, float r, const TriangleMesh& mesh,
                                            const geometry::Transform& xf, float contact_margin = 0.0f);

// Where a ray first meets a triangle (either side) within [0, max_distance]; the normal faces the ray.
bool ray_mesh(const geometry::Ray& ray, const TriangleMesh& mesh, const geometry::Transform& xf,
              ShapeHit& hit);

// The triangle's face normal in the world, turned toward `toward` (a contact normal).
Vec3 triangle_normal(const TriangleMesh& mesh, std::uint32_t triangle, const geometry::Transform& xf,
                     const Vec3& toward);

// Calls visit(triangle, world_bounds) for each triangle whose (padded) world box overlaps `region`, in the
// BVH's (fixed) order.
template <class Visit>
void mesh_triangles_in(const TriangleMesh& mesh, const geometry::Transform& xf, const geometry::Aabb& region,
                       Visit&& visit);

// The world box of one triangle, padded so float rounding of the frame change cannot shrink it.
geometry::Aabb triangle_world_bounds(const TriangleMesh& mesh, std::uint32_t triangle,
                                     const geometry::Transform& xf);
// The local box (in the mesh frame) around a world box.
geometry::Aabb local_region(const geometry::Aabb& world, const geometry::Transform& xf);

template <class Visit>
void mesh_triangles_in(const TriangleMesh& mesh, const geometry::Transform& xf, const geometry::Aabb& region,
                       Visit&& visit) {
    mesh.bvh.aabb_query(local_region(region, xf), [&](std::uint32_t slot) {
        const geometry::Aabb wb = triangle_world_bounds(mesh, slot, xf);
        if (wb.overlaps(region)) visit(slot, wb);
        return true;
    });
}

} // namespace ks::physics
