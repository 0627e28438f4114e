#pragma once
// A static bounding-volume hierarchy over AABBs, built once with the surface-area heuristic (binned, 32
// bins on the widest centroid axis), stored as one contiguous array of 32-byte nodes. Queries allocate
// nothing: traversal uses a fixed stack; the caller's visitor is inlined (templates).
#include "physics/ray.h"
#include "physics/shapes.h"

#include <bit>
#include <cstdint>
#include <span>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace ks::physics {

#if defined(__SSE2__)
using Lanes = __m128;
inline Lanes splat(float v) {
    return _mm_set1_ps(v);
}
#else
struct Lanes {
    float v[4];
};
inline Lanes splat(float v) {
    return {{v, v, v, v}};
}
#endif

class Bvh {
  public:
    struct Node {
        Vec3 min;
        std::uint32_t left_or_first; // inner: index of the left child (right = left + 1); leaf: first item
        Vec3 max;
        std::uint32_t count; // 0 for inner nodes
    };
    static constexpr int kMaxDepth = 64;
    static constexpr std::uint32_t kMaxLeafSize = 4;

    // items[i] is the box of item i; afterwards item_order() maps leaf slots to item indices.
    void build(std::span<const Aabb> items);
    void clear();
    bool empty() const { return nodes_.empty(); }
    std::span<const Node> nodes() const { return nodes_; }
    std::span<const std::uint32_t> item_order() const { return order_; }
    int depth() const { return depth_; }

    // Visits leaf slots (positions in item_order(), so per-item data stored in that order is read
    // contiguously) whose box the ray crosses within [0, max_t], nearest node first. visit(slot, inv_dir,
    // max_t&) returns false to stop; it may shrink max_t (closest-hit queries) to prune the rest.
    template <class Visit>
    void ray_query(const Ray& ray, float max_t, Visit&& visit) const;
    // The same traversal handing over whole leaves: visit(leaf, max_t&) with leaf an index into leaves(),
    // so callers can test a leaf's items together (SIMD). Returns false to stop.
    // `inv` is safe_inverse(ray.direction), computed once by the caller.
    template <class VisitLeaf>
    void ray_query_leaves(const Ray& ray, const Vec3& inv, float max_t, VisitLeaf&& visit) const;
    struct LeafRange {
        std::uint32_t first, count; // leaf slots [first, first + count)
    };
    std::span<const LeafRange> leaves() const { return leaves_; }
    // Visits leaf slots whose node box overlaps `box`. visit(slot) returns false to stop.
    template <class Visit>
    void aabb_query(const Aabb& box, Visit&& visit) const;

  private:
    // The binary tree collapsed to four children per node, bounds stored lane-wise: ray traversal tests four
    // boxes at once (SSE where available) and visits half as many nodes.
    struct alignas(64) WideNode { // 128 bytes: exactly two cache lines
        float min_x[4], min_y[4], min_z[4], max_x[4], max_y[4], max_z[4];
        std::int32_t child[4]; // >= 0: wide node; < 0: ~leaf index
        std::int32_t lanes;    // bit k set when child k exists
    };
    void build_wide();
    static int slab4(const WideNode& n, const Lanes& ox, const Lanes& oy, const Lanes& oz, const Lanes& ix,
                     const Lanes& iy, const Lanes& iz, float max_t, float* t_enter);

    std::vector<WideNode> wide_;
    std::vector<LeafRange> leaves_;
    std::vector<Node> nodes_;
    std::vector<std::uint32_t> order_;
    int depth_ = 0;
};

inline int Bvh::slab4(const WideNode& n, const Lanes& ox, const Lanes& oy, const Lanes& oz, const Lanes& ix,
                      const Lanes& iy, const Lanes& iz, float max_t, float* t_enter) {
#if defined(__SSE2__)
    const __m128 tx0 = _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(n.min_x), ox), ix);
    const __m128 tx1 = _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(n.max_x), ox), ix);
    const __m128 ty0 = _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(n.min_y), oy), iy);
    const __m128 ty1 = _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(n.max_y), oy), iy);
    const __m128 tz0 = _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(n.min_z), oz), iz);
    const __m128 tz1 = _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(n.max_z), oz), iz);
    const __m128 tmin = _mm_max_ps(_mm_max_ps(_mm_min_ps(tx0, tx1), _mm_min_ps(ty0, ty1)),
                                   _mm_max_ps(_mm_min_ps(tz0, tz1), _mm_setzero_ps()));
    const __m128 tmax = _mm_min_ps(_mm_min_ps(_mm_max_ps(tx0, tx1), _mm_max_ps(ty0, ty1)),
                                   _mm_min_ps(_mm_max_ps(tz0, tz1), _mm_set1_ps(max_t)));
    _mm_storeu_ps(t_enter, tmin);
    return _mm_movemask_ps(_mm_cmple_ps(tmin, _mm_mul_ps(tmax, _mm_set1_ps(kExitWiden)))) & n.lanes;
#else
    int mask = 0;
    for (int k = 0; k < 4; ++k)
        if (ray_aabb({ox.v[0], oy.v[0], oz.v[0]}, {ix.v[0], iy.v[0], iz.v[0]},
                     {n.min_x[k], n.min_y[k], n.min_z[k]}, {n.max_x[k], n.max_y[k], n.max_z[k]}, max_t,
                     t_enter[k]))
            mask |= 1 << k;
    return mask & n.lanes;
#endif
}

template <class Visit>
void Bvh::ray_query(const Ray& ray, float max_t, Visit&& visit) const {
    const Vec3 inv = safe_inverse(ray.direction);
    ray_query_leaves(ray, inv, max_t, [&](std::uint32_t leaf_index, float& t) {
        const LeafRange leaf = leaves_[leaf_index];
        for (std::uint32_t i = 0; i < leaf.count; ++i)
            if (!visit(leaf.first + i, inv, t)) return false;
        return true;
    });
}

template <class VisitLeaf>
void Bvh::ray_query_leaves(const Ray& ray, const Vec3& inv, float max_t, VisitLeaf&& visit) const {
    if (wide_.empty()) return;
    const Lanes ox = splat(ray.origin.x), oy = splat(ray.origin.y), oz = splat(ray.origin.z);
    const Lanes ix = splat(inv.x), iy = splat(inv.y), iz = splat(inv.z);
    struct Pending {
        std::int32_t child;
        float t;
    };
    Pending stack[kMaxDepth * 4];
    int top = 0;
    stack[top++] = {0, 0.0f};
    while (top > 0) {
        const Pending p = stack[--top];
        if (p.t > max_t) continue; // a closer hit was found meanwhile
        if (p.child < 0) {         // leaf
            if (!visit(static_cast<std::uint32_t>(~p.child), max_t)) return;
            continue;
        }
        const WideNode& n = wide_[p.child];
        float t_enter[4];
        const int mask = slab4(n, ox, oy, oz, ix, iy, iz, max_t, t_enter);
        if (!mask) continue;
        if ((mask & (mask - 1)) == 0) { // one child hit (the common case deep in the tree): no sorting
            const int k = std::countr_zero(static_cast<unsigned>(mask));
            stack[top++] = {n.child[k], t_enter[k]};
            continue;
        }
        const int rest = mask & (mask - 1);
        if ((rest & (rest - 1)) == 0) { // two children hit: push the farther first (ties: lane order)
            const int a = std::countr_zero(static_cast<unsigned>(mask)),
                      b = std::countr_zero(static_cast<unsigned>(rest));
            const bool b_farther = t_enter[a] < t_enter[b];
            const int first = b_farther ? b : a, second = b_farther ? a : b;
            stack[top++] = {n.child[first], t_enter[first]};
            stack[top++] = {n.child[second], t_enter[second]};
            continue;
        }
        // Push the hit children farthest first, so the nearest is popped next.
        int order[4], count = 0;
        for (int k = 0; k < 4; ++k)
            if (mask & (1 << k)) {
                int j = count++;
                while (j > 0 && t_enter[order[j - 1]] < t_enter[k]) order[j] = order[j - 1], --j;
                order[j] = k;
            }
        for (int j = 0; j < count; ++j) stack[top++] = {n.child[order[j]], t_enter[order[j]]};
    }
}

template <class Visit>
void Bvh::aabb_query(const Aabb& box, Visit&& visit) const {
    if (wide_.empty()) return;
    std::int32_t stack[kMaxDepth * 4];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const std::int32_t ref = stack[--top];
        if (ref < 0) {
            const LeafRange leaf = leaves_[~ref];
            for (std::uint32_t i = 0; i < leaf.count; ++i)
                if (!visit(leaf.first + i)) return;
            continue;
        }
        const WideNode& n = wide_[ref];
        int mask = n.lanes;
#if defined(__SSE2__)
        const __m128 lo = _mm_and_ps(_mm_and_ps(_mm_cmple_ps(_mm_loadu_ps(n.min_x), _mm_set1_ps(box.max.x)),
                                                _mm_cmple_ps(_mm_loadu_ps(n.min_y), _mm_set1_ps(box.max.y))),
                                     _mm_cmple_ps(_mm_loadu_ps(n.min_z), _mm_set1_ps(box.max.z)));
        const __m128 hi = _mm_and_ps(_mm_and_ps(_mm_cmpge_ps(_mm_loadu_ps(n.max_x), _mm_set1_ps(box.min.x)),
                                                _mm_cmpge_ps(_mm_loadu_ps(n.max_y), _mm_set1_ps(box.min.y))),
                                     _mm_cmpge_ps(_mm_loadu_ps(n.max_z), _mm_set1_ps(box.min.z)));
        mask &= _mm_movemask_ps(_mm_and_ps(lo, hi));
#else
        for (int k = 0; k < 4; ++k)
            if (!(n.min_x[k] <= box.max.x && n.min_y[k] <= box.max.y && n.min_z[k] <= box.max.z &&
                  n.max_x[k] >= box.min.x && n.max_y[k] >= box.min.y && n.max_z[k] >= box.min.z))
                mask &= ~(1 << k);
#endif
        for (int k = 3; k >= 0; --k)
            if (mask & (1 << k)) stack[top++] = n.child[k];
    }
}

} // namespace ks::physics
