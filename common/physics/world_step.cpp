// A world step: the movers' hash grid, the character obstacles it and the static BVH supply, moving the
// characters, trigger overlaps and the callbacks.
#include "physics/world.h"

#include "physics/triangle_mesh.h"

#include <algorithm>
#include <cmath>

namespace ks::physics {

namespace {
bool contains(const geometry::Aabb& outer, const geometry::Aabb& inner) {
    return outer.min.x <= inner.min.x && outer.min.y <= inner.min.y && outer.min.z <= inner.min.z &&
           inner.max.x <= outer.max.x && inner.max.y <= outer.max.y && inner.max.z <= outer.max.z;
}
} // namespace

// What the character controller may collide with: static bodies from the BVH, then movers from the
// sorted sweep list, excluding the character itself and anything its mask ignores.
class World::Obstacles final : public ObstacleSource {
  public:
    explicit Obstacles(const World& w) : world_(w) {}
    std::uint32_t self = kNone;
    std::uint32_t mask = 0;
    StaticCache* cache = nullptr; // the character's static neighbourhood (null: query the BVH directly)
    void gather(const geometry::Aabb& region, std::vector<Obstacle>& out) const override {
        const World& w = world_;
        auto add_static = [&](std::uint32_t slot) {
            const StaticPrim& p = w.static_prims_[slot];
            const Body& b = w.bodies_[p.body];
            if (p.enabled && (p.layers & mask) && b.bounds.overlaps(region))
                body_obstacles(b, p.body, region, [&](const Obstacle& o) { out.push_back(o); });
            return true;
        };
        if (!cache) {
            w.static_bvh_.aabb_query(region, add_static);
        } else {
            // Valid while the static set is the same and the bodies have not moved in memory (the cached
            // obstacles point at their shapes).
            if (cache->epoch != w.static_epoch_ || cache->bodies != w.bodies_.data() ||
                !contains(cache->region, region)) {
                cache->region = region.expanded(kStaticCacheMargin);
                cache->epoch = w.static_epoch_;
                cache->bodies = w.bodies_.data();
                cache->entries.clear();
                cache->usable_epoch = ~std::uint64_t{0};
                w.static_bvh_.aabb_query(cache->region, [&](std::uint32_t slot) {
                    const StaticPrim& p = w.static_prims_[slot];
                    const Body& b = w.bodies_[p.body];
                    if (!b.bounds.overlaps(cache->region)) return true;
                    body_obstacles(b, p.body, cache->region, [&](const Obstacle& o) {
                        cache->entries.push_back({o, slot});
                    });
                    return true;
                });
            }
            if (cache->usable_epoch != w.enabled_epoch_ || cache->usable_mask != mask) {
                cache->usable.clear();
                for (const StaticCache::Entry& e : cache->entries) {
                    const StaticPrim& p = w.static_prims_[e.slot];
                    if (p.enabled && (p.layers & mask)) cache->usable.push_back(e.obstacle);
                }
                cache->usable_epoch = w.enabled_epoch_;
                cache->usable_mask = mask;
            }
            for (const Obstacle& o : cache->usable)
                if (o.bounds.overlaps(region)) out.push_back(o);
        }
        const std::size_t first_mover = out.size();
        w.movers_overlapping(region, [&](std::uint32_t index) {
            const Body& b = w.bodies_[index];
            if (index != self && b.enabled && !b.trigger && (b.layers & mask))
                out.push_back({&b.shape, b.transform, index, b.yaw_only, b.bounds});
        });
        // Movers in body order, not the grid's visiting order: what the controller does (which contact wins
        // a tie) then does not depend on the grid's cell size. Usually zero to two entries.
        for (std::size_t i = first_mover + 1; i < out.size(); ++i)
            for (std::size_t j = i; j > first_mover && out[j - 1].id > out[j].id; --j)
                std::swap(out[j - 1], out[j]);
    }

  private:
    // A body as obstacles: itself, or a mesh's triangles that reach into `region` (physics/triangle_mesh.h).
    template <class Out>
    static void body_obstacles(const Body& b, std::uint32_t index, const geometry::Aabb& region, Out&& out) {
        if (b.shape.kind != ShapeKind::Mesh) {
            out(Obstacle{&b.shape, b.transform, index, b.yaw_only, b.bounds});
            return;
        }
        mesh_triangles_in(*b.shape.mesh, b.transform, region,
                          [&](std::uint32_t triangle, const geometry::Aabb& bounds) {
                              out(Obstacle{&b.shape, b.transform, index, b.yaw_only, bounds, triangle});
                          });
    }
    const World& world_;
};

// ---- movers: the grid (physics/mover_grid.h) or every mover -------------------------------------------

namespace {
constexpr float kDepenetrationMargin = 0.5f; // x/z units a push may add to a step's travel
} // namespace

void World::index_movers(float dt) {
    if (settings_.movers == MoverBroadphase::AllPairs) return;
    float max_speed = 0.0f;
    for (std::uint32_t index : movers_) {
        const Body& b = bodies_[index];
        if (b.character_slot != kNone) {
            const auto& m = characters_[b.character_slot].state.movement;
            const float v =
                glm::length(m.velocity) + (glm::length(m.acceleration) + std::abs(m.gravity)) * dt;
            if (std::isfinite(v)) max_speed = std::max(max_speed, std::min(v, 2.0f * m.max_speed));
        }
    }
    // Depenetration can push a character further than its velocity takes it. A small margin covers the
    // usual push; a character pushed further leaves its cell for the list every query reads, so the margin
    // trades the query box's width against that list, never correctness (docs/performance.md).
    const float slack = max_speed * dt + kDepenetrationMargin;
    mover_start_bounds_.resize(movers_.size());
    if (mover_position_.size() < bodies_.size()) mover_position_.resize(bodies_.size(), kNone);
    for (std::size_t i = 0; i < movers_.size(); ++i) {
        mover_start_bounds_[i] = bodies_[movers_[i]].bounds;
        mover_position_[movers_[i]] = static_cast<std::uint32_t>(i);
    }
    mover_grid_.build(mover_start_bounds_, slack);
    grid_valid_ = true;
}

template <class Visit>
void World::movers_overlapping(const geometry::Aabb& region, Visit&& visit) const {
    // Bodies added since the last step are not in the grid yet: scan them all (as the reference does).
    if (!grid_valid_ || settings_.movers == MoverBroadphase::AllPairs) {
        for (std::uint32_t index : movers_)
            if (bodies_[index].bounds.overlaps(region)) visit(index);
        return;
    }
    mover_grid_.query(region, [&](std::uint32_t position) { visit(movers_[position]); });
}

// ---- step ---------------------------------------------------------------------------------------------

void World::step(float dt) {
    if (!(dt > 0.0f) || !std::isfinite(dt)) return;
    build_static();
    collisions_.clear();
    trigger_events_.clear();
    index_movers(dt);
    for (std::uint32_t index : movers_) bodies_[index].previous_position = bodies_[index].transform.position;
    Obstacles obstacles(*this);
    for (std::size_t c = 0; c < characters_.size(); ++c) {
        CharacterData& cd = characters_[c];
        Body& b = bodies_[cd.body];
        if (!b.enabled) continue;
        obstacles.self = cd.body;
        obstacles.mask = b.collides_with;
        obstacles.cache = &cd.statics;
        move_character(obstacles, b.shape.radius, b.shape.half_height, cd.settings, cd.state,
                       b.transform.position, dt, scratch_);
        b.bounds = b.shape.bounds(b.transform);
        if (grid_valid_) mover_grid_.update(mover_position_[cd.body], b.bounds);
        const BodyId self = id_of(cd.body);
        for (const CharacterContact& cc : scratch_.contacts) {
            const BodyId other = id_of(cc.obstacle_id);
            collisions_.push_back(
                {self, other, cc.contact.point, cc.contact.normal, cc.contact.penetration, dt});
            collisions_.push_back(
                {other, self, cc.contact.point, -cc.contact.normal, cc.contact.penetration, dt});
        }
    }
    update_triggers(dt);
    dispatch();
}

float World::advance(double frame_dt) {
    const int steps = clock_.advance(frame_dt);
    for (int i = 0; i < steps; ++i) step(static_cast<float>(clock_.step()));
    return static_cast<float>(clock_.alpha());
}

void World::update_triggers(float) {
    std::swap(trigger_pairs_prev_, trigger_pairs_);
    trigger_pairs_.clear();
    auto test = [&](std::uint32_t trig) {
        const Body& t = bodies_[trig];
        if (!t.enabled) return;
        movers_overlapping(t.bounds, [&](std::uint32_t index) {
            const Body& b = bodies_[index];
            if (b.character_slot == kNone || !b.enabled) return;
            if (collide_capsule_shape(capsule_segment(b.shape, b.transform.position), b.shape.radius, t.shape,
                                      t.transform))
                trigger_pairs_.push_back(static_cast<std::uint64_t>(trig) << 32 | index);
        });
    };
    for (std::uint32_t trig : static_triggers_) test(trig);
    for (std::uint32_t index : movers_)
        if (bodies_[index].trigger) test(index);
    std::sort(trigger_pairs_.begin(), trigger_pairs_.end());
    // Merge the two sorted lists: only in the new one = enter, in both = stay, only in the old one = exit.
    std::size_t i = 0, j = 0;
    auto event = [&](std::uint64_t pair, TriggerEvent::Kind kind) {
        const auto trig = static_cast<std::uint32_t>(pair >> 32), other = static_cast<std::uint32_t>(pair);
        trigger_events_.push_back({kind, id_of(trig), id_of(other)});
    };
    while (i < trigger_pairs_.size() || j < trigger_pairs_prev_.size()) {
        if (j == trigger_pairs_prev_.size() ||
            (i < trigger_pairs_.size() && trigger_pairs_[i] < trigger_pairs_prev_[j])) {
            event(trigger_pairs_[i++], TriggerEvent::Kind::Enter);
        } else if (i == trigger_pairs_.size() || trigger_pairs_prev_[j] < trigger_pairs_[i]) {
            event(trigger_pairs_prev_[j++], TriggerEvent::Kind::Exit);
        } else {
            event(trigger_pairs_[i++], TriggerEvent::Kind::Stay);
            ++j;
        }
    }
}

void World::dispatch() {
    // Indices, not iterators: callbacks may add bodies; events of bodies removed meanwhile are skipped.
    // Without any collision callback the loop would only check handles: skip it (100 characters make 200
    // collision events per step).
    const std::size_t n = collision_callbacks_ > 0 ? collisions_.size() : 0;
    for (std::size_t i = 0; i < n; ++i) {
        const Collision c = collisions_[i];
        if (!valid(c.self) || !valid(c.other)) continue;
        if (auto cb = on_collision_[c.self.index]) (*cb)(*this, c);
    }
    const std::size_t m = trigger_events_.size();
    for (std::size_t i = 0; i < m; ++i) {
        const TriggerEvent e = trigger_events_[i];
        if (!valid(e.trigger)) continue;
        if (e.kind != TriggerEvent::Kind::Exit && !valid(e.other)) continue;
        if (auto cb = on_trigger_[e.trigger.index]) (*cb)(*this, e);
    }
}

} // namespace ks::physics
