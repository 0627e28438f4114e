#pragma once
// A static bounding-volume hierarchy over AABBs, built once with the surface-area heuristic (binned, 32
// bins on the widest centroid axis, leaves of at most 4 items), then collapsed into one contiguous array of
// 8-wide nodes for queries. Queries allocate nothing: traversal uses a fixed stack; the caller's visitor is
// inlined (templates). Ray traversal runs an AVX2 or a portable kernel (see RayKernel).
#include "physics/ray.h"
#include "physics/shapes.h"

#include <bit>
#include <cstdint>
#include <span>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h> // AVX2 intrinsics, used only inside the target("avx2") traversal below
#endif

namespace ks::physics {

// Which SIMD kernel ray traversal uses. Portable is SSE2 on x86-64 (always present there) and plain C++
// elsewhere; Avx2 tests all eight children of a node with one 8-lane slab test. Both perform the same
// float operations in the same order (no FMA: the AVX2 code is compiled for "avx2" only, so nothing can be
// contracted), so they return bit-identical hits; tests run both where the CPU has AVX2.
enum class RayKernel : std::uint8_t { Portable, Avx2 };
bool cpu_has_avx2();
RayKernel ray_kernel(); // the kernel ray queries use now: Avx2 when the CPU has it, unless overridden
// Tests and benchmarks: forces a kernel; returns false (and changes nothing) when the CPU lacks it.
bool set_ray_kernel(RayKernel kernel);

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
    static constexpr int kWidth = 8;

    // items[i] is the box of item i; afterwards item_order() maps leaf slots to item indices.
    void build(std::span<const geometry::Aabb> items);
    void clear();
    bool empty() const { return nodes_.empty(); }
    std::span<const Node> nodes() const { return nodes_; }
    std::span<const std::uint32_t> item_order() const { return order_; }
    int depth() const { return depth_; }
    std::size_t wide_node_count() const { return wide_.size(); }

    // Visits leaf slots (positions in item_order(), so per-item data stored in that order is read
    // contiguously) whose box the ray crosses within [0, max_t], nearest node first. visit(slot, inv_dir,
    // max_t&) returns false to stop; it may shrink max_t (closest-hit queries) to prune the rest.
    template <class Visit>
    void ray_query(const geometry::Ray& ray, float max_t, Visit&& visit) const;
    // The same traversal handing over whole leaves: visit(leaf, max_t&) with leaf an index into leaves(),
    // so callers can test a leaf's items together (SIMD). Returns false to stop.
    // `inv` is safe_inverse(ray.direction), computed once by the caller. Runs the kernel ray_kernel() names.
    template <class VisitLeaf>
    void ray_query_leaves(const geometry::Ray& ray, const Vec3& inv, float max_t, VisitLeaf&& visit) const {
        if (ray_kernel() == RayKernel::Avx2)
            ray_query_leaves_avx2(ray, inv, max_t, visit);
        else
            ray_query_leaves_portable(ray, inv, max_t, visit);
    }
    struct LeafRange {
        std::uint32_t first, count; // leaf slots [first, first + count)
    };
    std::span<const LeafRange> leaves() const { return leaves_; }
    // Visits leaf slots whose node box overlaps `box`, in leaf order. visit(slot) returns false to stop.
    template <class Visit>
    void aabb_query(const geometry::Aabb& box, Visit&& visit) const;

  private:
    // The binary tree collapsed to eight children per node (SAH decides the shape; collapsing halves the
    // depth twice over), bounds stored lane-wise so one 8-lane (or two 4-lane) slab test handles a node.
    struct alignas(64) WideNode {   // 256 bytes: four cache lines
        float bounds[6][kWidth];    // min x, y, z then max x, y, z; an empty lane holds an inverted box
        std::int32_t child[kWidth]; // >= 0: wide node; < 0: ~leaf index
        std::int32_t lanes;         // bit k set when child k exists
    };
    void build_wide();

    template <class VisitLeaf>
    void ray_query_leaves_portable(const geometry::Ray& ray, const Vec3& inv, float max_t,
                                   VisitLeaf& visit) const;
    template <class VisitLeaf>
    void ray_query_leaves_avx2(const geometry::Ray& ray, const Vec3& inv, float max_t,
                               VisitLeaf& visit) const;

    std::vector<WideNode> wide_;
    std::vector<LeafRange> leaves_;
    std::vector<Node> nodes_;
    std::vector<std::uint32_t> order_;
    int depth_ = 0;
};

namespace bvh_detail {
// Orders the hit children of a node by entry distance: pushes all but the nearest (farthest first, so the
// nearest of them pops next) and returns the nearest. Ties keep lane order. mask has >= 2 bits set.
struct Pending {
    std::int32_t child;
    float t;
};
inline std::int32_t order_children(int mask, const float* t_enter, const std::int32_t* child, Pending* stack,
                                   int& top) {
    const int a = std::countr_zero(static_cast<unsigned>(mask));
    const int rest = mask & (mask - 1);
    if ((rest & (rest - 1)) == 0) { // two children hit (the usual case above the leaves): no sort
        const int b = std::countr_zero(static_cast<unsigned>(rest));
        const bool a_first = t_enter[a] <= t_enter[b];
        const int near = a_first ? a : b, far = a_first ? b : a;
        stack[top++] = {child[far], t_enter[far]};
        return child[near];
    }
    int order[8], count = 0; // ascending t_enter (insertion sort: at most 8, usually 3)
    for (int m = mask; m; m &= m - 1) {
        const int k = std::countr_zero(static_cast<unsigned>(m));
        int j = count++;
        while (j > 0 && t_enter[order[j - 1]] > t_enter[k]) order[j] = order[j - 1], --j;
        order[j] = k;
    }
    for (int j = count - 1; j > 0; --j) stack[top++] = {child[order[j]], t_enter[order[j]]};
    return child[order[0]];
}
} // namespace bvh_detail

template <class Visit>
void Bvh::ray_query(const geometry::Ray& ray, float max_t, Visit&& visit) const {
    const Vec3 inv = geometry::safe_inverse(ray.direction);
    ray_query_leaves(ray, inv, max_t, [&](std::uint32_t leaf_index, float& t) {
        const LeafRange leaf = leaves_[leaf_index];
        for (std::uint32_t i = 0; i < leaf.count; ++i)
            if (!visit(leaf.first + i, inv, t)) return false;
        return true;
    });
}

template <class Visit>
void Bvh::aabb_query(const geometry::Aabb& box, Visit&& visit) const {
    if (wide_.empty()) return;
    std::int32_t stack[kMaxDepth * kWidth];
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
        int mask = 0;
#if defined(__SSE2__)
        const __m128 bx0 = _mm_set1_ps(box.max.x), by0 = _mm_set1_ps(box.max.y), bz0 = _mm_set1_ps(box.max.z);
        const __m128 bx1 = _mm_set1_ps(box.min.x), by1 = _mm_set1_ps(box.min.y), bz1 = _mm_set1_ps(box.min.z);
        for (int h = 0; h < kWidth; h += 4) {
            const __m128 lo = _mm_and_ps(_mm_and_ps(_mm_cmple_ps(_mm_load_ps(&n.bounds[0][h]), bx0),
                                                    _mm_cmple_ps(_mm_load_ps(&n.bounds[1][h]), by0)),
                                         _mm_cmple_ps(_mm_load_ps(&n.bounds[2][h]), bz0));
            const __m128 hi = _mm_and_ps(_mm_and_ps(_mm_cmpge_ps(_mm_load_ps(&n.bounds[3][h]), bx1),
                                                    _mm_cmpge_ps(_mm_load_ps(&n.bounds[4][h]), by1)),
                                         _mm_cmpge_ps(_mm_load_ps(&n.bounds[5][h]), bz1));
            mask |= _mm_movemask_ps(_mm_and_ps(lo, hi)) << h;
        }
#else
        for (int k = 0; k < kWidth; ++k)
            if (n.bounds[0][k] <= box.max.x && n.bounds[1][k] <= box.max.y && n.bounds[2][k] <= box.max.z &&
                n.bounds[3][k] >= box.min.x && n.bounds[4][k] >= box.min.y && n.bounds[5][k] >= box.min.z)
                mask |= 1 << k;
#endif
        mask &= n.lanes;
        for (int k = kWidth - 1; k >= 0; --k)
            if (mask & (1 << k)) stack[top++] = n.child[k];
    }
}

} // namespace ks::physics

// The traversal loop, compiled twice: portable (SSE2 / scalar) and, inside a target("avx2") region, AVX2.
#define KS_BVH_TRAVERSE_AVX2 0
#include "physics/bvh_traverse.inl"
#undef KS_BVH_TRAVERSE_AVX2
#if defined(__x86_64__) && defined(__GNUC__)
// GCC takes the target from a pragma region; clang (the fuzz build) ignores `#pragma GCC target` and needs
// the attribute applied to each function in the region instead.
#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2")
#endif
#define KS_BVH_TRAVERSE_AVX2 1
#include "physics/bvh_traverse.inl"
#undef KS_BVH_TRAVERSE_AVX2
#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif
#else
namespace ks::physics {
template <class VisitLeaf>
void Bvh::ray_query_leaves_avx2(const geometry::Ray& ray, const Vec3& inv, float max_t,
                                VisitLeaf& visit) const {
    ray_query_leaves_portable(ray, inv, max_t, visit);
}
} // namespace ks::physics
#endif
