#pragma once
// Level geometry from a convex brush (brush/brush.h): each face a polygon of the mesh (fanned from its first
// corner, counter-clockwise seen from outside) with the face plane's normal, texture coordinates from
// brush::texture_coordinates and tangents along them; the whole brush one convex solid (MeshData's polygons
// and solids), so the light bake lays out its faces and casts shadows against it like a wall's box.
// No GL: tested on its own, uploaded by GpuMesh.
#include "brush/brush.h"
#include "geometry/transform.h"
#include "render/mesh_data.h"

#include <string>
#include <vector>

namespace ks::render {

// The faces of one material: polygons [first_polygon, first_polygon + polygon_count) of BrushMesh::mesh.
struct BrushMaterialRange {
    std::string material;
    std::uint32_t first_polygon = 0, polygon_count = 0;
};

struct BrushMesh {
    MeshData mesh; // world space; polygons grouped by material, in order of each material's first face
    std::vector<BrushMaterialRange> materials;
};

// `brush` is in world space (a level entity's brush placed by its frame). A face's scale is world units per
// texture repeat, as a wall's texture_scale: a box brush whose faces have scale (s, s), no offset and no
// rotation is mapped exactly as append_box maps a wall with texture_scale s.
BrushMesh build_brush_mesh(const brush::Brush& brush);

// A box (centre and half size in `frame`'s space) as a brush in the world, its planes turned and moved in
// double precision, every face mapped with `world_per_repeat` world units per texture repeat, no offset or
// turn: the level's walls, floors and stair steps (build_surface_mesh). An Error where the box would leave
// the brush module's world (brush::kMaxCoordinate).
Result<brush::Brush> placed_box_brush(const Vec3& local_centre, const Vec3& half,
                                      const geometry::Transform& frame, float world_per_repeat);

// Polygons [first_polygon, first_polygon + polygon_count) of a mesh made of polygons, as a mesh of their own
// (vertices as they are, light-map coordinates included; no solid, since part of one is not closed).
MeshData polygon_range(const MeshData& mesh, std::uint32_t first_polygon, std::uint32_t polygon_count);

} // namespace ks::render
