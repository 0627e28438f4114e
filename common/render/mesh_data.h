#pragma once
// CPU-side triangle meshes and the builders for level geometry (boxes, stairs; brushes in brush_mesh.h). No
// GL: the builders are tested on their own and uploaded by GpuMesh.
#include "core/math.h"
#include "geometry/aabb.h"

#include <cstdint>
#include <vector>

namespace ks::render {

struct Vertex {
    Vec3 position;
    Vec3 normal;
    Vec2 uv;
    Vec4 tangent;           // xyz tangent, w handedness of the bitangent
    Vec2 lightmap_uv{0.0f}; // the baked light map's coordinate (static level geometry; see light_bake.h)
};

struct MeshData {
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    // Level geometry only (models leave them empty): the mesh as convex planar polygons whose corners are
    // consecutive vertices, polygon_sizes[i] corners each (fanned from the first), and those polygons
    // grouped into closed convex solids of solid_sizes[j] polygons each. The light bake gives every polygon
    // its texels and casts its shadow rays against the solids.
    std::vector<std::uint32_t> polygon_sizes;
    std::vector<std::uint32_t> solid_sizes;
    geometry::Aabb bounds() const;
};

// Appends `polygon`'s corners to `mesh` as one polygon of the level geometry (polygon_sizes), fanned into
// triangles from its first corner. The corners must be counter-clockwise seen from the side their normal
// points to (the outside).
void append_polygon(MeshData& mesh, const std::vector<Vertex>& polygon);

// Appends `more`: its vertices, triangles, polygons and solids after those of `mesh`.
void append_mesh(MeshData& mesh, const MeshData& more);

// A box with the given centre/size in the mesh's space, mapped onto world axes (the previews' floors; the
// level's boxes are brushes, brush_mesh.h). UVs are box-mapped in *world* units divided by
// `world_per_repeat` using `to_world` so textures keep their scale on any size of wall (no stretching).
void append_box(MeshData& mesh, const Vec3& center, const Vec3& size, const Mat4& to_world,
                float world_per_repeat);

// A unit cube (side 1, centred) with 0..1 UVs per face: placeholder models and debug use.
MeshData unit_cube();

} // namespace ks::render
