#pragma once
// A static bounding-volume hierarchy over AABBs, built once with the surface-area heuristic (binned, 32
// bins on the widest centroid axis), stored as one contiguous array of 32-byte nodes. Queries allocate
// nothing: traversal uses a fixed stack; the caller's visitor is inlined (templates).
#include "physics/ray.h"
#include "physics/shapes.h"

#include <cstdint>
#include <span>
#include <vector>

namespace ks::physics {

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
    // contiguously) whose box the ray crosses within [0, max_t], nearest node first. visit(slot, max_t&)
    // returns false to stop; it may shrink max_t (closest-hit queries) to prune the rest.
    template <class Visit>
    void ray_query(const Ray& ray, float max_t, Visit&& visit) const;
    // Visits leaf slots whose node box overlaps `box`. visit(slot) returns false to stop.
    template <class Visit>
    void aabb_query(const Aabb& box, Visit&& visit) const;

  private:
    std::vector<Node> nodes_;
    std::vector<std::uint32_t> order_;
    int depth_ = 0;
};

template <class Visit>
void Bvh::ray_query(const Ray& ray, float max_t, Visit&& visit) const {
    if (nodes_.empty()) return;
    const Vec3 inv = safe_inverse(ray.direction);
    struct Pending {
        std::uint32_t node;
        float t;
    };
    Pending stack[kMaxDepth * 2];
    int top = 0;
    float t_root;
    if (!ray_aabb(ray, inv, {nodes_[0].min, nodes_[0].max}, max_t, t_root)) return;
    std::uint32_t current = 0;
    for (;;) {
        const Node& node = nodes_[current];
        if (node.count > 0) {
            for (std::uint32_t i = 0; i < node.count; ++i)
                if (!visit(node.left_or_first + i, max_t)) return;
        } else {
            const std::uint32_t l = node.left_or_first, r = l + 1;
            float tl, tr;
            const bool hl = ray_aabb(ray, inv, {nodes_[l].min, nodes_[l].max}, max_t, tl);
            const bool hr = ray_aabb(ray, inv, {nodes_[r].min, nodes_[r].max}, max_t, tr);
            if (hl && hr) {
                if (tr < tl) {
                    stack[top++] = {l, tl};
                    current = r;
                } else {
                    stack[top++] = {r, tr};
                    current = l;
                }
                continue;
            }
            if (hl || hr) {
                current = hl ? l : r;
                continue;
            }
        }
        // Pop, skipping nodes that a shrunk max_t (closest hit found meanwhile) now excludes.
        for (;;) {
            if (top == 0) return;
            const Pending p = stack[--top];
            if (p.t <= max_t) {
                current = p.node;
                break;
            }
        }
    }
}

template <class Visit>
void Bvh::aabb_query(const Aabb& box, Visit&& visit) const {
    if (nodes_.empty()) return;
    std::uint32_t stack[kMaxDepth * 2];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        if (!box.overlaps({node.min, node.max})) continue;
        if (node.count > 0) {
            for (std::uint32_t i = 0; i < node.count; ++i)
                if (!visit(node.left_or_first + i)) return;
        } else {
            stack[top++] = node.left_or_first + 1;
            stack[top++] = node.left_or_first;
        }
    }
}

} // namespace ks::physics
