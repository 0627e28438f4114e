#include "physics/bvh.h"

#include <algorithm>
#include <cmath>

namespace ks::physics {
namespace {

constexpr int kBins = 32;

struct Builder {
    std::span<const geometry::Aabb> boxes;
    std::vector<Vec3> centres;
    std::vector<std::uint32_t>& order;
    std::vector<Bvh::Node>& nodes;
    int max_depth = 0;

    geometry::Aabb bounds_of(std::uint32_t first, std::uint32_t count) const {
        geometry::Aabb b = geometry::Aabb::empty();
        for (std::uint32_t i = first; i < first + count; ++i) b.grow(boxes[order[i]]);
        return b;
    }

    void build(std::uint32_t node_index, std::uint32_t first, std::uint32_t count, int depth) {
        max_depth = std::max(max_depth, depth);
        geometry::Aabb b = bounds_of(first, count);
        // Widen by a few ulps so the node test is conservative for every primitive inside it.
        const Vec3 pad = (glm::abs(b.min) + glm::abs(b.max)) * 1e-6f + Vec3(1e-6f);
        nodes[node_index].min = b.min - pad;
        nodes[node_index].max = b.max + pad;
        if (count <= 1 || depth >= Bvh::kMaxDepth - 2) return make_leaf(node_index, first, count);

        geometry::Aabb cb = geometry::Aabb::empty();
        for (std::uint32_t i = first; i < first + count; ++i) cb.grow(centres[order[i]]);
        const Vec3 ext = cb.max - cb.min;
        int axis = ext.x >= ext.y && ext.x >= ext.z ? 0 : (ext.y >= ext.z ? 1 : 2);
        std::uint32_t mid = first + count / 2;
        bool split_found = false;
        if (ext[axis] > 0.0f) {
            geometry::Aabb bin_box[kBins];
            std::uint32_t bin_count[kBins] = {};
            for (auto& bb : bin_box) bb = geometry::Aabb::empty();
            const float scale = kBins / ext[axis];
            auto bin_of = [&](std::uint32_t item) {
                int k = static_cast<int>((centres[item][axis] - cb.min[axis]) * scale);
                return std::clamp(k, 0, kBins - 1);
            };
            for (std::uint32_t i = first; i < first + count; ++i) {
                const int k = bin_of(order[i]);
                bin_box[k].grow(boxes[order[i]]);
                ++bin_count[k];
            }
            float right_area[kBins];
            std::uint32_t right_count[kBins];
            geometry::Aabb acc = geometry::Aabb::empty();
            std::uint32_t n = 0;
            for (int k = kBins - 1; k > 0; --k) {
                if (bin_count[k]) acc.grow(bin_box[k]);
                n += bin_count[k];
                right_area[k] = n ? acc.surface_area() : 0.0f;
                right_count[k] = n;
            }
            float best_cost = 3.4e38f;
            int best_split = -1;
            acc = geometry::Aabb::empty();
            n = 0;
            for (int k = 0; k < kBins - 1; ++k) {
                if (bin_count[k]) acc.grow(bin_box[k]);
                n += bin_count[k];
                if (n == 0 || right_count[k + 1] == 0) continue;
                const float cost = acc.surface_area() * n + right_area[k + 1] * right_count[k + 1];
                if (cost < best_cost) best_cost = cost, best_split = k;
            }
            const float leaf_cost = b.surface_area() * count;
            // Traversal costs about one box test per child; a leaf of <= kMaxLeafSize stays when cheaper.
            if (best_split >= 0) {
                if (count <= Bvh::kMaxLeafSize && best_cost + 2.0f * b.surface_area() >= leaf_cost)
                    return make_leaf(node_index, first, count);
                auto it = std::partition(order.begin() + first, order.begin() + first + count,
                                         [&](std::uint32_t item) { return bin_of(item) <= best_split; });
                mid = static_cast<std::uint32_t>(it - order.begin());
                split_found = mid > first && mid < first + count;
            }
        }
        if (!split_found) {
            if (count <= Bvh::kMaxLeafSize) return make_leaf(node_index, first, count);
            // Coincident centroids: split by index (median) so depth stays logarithmic.
            std::nth_element(
                order.begin() + first, order.begin() + mid, order.begin() + first + count,
                [&](std::uint32_t a, std::uint32_t b2) { return centres[a][axis] < centres[b2][axis]; });
        }
        const auto left = static_cast<std::uint32_t>(nodes.size());
        nodes.emplace_back();
        nodes.emplace_back();
        nodes[node_index].left_or_first = left;
        nodes[node_index].count = 0;
        build(left, first, mid - first, depth + 1);
        build(left + 1, mid, first + count - mid, depth + 1);
    }

    void make_leaf(std::uint32_t node_index, std::uint32_t first, std::uint32_t count) {
        nodes[node_index].left_or_first = first;
        nodes[node_index].count = count;
    }
};

} // namespace

void Bvh::build(std::span<const geometry::Aabb> items) {
    clear();
    if (items.empty()) return;
    order_.resize(items.size());
    for (std::uint32_t i = 0; i < items.size(); ++i) order_[i] = i;
    nodes_.reserve(items.size() * 2);
    nodes_.emplace_back();
    Builder b{items, {}, order_, nodes_};
    b.centres.resize(items.size());
    for (std::size_t i = 0; i < items.size(); ++i) b.centres[i] = items[i].center();
    b.build(0, 0, static_cast<std::uint32_t>(items.size()), 1);
    depth_ = b.max_depth;
    build_wide();
}

void Bvh::build_wide() {
    wide_.clear();
    leaves_.clear();
    // Each wide node takes a binary node's children, then repeatedly opens the largest inner child in place
    // of itself until it holds kWidth.
    struct Work {
        std::uint32_t binary;
        std::uint32_t wide;
    };
    std::vector<Work> work;
    auto child_ref = [&](std::uint32_t b) -> std::int32_t {
        const Node& n = nodes_[b];
        if (n.count > 0) {
            leaves_.push_back({n.left_or_first, n.count});
            return ~static_cast<std::int32_t>(leaves_.size() - 1);
        }
        wide_.emplace_back();
        work.push_back({b, static_cast<std::uint32_t>(wide_.size() - 1)});
        return static_cast<std::int32_t>(wide_.size() - 1);
    };
    auto fill = [&](WideNode& w, const std::uint32_t* kids, int count) {
        w.lanes = (1 << count) - 1;
        for (int k = 0; k < kWidth; ++k) {
            if (k < count) {
                const Node& n = nodes_[kids[k]];
                for (int a = 0; a < 3; ++a) w.bounds[a][k] = n.min[a], w.bounds[3 + a][k] = n.max[a];
                w.child[k] = child_ref(kids[k]);
            } else { // empty lane: an inverted box no ray or box query enters
                for (int a = 0; a < 3; ++a) w.bounds[a][k] = 3.4e38f, w.bounds[3 + a][k] = -3.4e38f;
                w.child[k] = 0;
            }
        }
    };
    auto first_slot = [&](std::uint32_t b) {
        while (nodes_[b].count == 0) b = nodes_[b].left_or_first;
        return nodes_[b].left_or_first;
    };
    if (nodes_[0].count > 0) { // a single leaf: wrap it
        wide_.emplace_back();
        WideNode w;
        const std::uint32_t root = 0;
        fill(w, &root, 1);
        wide_[0] = w;
        return;
    }
    wide_.emplace_back();
    work.push_back({0, 0});
    while (!work.empty()) {
        const Work job = work.back();
        work.pop_back();
        std::uint32_t kids[kWidth] = {nodes_[job.binary].left_or_first, nodes_[job.binary].left_or_first + 1};
        int count = 2;
        while (count < kWidth) {
            int best = -1;
            float best_area = -1.0f;
            for (int k = 0; k < count; ++k) {
                const Node& n = nodes_[kids[k]];
                const float area = geometry::Aabb{n.min, n.max}.surface_area();
                if (n.count == 0 && area > best_area) best_area = area, best = k;
            }
            if (best < 0) break;
            const std::uint32_t open = kids[best];
            kids[best] = nodes_[open].left_or_first;
            kids[count++] = nodes_[open].left_or_first + 1;
        }
        // Children in slot order (left to right in the binary tree), so box queries visit leaf slots in
        // ascending order whatever the width: the character controller sees its obstacles in that order.
        std::sort(kids, kids + count,
                  [&](std::uint32_t a, std::uint32_t b) { return first_slot(a) < first_slot(b); });
        WideNode w;
        fill(w, kids, count);
        wide_[job.wide] = w;
    }
}

void Bvh::clear() {
    nodes_.clear();
    wide_.clear();
    leaves_.clear();
    order_.clear();
    depth_ = 0;
}

namespace {
RayKernel detect_kernel() {
#if defined(__x86_64__) && defined(__GNUC__)
    __builtin_cpu_init(); // this runs during static initialisation, possibly before libgcc's own
    return __builtin_cpu_supports("avx2") ? RayKernel::Avx2 : RayKernel::Portable;
#else
    return RayKernel::Portable;
#endif
}
RayKernel g_kernel = detect_kernel();
} // namespace

bool cpu_has_avx2() {
    static const bool has = detect_kernel() == RayKernel::Avx2;
    return has;
}

RayKernel ray_kernel() {
    return g_kernel;
}

bool set_ray_kernel(RayKernel kernel) {
    if (kernel == RayKernel::Avx2 && !cpu_has_avx2()) return false;
    g_kernel = kernel;
    return true;
}

} // namespace ks::physics
