#pragma once
// Several convex hulls that together hold a triangle mesh: a prop's "hulls" collision (docs/models.md).
//
// Method: approximate convex decomposition in the manner of V-HACD (Mamou and Ghorbel, 2009/2016), written
// here because Debian 12 packages no decomposition library. The mesh is voxelized (solid_voxels.h: surface
// voxels by exact triangle/box overlap, the inside by a flood fill from outside). Phase one cuts: parts are
// boxes of space; the part whose convex hull exceeds its voxels the most is cut, while some part's mean gap
// (excess volume over the part's skin) is above `tolerance` times the mesh's largest side or its hull is
// more than `max_excess` empty, at the axis-aligned plane that minimises the two halves' hull volumes plus
// V-HACD's balance term (ties go to the thinner section: a neck),
// moved onto the mesh's nearest vertex coordinate within two voxels. Each part's hull is then built from the
// mesh itself clipped to the part's box, plus the box corners inside the solid, so the hulls hold every
// point of the surface exactly, not a voxel approximation. Phase two merges: the pair whose merged hull adds
// the least volume is merged while there are more hulls than the cap, and pairs whose union is convex anyway
// (a table's top cut in two) are merged whatever the count. Merged hulls may overlap; when the hulls add up
// to more volume than one hull of the whole mesh (a ring in two overlapping pieces), that one hull is
// returned.
#include "core/math.h"
#include "core/result.h"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace ks::brush {

struct DecompositionOptions {
    int max_hulls = 8;       // the cap on the count, 1..kMaxDecompositionHulls
    int resolution = 48;     // voxels along the mesh's largest side, 8..kMaxDecompositionResolution
    double tolerance = 0.02; // a part is convex enough when its hull's mean gap is below this fraction of the
                             // largest side (0..1)
    double max_excess = 0.1; // and its hull is at most this share empty (0..1)
};

inline constexpr int kMaxDecompositionHulls = 64;
inline constexpr int kMaxDecompositionParts = 96; // phase one's limit: three times the cap, at least 12
inline constexpr int kMaxDecompositionResolution = 128;
inline constexpr std::size_t kMaxDecompositionTriangles = 1'000'000;

struct ConvexDecomposition {
    std::vector<std::vector<DVec3>> hulls; // each hull's points: at least 4, spanning a volume
    double hull_volume = 0.0;              // the hulls' volumes summed
    double voxel_volume = 0.0;             // the mesh's solid as voxels (surface and inside)
    int parts = 0;                         // phase one's parts, before merging
};

// Refuses no triangles, more than kMaxDecompositionTriangles, an index out of range, a non-finite vertex,
// options out of range, and a mesh that spans no volume (every hull flat): each an Error naming the
// triangle or vertex.
Result<ConvexDecomposition> decompose_convex(std::span<const DVec3> vertices,
                                             std::span<const std::array<std::uint32_t, 3>> triangles,
                                             const DecompositionOptions& options = {});

} // namespace ks::brush
