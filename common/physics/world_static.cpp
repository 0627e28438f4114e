// The static set: the BVH over static bodies and the compact per-leaf copies that rays read.
#include "physics/world.h"

namespace ks::physics {

void World::build_static() const {
    if (!static_dirty_) return;
    std::vector<geometry::Aabb> boxes;
    std::vector<std::uint32_t> items;
    for (std::uint32_t i = 0; i < bodies_.size(); ++i) {
        const Body& b = bodies_[i];
        if (b.alive && b.motion == Motion::Static && !b.trigger) {
            boxes.push_back(b.bounds);
            items.push_back(i);
        }
    }
    static_bvh_.build(boxes);
    static_prims_.resize(items.size());
    static_slot_of_.assign(bodies_.size(), kNone);
    auto order = static_bvh_.item_order();
    for (std::size_t slot = 0; slot < order.size(); ++slot) {
        const std::uint32_t bi = items[order[slot]];
        const Body& b = bodies_[bi];
        StaticPrim& p = static_prims_[slot];
        p.position = b.transform.position;
        p.body = bi;
        p.rotation = b.transform.rotation;
        p.half = b.shape.half_extents;
        p.layers = b.layers;
        p.kind = b.shape.kind;
        p.axis_aligned = b.transform.rotation == Quat(1.0f, 0.0f, 0.0f, 0.0f);
        p.enabled = b.enabled;
        static_slot_of_[bi] = static_cast<std::uint32_t>(slot);
    }
    static_assert(Bvh::kMaxLeafSize <= 4, "a leaf must fit one packet");
    static_packets_.clear();
    for (const Bvh::LeafRange& leaf : static_bvh_.leaves()) {
        BoxPacket bp{};
        bp.first_slot = leaf.first;
        for (std::uint32_t k = 0; k < leaf.count; ++k) {
            const StaticPrim& p = static_prims_[leaf.first + k];
            bp.layers[k] = p.enabled ? p.layers : 0u;
            bp.body[k] = p.body;
            if (p.kind == ShapeKind::Box && p.axis_aligned) {
                bp.cx[k] = p.position.x, bp.cy[k] = p.position.y, bp.cz[k] = p.position.z;
                bp.hx[k] = p.half.x, bp.hy[k] = p.half.y, bp.hz[k] = p.half.z;
                bp.boxes |= 1u << k;
            } else {
                // Anything else gets its world bounds, padded like the BVH's node boxes, as a conservative
                // prefilter: the lane's own test runs only when the ray enters these bounds.
                const geometry::Aabb& wb = bodies_[p.body].bounds;
                const Vec3 c = wb.center(), e = (wb.max - wb.min) * 0.5f;
                const Vec3 h = e + (glm::abs(c) + e) * 2e-6f + Vec3(1e-5f);
                bp.cx[k] = c.x, bp.cy[k] = c.y, bp.cz[k] = c.z;
                bp.hx[k] = h.x, bp.hy[k] = h.y, bp.hz[k] = h.z;
                bp.others |= 1u << k;
            }
        }
        static_packets_.push_back(bp);
    }
    static_leaf_of_.resize(static_prims_.size());
    for (std::uint32_t leaf = 0; leaf < static_bvh_.leaves().size(); ++leaf)
        for (std::uint32_t k = 0; k < static_bvh_.leaves()[leaf].count; ++k)
            static_leaf_of_[static_bvh_.leaves()[leaf].first + k] = leaf;
    ++static_epoch_;
    static_dirty_ = false;
}

const Bvh& World::static_bvh() const {
    build_static();
    return static_bvh_;
}

} // namespace ks::physics
