#pragma once
// CPU-side triangle meshes and the builders for level geometry (boxes, stairs). No GL: the builders are
// tested on their own and uploaded by GpuMesh.
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
    geometry::Aabb bounds() const;
};

// A box with the given centre/size in the mesh's space. UVs are box-mapped in *world* units divided by
// `world_per_repeat` using `to_world` so textures keep their scale on any size of wall (no stretching).
void append_box(MeshData& mesh, const Vec3& center, const Vec3& size, const Mat4& to_world,
                float world_per_repeat);

// Stairs of `steps` boxes filling `size` (width x, rise y, run z), rising toward local -z, origin at the
// bottom centre of the low end... of the whole footprint (as the level format places them).
void append_stairs(MeshData& mesh, const Vec3& size, int steps, const Mat4& to_world, float world_per_repeat);

// A unit cube (side 1, centred) with 0..1 UVs per face: placeholder models and debug use.
MeshData unit_cube();

} // namespace ks::render
