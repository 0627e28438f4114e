#pragma once
// What a simplified triangle list does to a mesh's look beyond moving its surface (meshopt_simplify in
// Debian 12's meshoptimizer 0.18 measures positions only): how far the texture slides along the surface and
// how much the shading normals bend. Each simplified triangle is sampled (corners, edge midpoints, centre)
// and each sample compared with the original surface at its nearest point there (a uniform grid finds the
// original triangles near it). Used by modelio::simplify_triangles (model_lod.h).
#include "core/math.h"

#include <cstddef>
#include <cstdint>
#include <span>

namespace ks::modelio {

// A vertex buffer read in place: each stream starts at its first vertex's value and steps by its stride
// (interleaved vertices: every stride is the vertex's size; separate arrays: the element's size).
struct VertexStreams {
    const Vec3* positions = nullptr;
    std::size_t position_stride = sizeof(Vec3);
    const Vec3* normals = nullptr; // optional: no normal check without them
    std::size_t normal_stride = sizeof(Vec3);
    const Vec2* uvs = nullptr; // optional: no texture check without them
    std::size_t uv_stride = sizeof(Vec2);
    std::size_t count = 0;
};

struct LevelFidelity {
    // The farthest the texture moved along the surface (position units), each simplified triangle's slide
    // capped at its own width (smallest altitude): a wrong texture inside a thin triangle is a thin strip.
    float texture_shift = 0.0f;
    float normal_angle = 0.0f; // the largest angle between the shading normals, radians
    // How wide the widest region whose normals bend by more than the allowed angle is (position units): the
    // smallest altitude of each simplified triangle with such a sample. A rounded box's bevel collapsed to a
    // sharp edge bends its normals by up to 45 degrees, but only across the bevel's width: at the distance
    // where that width is under a pixel, the light it changes is too.
    float normal_extent = 0.0f;
};

// `simplified` against `original` (both triangle lists over `vertices`); `search` is how far from the
// original surface a sample may lie (the simplification's position error, with a margin); `max_bend`
// (radians) is the normal bend that counts toward normal_extent.
LevelFidelity measure_level_fidelity(const VertexStreams& vertices, std::span<const std::uint32_t> original,
                                     std::span<const std::uint32_t> simplified, float search, float max_bend);

} // namespace ks::modelio
