#include "modelio/lod_fidelity.h"

#include "geometry/aabb.h"
#include "geometry/closest_on_triangle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace ks::modelio {

namespace {

template <class T>
const T& element(const T* first, std::size_t stride, std::uint32_t index) {
    return *reinterpret_cast<const T*>(reinterpret_cast<const unsigned char*>(first) + stride * index);
}

// The original triangles binned into a uniform grid over their bounds (each in every cell its box, widened by
// the search distance, touches): a sample looks in its own cell only.
class TriangleGrid {
  public:
    TriangleGrid(const VertexStreams& v, std::span<const std::uint32_t> indices, float search) {
        for (std::uint32_t i : indices) bounds_.grow(element(v.positions, v.position_stride, i));
        bounds_ = bounds_.expanded(search);
        const Vec3 size = bounds_.max - bounds_.min;
        const std::size_t triangles = indices.size() / 3;
        // Cells about a triangle across (the mean edge: a surface's triangles crowd a few cells of a grid
        // sized by volume), never smaller than the search distance.
        double edges = 0.0;
        for (std::size_t t = 0; t < triangles; ++t)
            for (int k = 0; k < 3; ++k)
                edges += glm::length(element(v.positions, v.position_stride, indices[t * 3 + (k + 1) % 3]) -
                                     element(v.positions, v.position_stride, indices[t * 3 + k]));
        const float mean_edge =
            triangles ? static_cast<float>(edges / (3.0 * static_cast<double>(triangles))) : 0.0f;
        const float cell = std::max({search, mean_edge, 1e-6f * glm::length(size) + 1e-12f});
        for (int a = 0; a < 3; ++a) dims_[a] = std::clamp(static_cast<int>(size[a] / cell) + 1, 1, 128);
        for (int a = 0; a < 3; ++a) cell_size_[a] = size[a] / static_cast<float>(dims_[a]);
        cells_.assign(static_cast<std::size_t>(dims_[0] * dims_[1] * dims_[2]) + 1, 0);
        // Counting pass, then filling (one contiguous list).
        for (int pass = 0; pass < 2; ++pass) {
            if (pass == 1) {
                for (std::size_t c = 1; c < cells_.size(); ++c) cells_[c] += cells_[c - 1];
                entries_.resize(cells_.back());
                cursor_.assign(cells_.begin(), cells_.end() - 1);
            }
            for (std::size_t t = 0; t < triangles; ++t) {
                geometry::Aabb box = geometry::Aabb::empty();
                for (int k = 0; k < 3; ++k)
                    box.grow(element(v.positions, v.position_stride, indices[t * 3 + k]));
                box = box.expanded(search);
                int lo[3], hi[3];
                for (int a = 0; a < 3; ++a) {
                    lo[a] = cell_of(box.min[a], a);
                    hi[a] = cell_of(box.max[a], a);
                }
                for (int z = lo[2]; z <= hi[2]; ++z)
                    for (int y = lo[1]; y <= hi[1]; ++y)
                        for (int x = lo[0]; x <= hi[0]; ++x) {
                            const std::size_t c = static_cast<std::size_t>((z * dims_[1] + y) * dims_[0] + x);
                            if (pass == 0)
                                ++cells_[c + 1];
                            else
                                entries_[cursor_[c]++] = static_cast<std::uint32_t>(t);
                        }
            }
        }
    }
    std::span<const std::uint32_t> near(const Vec3& p) const {
        const std::size_t c = static_cast<std::size_t>(
            (cell_of(p.z, 2) * dims_[1] + cell_of(p.y, 1)) * dims_[0] + cell_of(p.x, 0));
        return {entries_.data() + cells_[c], cells_[c + 1] - cells_[c]};
    }

  private:
    int cell_of(float value, int axis) const {
        const float f = cell_size_[axis] > 0.0f ? (value - bounds_.min[axis]) / cell_size_[axis] : 0.0f;
        if (!(f > 0.0f)) return 0; // NaN too
        return std::min(static_cast<int>(f), dims_[axis] - 1);
    }
    geometry::Aabb bounds_ = geometry::Aabb::empty();
    int dims_[3] = {1, 1, 1};
    float cell_size_[3] = {0, 0, 0};
    std::vector<std::uint32_t> cells_; // prefix sums: cell c holds entries_[cells_[c], cells_[c + 1])
    std::vector<std::uint32_t> entries_, cursor_;
};

// Texture coordinates per position unit over the whole mesh (the square root of its texture area over its
// surface area): how far a change of coordinates is along the surface. Per mesh, not per triangle, so a
// triangle whose coordinates barely change (a sphere's pole, a one-colour strip) does not divide by zero;
// 0 when the coordinates span nothing.
float texture_density(const VertexStreams& v, std::span<const std::uint32_t> indices) {
    double surface = 0.0, texture = 0.0;
    geometry::Aabb box = geometry::Aabb::empty();
    Vec2 uv_lo(std::numeric_limits<float>::infinity()), uv_hi(-std::numeric_limits<float>::infinity());
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const Vec3 a = element(v.positions, v.position_stride, indices[t]);
        const Vec3 b = element(v.positions, v.position_stride, indices[t + 1]);
        const Vec3 c = element(v.positions, v.position_stride, indices[t + 2]);
        const Vec2 ta = element(v.uvs, v.uv_stride, indices[t]),
                   tb = element(v.uvs, v.uv_stride, indices[t + 1]),
                   tc = element(v.uvs, v.uv_stride, indices[t + 2]);
        surface += glm::length(glm::cross(b - a, c - a));
        const Vec2 d1 = tb - ta, d2 = tc - ta;
        texture += std::abs(d1.x * d2.y - d1.y * d2.x);
        for (const Vec3& p : {a, b, c}) box.grow(p);
        for (const Vec2& q : {ta, tb, tc}) {
            uv_lo = glm::min(uv_lo, q);
            uv_hi = glm::max(uv_hi, q);
        }
    }
    if (surface > 0.0 && texture > 1e-12 * surface) return static_cast<float>(std::sqrt(texture / surface));
    const float span = glm::length(box.max - box.min);
    return span > 0.0f && std::isfinite(uv_hi.x) ? glm::length(uv_hi - uv_lo) / span : 0.0f;
}

} // namespace

LevelFidelity measure_level_fidelity(const VertexStreams& v, std::span<const std::uint32_t> original,
                                     std::span<const std::uint32_t> simplified, float search,
                                     float max_bend) {
    LevelFidelity out;
    if (!v.positions || original.size() < 3 || simplified.size() < 3) return out;
    // A position that is not finite (or an index past the vertices) makes every measure unbounded: such a
    // level is never drawn.
    for (std::span<const std::uint32_t> list : {original, simplified})
        for (std::uint32_t i : list)
            if (i >= v.count || !is_finite(element(v.positions, v.position_stride, i))) {
                const float inf = std::numeric_limits<float>::infinity();
                return {inf, inf, inf};
            }
    const TriangleGrid grid(v, original, search);
    const float density = v.uvs ? texture_density(v, original) : 0.0f;
    // The point of an original triangle nearest a sample, and how far it is (a triangle facing away counts as
    // a search farther).
    struct Near {
        geometry::TriangleClosest<Vec3> hit;
        float distance;
    };
    std::vector<Near> nearby; // per sample: each original triangle near it
    auto position = [&](std::uint32_t i) { return element(v.positions, v.position_stride, i); };
    auto normal = [&](std::uint32_t i) { return element(v.normals, v.normal_stride, i); };
    auto uv = [&](std::uint32_t i) { return element(v.uvs, v.uv_stride, i); };
    auto nearest_on = [&](std::uint32_t o, const Vec3& p, const Vec3& face) {
        const std::uint32_t* q = &original[static_cast<std::size_t>(o) * 3];
        const Vec3 a = position(q[0]), b = position(q[1]), c = position(q[2]);
        const auto hit = geometry::closest_on_triangle(p, a, b, c);
        const float d = glm::length(hit.point - p);
        return Near{hit, glm::dot(glm::cross(b - a, c - a), face) < 0.0f ? d + search : d};
    };
    // Corners, edge midpoints and the centre, as weights of (a, b, c).
    static constexpr float kSamples[7][3] = {{1, 0, 0},
                                             {0, 1, 0},
                                             {0, 0, 1},
                                             {0.5f, 0.5f, 0},
                                             {0, 0.5f, 0.5f},
                                             {0.5f, 0, 0.5f},
                                             {1.0f / 3, 1.0f / 3, 1.0f / 3}};
    for (std::size_t t = 0; t + 2 < simplified.size(); t += 3) {
        const std::uint32_t s[3] = {simplified[t], simplified[t + 1], simplified[t + 2]};
        const Vec3 face = glm::cross(position(s[1]) - position(s[0]), position(s[2]) - position(s[0]));
        float bend = 0.0f, slide = 0.0f; // the most this triangle's samples bend and slide
        for (const auto& w : kSamples) {
            const Vec3 p = position(s[0]) * w[0] + position(s[1]) * w[1] + position(s[2]) * w[2];
            // The original triangles nearest the sample (those facing the other way count as a search
            // farther); where several are as near (a shared edge, a texture seam, stacked layers) the sample
            // is taken to lie on the one that agrees best with it.
            const std::span<const std::uint32_t> near = grid.near(p);
            nearby.resize(near.size());
            float best = std::numeric_limits<float>::infinity();
            for (std::size_t k = 0; k < near.size(); ++k) {
                nearby[k] = nearest_on(near[k], p, face);
                best = std::min(best, nearby[k].distance);
            }
            if (!std::isfinite(best)) continue;      // farther than the search: the position error says it
            const float tie = best + 0.05f * search; // float rounding of a point on an edge is far smaller
            float shift = std::numeric_limits<float>::infinity(),
                  angle = std::numeric_limits<float>::infinity();
            for (std::size_t k = 0; k < near.size(); ++k) {
                if (nearby[k].distance > tie) continue;
                const std::uint32_t* q = &original[static_cast<std::size_t>(near[k]) * 3];
                const geometry::TriangleClosest<Vec3>& hit = nearby[k].hit;
                const float wa = 1.0f - hit.along_ab - hit.along_ac;
                if (v.uvs) {
                    const Vec2 here = uv(s[0]) * w[0] + uv(s[1]) * w[1] + uv(s[2]) * w[2];
                    const Vec2 there = uv(q[0]) * wa + uv(q[1]) * hit.along_ab + uv(q[2]) * hit.along_ac;
                    const float moved = glm::length(here - there);
                    shift = std::min(shift, density > 0.0f ? moved / density : 0.0f);
                }
                if (v.normals) {
                    const Vec3 here = normal(s[0]) * w[0] + normal(s[1]) * w[1] + normal(s[2]) * w[2];
                    const Vec3 there =
                        normal(q[0]) * wa + normal(q[1]) * hit.along_ab + normal(q[2]) * hit.along_ac;
                    const float lengths = glm::length(here) * glm::length(there);
                    angle = std::min(angle,
                                     lengths > 1e-12f
                                         ? std::acos(std::clamp(glm::dot(here, there) / lengths, -1.0f, 1.0f))
                                         : 0.0f);
                }
            }
            if (v.uvs && std::isfinite(shift)) slide = std::max(slide, shift);
            if (v.normals && std::isfinite(angle)) bend = std::max(bend, angle);
        }
        out.normal_angle = std::max(out.normal_angle, bend);
        // What goes wrong inside this triangle is no wider than the triangle: a slide or bend across a thin
        // one (a rounded edge collapsed) shows as a strip as wide as its smallest altitude.
        float longest = 0.0f;
        for (int k = 0; k < 3; ++k)
            longest = std::max(longest, glm::length(position(s[(k + 1) % 3]) - position(s[k])));
        const float width = longest > 0.0f ? glm::length(face) / longest : 0.0f;
        out.texture_shift = std::max(out.texture_shift, std::min(slide, width));
        if (bend > max_bend) out.normal_extent = std::max(out.normal_extent, width);
    }
    return out;
}

} // namespace ks::modelio
