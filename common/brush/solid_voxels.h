#pragma once
// Internal to brush: a triangle mesh as a grid of voxels, the measure the convex decomposition
// (convex_decomposition.h) chooses its cuts by. A voxel is Surface when the (closed) triangle overlaps its
// (closed, slightly grown) box, so every point of the surface lies in a Surface voxel; Inside when no path of
// face neighbours leads from it to the grid's border without crossing the surface (a flood fill from the
// padding); Outside otherwise. An open mesh has no Inside voxels, only its surface.
#include "core/math.h"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace ks::brush {

enum class Voxel : std::uint8_t { Outside, Surface, Inside };

// A box of voxels [lo, hi) in grid indices.
struct VoxelBox {
    std::array<int, 3> lo{0, 0, 0};
    std::array<int, 3> hi{0, 0, 0};
    int size(int axis) const { return hi[axis] - lo[axis]; }
    long long count() const { return static_cast<long long>(size(0)) * size(1) * size(2); }
};

class SolidVoxels {
  public:
    // `cells` voxels along the mesh's largest side, plus two voxels of padding on every side.
    SolidVoxels(std::span<const DVec3> vertices, std::span<const std::array<std::uint32_t, 3>> triangles,
                int cells);

    const std::array<int, 3>& dims() const { return dims_; }
    double cell() const { return cell_; }
    DVec3 corner(const std::array<int, 3>& index) const; // a lattice point, in model space
    Voxel at(int x, int y, int z) const { return state_[index(x, y, z)]; }
    bool solid(int x, int y, int z) const { return at(x, y, z) != Voxel::Outside; }
    // The voxel holding a point in model space; Outside beyond the grid.
    Voxel at_point(const DVec3& p) const;
    VoxelBox all() const { return {{0, 0, 0}, dims_}; }

    // Solid voxels in the box, in O(1) (a summed-volume table).
    long long solid_count(const VoxelBox& box) const;
    // The smallest box holding the solid voxels of `box`; an empty box (count 0) when there are none.
    VoxelBox shrink(const VoxelBox& box) const;
    // Solid voxels of `box` with a face neighbour that is not a solid voxel of `box`: the part's skin.
    long long boundary_count(const VoxelBox& box) const;
    // The corners that can be corners of the hull of the solid voxels of `box`: the outer faces of the first
    // and last solid voxel of every column along the box's longest axis, each lattice point once (in grid
    // units, to keep a hull's arithmetic exact). Reuses `out`.
    void hull_points(const VoxelBox& box, std::vector<DVec3>& out) const;

  private:
    std::size_t index(int x, int y, int z) const {
        return static_cast<std::size_t>(x) +
               static_cast<std::size_t>(dims_[0]) *
                   (static_cast<std::size_t>(y) +
                    static_cast<std::size_t>(dims_[1]) * static_cast<std::size_t>(z));
    }
    void mark_surface(std::span<const DVec3> vertices,
                      std::span<const std::array<std::uint32_t, 3>> triangles);
    void fill_inside();
    void build_sums();

    DVec3 origin_{0.0};
    double cell_ = 1.0;
    std::array<int, 3> dims_{1, 1, 1};
    std::vector<Voxel> state_;
    std::vector<std::uint32_t> sums_;          // (dims+1)^3 summed solid counts
    mutable std::vector<std::uint32_t> stamp_; // lattice marks for hull_points
    mutable std::uint32_t generation_ = 0;
};

} // namespace ks::brush
