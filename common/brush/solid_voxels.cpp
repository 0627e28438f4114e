#include "brush/solid_voxels.h"

#include <algorithm>
#include <cmath>

namespace ks::brush {
namespace {

// Separating-axis test of a triangle against an axis-aligned box centred on the origin with half size `h`
// (Akenine-Möller): the box's three axes, the triangle's normal and the nine edge cross products.
bool triangle_overlaps_box(DVec3 a, DVec3 b, DVec3 c, const DVec3& h) {
    const std::array<DVec3, 3> edges{b - a, c - b, a - c};
    for (const DVec3& e : edges) {
        for (int axis = 0; axis < 3; ++axis) {
            DVec3 unit(0.0);
            unit[axis] = 1.0;
            const DVec3 n = glm::cross(unit, e);
            const double pa = glm::dot(n, a), pb = glm::dot(n, b), pc = glm::dot(n, c);
            const double r = h.x * std::abs(n.x) + h.y * std::abs(n.y) + h.z * std::abs(n.z);
            if (std::min({pa, pb, pc}) > r || std::max({pa, pb, pc}) < -r) return false;
        }
    }
    for (int axis = 0; axis < 3; ++axis)
        if (std::min({a[axis], b[axis], c[axis]}) > h[axis] ||
            std::max({a[axis], b[axis], c[axis]}) < -h[axis])
            return false;
    const DVec3 n = glm::cross(edges[0], edges[1]);
    const double d = glm::dot(n, a);
    const double r = h.x * std::abs(n.x) + h.y * std::abs(n.y) + h.z * std::abs(n.z);
    return std::abs(d) <= r;
}

} // namespace

SolidVoxels::SolidVoxels(std::span<const DVec3> vertices,
                         std::span<const std::array<std::uint32_t, 3>> triangles, int cells) {
    DVec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (const auto& t : triangles)
        for (std::uint32_t i : t) lo = glm::min(lo, vertices[i]), hi = glm::max(hi, vertices[i]);
    const DVec3 extent = hi - lo;
    cell_ = std::max({extent.x, extent.y, extent.z}) / std::max(cells, 1);
    if (!(cell_ > 0.0)) cell_ = 1.0;
    for (int axis = 0; axis < 3; ++axis) {
        // Two voxels of padding: a face on the first one's inner side marks it (boxes are grown by a hair),
        // and the outermost layer must stay clear for the fill to start from.
        dims_[axis] = std::max(static_cast<int>(std::ceil(extent[axis] / cell_ - 1e-9)), 1) + 4;
        origin_[axis] = (lo[axis] + hi[axis]) * 0.5 - dims_[axis] * cell_ * 0.5;
    }
    state_.assign(static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2], Voxel::Outside);
    mark_surface(vertices, triangles);
    fill_inside();
    build_sums();
}

DVec3 SolidVoxels::corner(const std::array<int, 3>& i) const {
    return origin_ + DVec3(i[0], i[1], i[2]) * cell_;
}

Voxel SolidVoxels::at_point(const DVec3& p) const {
    const DVec3 g = glm::floor((p - origin_) / cell_);
    for (int axis = 0; axis < 3; ++axis)
        if (!(g[axis] >= 0 && g[axis] < dims_[axis])) return Voxel::Outside;
    return at(static_cast<int>(g.x), static_cast<int>(g.y), static_cast<int>(g.z));
}

void SolidVoxels::mark_surface(std::span<const DVec3> vertices,
                               std::span<const std::array<std::uint32_t, 3>> triangles) {
    // Boxes grown by a hair, so that a triangle on a voxel face marks both voxels.
    const DVec3 half(cell_ * (0.5 + 1e-9));
    for (const auto& t : triangles) {
        const DVec3 a = (vertices[t[0]] - origin_) / cell_, b = (vertices[t[1]] - origin_) / cell_,
                    c = (vertices[t[2]] - origin_) / cell_;
        std::array<int, 3> from{}, to{};
        for (int axis = 0; axis < 3; ++axis) {
            const double mn = std::min({a[axis], b[axis], c[axis]}),
                         mx = std::max({a[axis], b[axis], c[axis]});
            from[axis] = std::clamp(static_cast<int>(std::floor(mn - 1e-9)), 0, dims_[axis] - 1);
            to[axis] = std::clamp(static_cast<int>(std::floor(mx + 1e-9)), 0, dims_[axis] - 1);
        }
        const bool single = from == to;
        for (int z = from[2]; z <= to[2]; ++z)
            for (int y = from[1]; y <= to[1]; ++y)
                for (int x = from[0]; x <= to[0]; ++x) {
                    const std::size_t i = index(x, y, z);
                    if (state_[i] == Voxel::Surface) continue;
                    const DVec3 centre = origin_ + (DVec3(x, y, z) + 0.5) * cell_;
                    if (single || triangle_overlaps_box(vertices[t[0]] - centre, vertices[t[1]] - centre,
                                                        vertices[t[2]] - centre, half))
                        state_[i] = Voxel::Surface;
                }
    }
}

void SolidVoxels::fill_inside() {
    // Every voxel not reached from the grid's border through non-surface voxels is inside.
    std::vector<char> reached(state_.size(), 0);
    std::vector<std::array<int, 3>> stack;
    for (int z = 0; z < dims_[2]; ++z)
        for (int y = 0; y < dims_[1]; ++y)
            for (int x = 0; x < dims_[0]; ++x) {
                const bool border =
                    x == 0 || y == 0 || z == 0 || x == dims_[0] - 1 || y == dims_[1] - 1 || z == dims_[2] - 1;
                const std::size_t i = index(x, y, z);
                if (!border || state_[i] == Voxel::Surface) continue;
                reached[i] = 1;
                stack.push_back({x, y, z});
            }
    while (!stack.empty()) {
        const std::array<int, 3> v = stack.back();
        stack.pop_back();
        for (int axis = 0; axis < 3; ++axis)
            for (int step : {-1, 1}) {
                std::array<int, 3> n = v;
                n[axis] += step;
                if (n[axis] < 0 || n[axis] >= dims_[axis]) continue;
                const std::size_t i = index(n[0], n[1], n[2]);
                if (reached[i] || state_[i] == Voxel::Surface) continue;
                reached[i] = 1;
                stack.push_back(n);
            }
    }
    for (std::size_t i = 0; i < state_.size(); ++i)
        if (state_[i] == Voxel::Outside && !reached[i]) state_[i] = Voxel::Inside;
}

void SolidVoxels::build_sums() {
    const int sx = dims_[0] + 1, sy = dims_[1] + 1, sz = dims_[2] + 1;
    sums_.assign(static_cast<std::size_t>(sx) * sy * sz, 0);
    auto s = [&](int x, int y, int z) -> std::uint32_t& {
        return sums_[static_cast<std::size_t>(x) +
                     static_cast<std::size_t>(sx) * (y + static_cast<std::size_t>(sy) * z)];
    };
    for (int z = 1; z < sz; ++z)
        for (int y = 1; y < sy; ++y)
            for (int x = 1; x < sx; ++x)
                s(x, y, z) = (solid(x - 1, y - 1, z - 1) ? 1u : 0u) + s(x - 1, y, z) + s(x, y - 1, z) +
                             s(x, y, z - 1) - s(x - 1, y - 1, z) - s(x - 1, y, z - 1) - s(x, y - 1, z - 1) +
                             s(x - 1, y - 1, z - 1);
}

long long SolidVoxels::solid_count(const VoxelBox& b) const {
    if (b.size(0) <= 0 || b.size(1) <= 0 || b.size(2) <= 0) return 0;
    const int sx = dims_[0] + 1, sy = dims_[1] + 1;
    auto s = [&](int x, int y, int z) -> long long {
        return sums_[static_cast<std::size_t>(x) +
                     static_cast<std::size_t>(sx) * (y + static_cast<std::size_t>(sy) * z)];
    };
    const auto& [x0, y0, z0] = b.lo;
    const auto& [x1, y1, z1] = b.hi;
    return s(x1, y1, z1) - s(x0, y1, z1) - s(x1, y0, z1) - s(x1, y1, z0) + s(x0, y0, z1) + s(x0, y1, z0) +
           s(x1, y0, z0) - s(x0, y0, z0);
}

VoxelBox SolidVoxels::shrink(const VoxelBox& box) const {
    if (solid_count(box) == 0) return {box.lo, box.lo};
    VoxelBox out = box;
    for (int axis = 0; axis < 3; ++axis) {
        // Move each side in while the slab it would drop holds no solid voxel.
        for (;;) {
            VoxelBox slab = out;
            slab.hi[axis] = slab.lo[axis] + 1;
            if (solid_count(slab) != 0) break;
            ++out.lo[axis];
        }
        for (;;) {
            VoxelBox slab = out;
            slab.lo[axis] = slab.hi[axis] - 1;
            if (solid_count(slab) != 0) break;
            --out.hi[axis];
        }
    }
    return out;
}

long long SolidVoxels::boundary_count(const VoxelBox& b) const {
    auto in_part = [&](int x, int y, int z) {
        return x >= b.lo[0] && x < b.hi[0] && y >= b.lo[1] && y < b.hi[1] && z >= b.lo[2] && z < b.hi[2] &&
               solid(x, y, z);
    };
    long long count = 0;
    for (int z = b.lo[2]; z < b.hi[2]; ++z)
        for (int y = b.lo[1]; y < b.hi[1]; ++y)
            for (int x = b.lo[0]; x < b.hi[0]; ++x)
                if (solid(x, y, z) &&
                    (!in_part(x - 1, y, z) || !in_part(x + 1, y, z) || !in_part(x, y - 1, z) ||
                     !in_part(x, y + 1, z) || !in_part(x, y, z - 1) || !in_part(x, y, z + 1)))
                    ++count;
    return count;
}

void SolidVoxels::hull_points(const VoxelBox& b, std::vector<DVec3>& out) const {
    out.clear();
    const int sx = dims_[0] + 1, sy = dims_[1] + 1, sz = dims_[2] + 1;
    if (stamp_.empty()) stamp_.assign(static_cast<std::size_t>(sx) * sy * sz, 0);
    if (++generation_ == 0) {
        std::fill(stamp_.begin(), stamp_.end(), 0);
        generation_ = 1;
    }
    auto add = [&](int x, int y, int z) {
        std::uint32_t& mark = stamp_[static_cast<std::size_t>(x) +
                                     static_cast<std::size_t>(sx) * (y + static_cast<std::size_t>(sy) * z)];
        if (mark == generation_) return;
        mark = generation_;
        out.emplace_back(x, y, z);
    };
    // Columns along the longest axis `c`; u and v span the footprint.
    const int c = b.size(0) >= b.size(1) && b.size(0) >= b.size(2) ? 0 : (b.size(1) >= b.size(2) ? 1 : 2);
    const int u = (c + 1) % 3, v = (c + 2) % 3;
    std::array<int, 3> p{};
    for (int i = b.lo[u]; i < b.hi[u]; ++i)
        for (int j = b.lo[v]; j < b.hi[v]; ++j) {
            p[u] = i;
            p[v] = j;
            int first = -1, last = -1;
            for (int k = b.lo[c]; k < b.hi[c]; ++k) {
                p[c] = k;
                if (!solid(p[0], p[1], p[2])) continue;
                if (first < 0) first = k;
                last = k;
            }
            if (first < 0) continue;
            for (int end : {first, last + 1})
                for (int du = 0; du < 2; ++du)
                    for (int dv = 0; dv < 2; ++dv) {
                        std::array<int, 3> q{};
                        q[u] = i + du;
                        q[v] = j + dv;
                        q[c] = end;
                        add(q[0], q[1], q[2]);
                    }
        }
}

} // namespace ks::brush
