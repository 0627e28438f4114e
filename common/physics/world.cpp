#include "physics/world.h"

#include "core/log.h"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace ks::physics {

namespace {
constexpr std::uint32_t kNone = 0xffffffffu;
bool contains(const geometry::Aabb& outer, const geometry::Aabb& inner) {
    return outer.min.x <= inner.min.x && outer.min.y <= inner.min.y && outer.min.z <= inner.min.z &&
           inner.max.x <= outer.max.x && inner.max.y <= outer.max.y && inner.max.z <= outer.max.z;
}
constexpr float kMaxCoordinate = 1e7f; // beyond this float spacing is > 1 unit: refuse instead of drifting
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
                out.push_back({&b.shape, b.transform, p.body, b.yaw_only, b.bounds});
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
                w.static_bvh_.aabb_query(cache->region, [&](std::uint32_t slot) {
                    const StaticPrim& p = w.static_prims_[slot];
                    const Body& b = w.bodies_[p.body];
                    if (b.bounds.overlaps(cache->region))
                        cache->entries.push_back(
                            {{&b.shape, b.transform, p.body, b.yaw_only, b.bounds}, slot});
                    return true;
                });
            }
            for (const StaticCache::Entry& e : cache->entries) {
                const StaticPrim& p = w.static_prims_[e.slot]; // enabled may change between steps
                if (p.enabled && (p.layers & mask) && e.obstacle.bounds.overlaps(region))
                    out.push_back(e.obstacle);
            }
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
    const World& world_;
};

World::World(WorldSettings settings)
    : settings_(settings),
      clock_(settings.step > 0.0 ? settings.step : 1.0 / 120.0, settings.max_steps_per_frame) {}

World::Body* World::get(BodyId id) {
    if (id.index >= bodies_.size()) return nullptr;
    Body& b = bodies_[id.index];
    return b.alive && b.generation == id.generation ? &b : nullptr;
}
const World::Body* World::get(BodyId id) const {
    return const_cast<World*>(this)->get(id);
}
bool World::valid(BodyId id) const {
    return get(id) != nullptr;
}

Result<BodyId> World::add(const BodyDesc& desc, const std::string& what) {
    if (auto v = desc.shape.validate(what); !v) return v.error();
    const Vec3& p = desc.transform.position;
    if (!is_finite(p) || std::abs(p.x) > kMaxCoordinate || std::abs(p.y) > kMaxCoordinate ||
        std::abs(p.z) > kMaxCoordinate)
        return Error(what + ": position is not finite or beyond 1e7", Location(what),
                     "place bodies within +-1e7 units of the origin");
    if (!is_finite(desc.transform.rotation) || std::abs(glm::length(desc.transform.rotation) - 1.0f) > 1e-3f)
        return Error(what + ": rotation is not a unit quaternion", Location(what),
                     "build rotations with quat_from_ypr");
    if (desc.motion == Motion::Character && (desc.shape.kind != ShapeKind::Capsule || desc.trigger))
        return Error(what + ": a character must be a (non-trigger) capsule", Location(what),
                     "use Shape::capsule(radius, half_segment) for player and robots");
    std::uint32_t index;
    if (!free_slots_.empty()) {
        index = free_slots_.back();
        free_slots_.pop_back();
    } else {
        index = static_cast<std::uint32_t>(bodies_.size());
        bodies_.emplace_back();
        on_collision_.emplace_back();
        on_trigger_.emplace_back();
    }
    Body& b = bodies_[index];
    const std::uint32_t generation = b.generation + 1;
    b = Body{};
    b.generation = generation;
    b.shape = desc.shape;
    b.transform = desc.transform;
    b.transform.rotation = glm::normalize(desc.transform.rotation);
    b.previous_position = p;
    b.bounds = b.shape.bounds(b.transform);
    // A trigger is only a trigger: it never blocks, stops shots or hides anything (custom bits kept).
    b.layers = desc.trigger ? (desc.layers & ~layer::kDefault) | layer::kTrigger
                            : desc.layers | (desc.motion == Motion::Character ? layer::kCharacter : 0u);
    b.collides_with = desc.collides_with;
    b.user_data = desc.user_data;
    b.motion = desc.motion;
    b.trigger = desc.trigger;
    b.alive = true;
    b.yaw_only = is_yaw_only(b.transform.rotation);
    ++live_count_;
    if (b.motion == Motion::Character) {
        b.character_slot = static_cast<std::uint32_t>(characters_.size());
        CharacterData cd;
        cd.body = index;
        cd.settings = desc.character;
        cd.state.movement = desc.movement;
        characters_.push_back(cd);
    }
    if (b.motion == Motion::Static && !b.trigger)
        mark_static_dirty();
    else if (b.motion == Motion::Static)
        static_triggers_.push_back(index);
    else {
        movers_.push_back(index);
        grid_valid_ = false; // not in the grid until the next step indexes it
    }
    return BodyId{index, generation};
}

void World::remove(BodyId id) {
    Body* b = get(id);
    if (!b) return;
    const std::uint32_t index = id.index;
    if (b->motion == Motion::Static && !b->trigger) {
        mark_static_dirty();
    } else if (b->motion == Motion::Static) {
        static_triggers_.erase(std::find(static_triggers_.begin(), static_triggers_.end(), index));
    } else {
        movers_.erase(std::find(movers_.begin(), movers_.end(), index));
        // Its grid entries stay until the next step; queries skip dead bodies.
    }
    if (b->character_slot != kNone) {
        const std::uint32_t slot = b->character_slot;
        characters_[slot] = std::move(characters_.back());
        characters_.pop_back();
        if (slot < characters_.size()) bodies_[characters_[slot].body].character_slot = slot;
    }
    b->alive = false;
    ++b->generation; // stale handles no longer resolve
    if (on_collision_[index]) --collision_callbacks_;
    on_collision_[index].reset();
    on_trigger_[index].reset();
    free_slots_.push_back(index);
    --live_count_;
}

void World::set_enabled(BodyId id, bool enabled) {
    if (Body* b = get(id)) {
        b->enabled = enabled;
        if (!static_dirty_ && id.index < static_slot_of_.size() && static_slot_of_[id.index] != kNone) {
            const std::uint32_t slot = static_slot_of_[id.index];
            static_prims_[slot].enabled = enabled;
            BoxPacket& bp = static_packets_[static_leaf_of_[slot]];
            bp.layers[slot - bp.first_slot] = enabled ? b->layers : 0u;
        }
    }
}
bool World::enabled(BodyId id) const {
    const Body* b = get(id);
    return b && b->enabled;
}

Transform World::transform(BodyId id) const {
    const Body* b = get(id);
    return b ? b->transform : Transform{};
}

void World::set_transform(BodyId id, const Transform& xf) {
    Body* b = get(id);
    if (!b || !is_finite(xf.position) || !is_finite(xf.rotation)) return;
    b->transform = xf;
    b->transform.rotation = glm::normalize(xf.rotation);
    b->yaw_only = is_yaw_only(b->transform.rotation);
    b->bounds = b->shape.bounds(b->transform);
    if (b->motion == Motion::Character) b->previous_position = xf.position; // a teleport: no interpolation
    if (b->motion == Motion::Static && !b->trigger) mark_static_dirty();
}

Vec3 World::interpolated_position(BodyId id, float alpha) const {
    const Body* b = get(id);
    if (!b) return Vec3(0.0f);
    return glm::mix(b->previous_position, b->transform.position, std::clamp(alpha, 0.0f, 1.0f));
}

const Shape& World::shape(BodyId id) const {
    static const Shape none;
    const Body* b = get(id);
    return b ? b->shape : none;
}
std::uint64_t World::user_data(BodyId id) const {
    const Body* b = get(id);
    return b ? b->user_data : 0;
}
std::uint32_t World::layers(BodyId id) const {
    const Body* b = get(id);
    return b ? b->layers : 0;
}

CharacterState& World::character(BodyId id) {
    Body* b = get(id);
    if (!b || b->character_slot == kNone) {
        // A stale handle or a non-character: a harmless scratch state instead of a crash.
        log::warn("physics: character() called with a handle that is not a live character (index ", id.index,
                  ")");
        static thread_local CharacterState scratch;
        scratch = CharacterState{};
        return scratch;
    }
    return characters_[b->character_slot].state;
}
const CharacterState& World::character(BodyId id) const {
    return const_cast<World*>(this)->character(id);
}

bool World::jump(BodyId id, float speed) {
    Body* b = get(id);
    if (!b || b->character_slot == kNone || !std::isfinite(speed)) return false;
    CharacterState& s = characters_[b->character_slot].state;
    if (!s.grounded) return false;
    s.movement.velocity.y = speed;
    s.grounded = false;
    s.jumping = true;
    return true;
}

void World::set_on_collision(BodyId id, CollisionCallback callback) {
    if (!get(id)) return;
    auto& slot = on_collision_[id.index];
    collision_callbacks_ -= slot ? 1 : 0;
    slot = callback ? std::make_shared<CollisionCallback>(std::move(callback)) : nullptr;
    collision_callbacks_ += slot ? 1 : 0;
}
void World::set_on_trigger(BodyId id, TriggerCallback callback) {
    if (get(id))
        on_trigger_[id.index] = callback ? std::make_shared<TriggerCallback>(std::move(callback)) : nullptr;
}

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

// ---- movers: hash grid over x/z -----------------------------------------------------------------------

namespace {
std::uint32_t cell_hash(int ix, int iz) {
    return static_cast<std::uint32_t>(ix) * 73856093u ^ static_cast<std::uint32_t>(iz) * 19349663u;
}
// Multiplies by the reciprocal, folded to a constant: for the power-of-two cell size used (4) that equals the
// division exactly, without a division per cell bound in the broadphase.
int cell_of(float v, float cell) {
    return static_cast<int>(std::floor(v * (1.0f / cell)));
}
constexpr int kMaxCellsPerMover = 64;
} // namespace

void World::index_movers(float dt) {
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
    // Ground snap and depenetration move a character beyond its velocity: allow for them too.
    mover_slack_ = max_speed * dt + 2.0f;

    std::uint32_t buckets = 16;
    while (buckets < 2 * movers_.size()) buckets *= 2;
    grid_mask_ = buckets - 1;
    grid_count_.assign(buckets + 1, 0);
    grid_oversized_.clear();
    // Each mover's cell range, computed once for both passes (x0 > x1 marks an oversized mover).
    mover_cells_.resize(movers_.size());
    for (std::size_t i = 0; i < movers_.size(); ++i) {
        const geometry::Aabb& b = bodies_[movers_[i]].bounds;
        const double nx = std::floor(b.max.x * (1.0f / kCell)) - std::floor(b.min.x * (1.0f / kCell)) + 1.0;
        const double nz = std::floor(b.max.z * (1.0f / kCell)) - std::floor(b.min.z * (1.0f / kCell)) + 1.0;
        CellRange& r = mover_cells_[i];
        if (nx * nz > kMaxCellsPerMover) {
            r = {1, 0, 0, 0};
            grid_oversized_.push_back(movers_[i]);
            continue;
        }
        r = {cell_of(b.min.x, kCell), cell_of(b.max.x, kCell), cell_of(b.min.z, kCell),
             cell_of(b.max.z, kCell)};
        for (int x = r.x0; x <= r.x1; ++x)
            for (int z = r.z0; z <= r.z1; ++z) ++grid_count_[(cell_hash(x, z) & grid_mask_) + 1];
    }
    for (std::uint32_t k = 0; k < buckets; ++k) grid_count_[k + 1] += grid_count_[k];
    grid_start_.assign(grid_count_.begin(), grid_count_.end());
    grid_items_.resize(grid_count_[buckets]);
    for (std::size_t i = 0; i < movers_.size(); ++i) { // fill in mover order: deterministic
        const CellRange& r = mover_cells_[i];
        for (int x = r.x0; x <= r.x1; ++x)
            for (int z = r.z0; z <= r.z1; ++z)
                grid_items_[grid_count_[cell_hash(x, z) & grid_mask_]++] = movers_[i];
    }
    if (grid_stamp_.size() < bodies_.size()) grid_stamp_.resize(bodies_.size(), 0);
    grid_valid_ = true;
}

template <class Visit>
void World::movers_overlapping(const geometry::Aabb& region, Visit&& visit) const {
    if (!grid_valid_) { // bodies were added since the last step: scan them all
        for (std::uint32_t index : movers_)
            if (bodies_[index].bounds.overlaps(region)) visit(index);
        return;
    }
    if (++grid_query_ == 0) { // stamp wrap-around: clear once every 4 billion queries
        std::fill(grid_stamp_.begin(), grid_stamp_.end(), 0u);
        grid_query_ = 1;
    }
    auto consider = [&](std::uint32_t index) {
        if (grid_stamp_[index] == grid_query_) return; // already seen through another cell
        grid_stamp_[index] = grid_query_;
        const Body& b = bodies_[index];
        if (b.alive && b.motion != Motion::Static && b.bounds.overlaps(region)) visit(index);
    };
    const geometry::Aabb wide = region.expanded(mover_slack_);
    const int x0 = cell_of(wide.min.x, kCell), x1 = cell_of(wide.max.x, kCell);
    const int z0 = cell_of(wide.min.z, kCell), z1 = cell_of(wide.max.z, kCell);
    if (static_cast<double>(x1 - x0 + 1) * (z1 - z0 + 1) > 4.0 * (grid_mask_ + 1)) {
        for (std::uint32_t index : movers_) consider(index); // a query wider than the whole grid
    } else {
        for (int x = x0; x <= x1; ++x)
            for (int z = z0; z <= z1; ++z) {
                const std::uint32_t k = cell_hash(x, z) & grid_mask_;
                for (std::uint32_t i = grid_start_[k]; i < grid_start_[k + 1]; ++i) consider(grid_items_[i]);
            }
    }
    for (std::uint32_t index : grid_oversized_) consider(index);
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
        // Queries find movers through the cells of their start-of-step bounds, widened by the slack. One
        // pushed further than that (out of a door that closed on it, out of a packed crowd) is visited by
        // every later query of this step instead, so no contact with it is missed.
        const Vec3 moved = b.transform.position - b.previous_position;
        if (std::max(std::abs(moved.x), std::abs(moved.z)) > mover_slack_) grid_oversized_.push_back(cd.body);
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

// ---- queries ------------------------------------------------------------------------------------------

namespace {
// Lanes of `bp` whose axis-aligned box ray_centred_aabb would accept within max_t: the same operations in
// the same order, four at once (plain SSE multiplies and subtractions: nothing to contract into an FMA).
// Also stores each lane's entry distance and its x and y slab entries (which face was entered).
template <class Packet>
std::uint32_t packet_slab(const Packet& bp, const Vec3& origin, const Vec3& inv, float max_t, float* tmin_out,
                          float* lox_out, float* loy_out) {
#if defined(__SSE2__)
    const __m128 ox = _mm_sub_ps(_mm_set1_ps(origin.x), _mm_load_ps(bp.cx));
    const __m128 oy = _mm_sub_ps(_mm_set1_ps(origin.y), _mm_load_ps(bp.cy));
    const __m128 oz = _mm_sub_ps(_mm_set1_ps(origin.z), _mm_load_ps(bp.cz));
    const __m128 hx = _mm_load_ps(bp.hx), hy = _mm_load_ps(bp.hy), hz = _mm_load_ps(bp.hz);
    const __m128 sign = _mm_set1_ps(-0.0f);
    const __m128 ix = _mm_set1_ps(inv.x), iy = _mm_set1_ps(inv.y), iz = _mm_set1_ps(inv.z);
    const __m128 tx0 = _mm_mul_ps(_mm_sub_ps(_mm_xor_ps(hx, sign), ox), ix);
    const __m128 tx1 = _mm_mul_ps(_mm_sub_ps(hx, ox), ix);
    const __m128 ty0 = _mm_mul_ps(_mm_sub_ps(_mm_xor_ps(hy, sign), oy), iy);
    const __m128 ty1 = _mm_mul_ps(_mm_sub_ps(hy, oy), iy);
    const __m128 tz0 = _mm_mul_ps(_mm_sub_ps(_mm_xor_ps(hz, sign), oz), iz);
    const __m128 tz1 = _mm_mul_ps(_mm_sub_ps(hz, oz), iz);
    const __m128 lox = _mm_min_ps(tx0, tx1), loy = _mm_min_ps(ty0, ty1);
    const __m128 tmin = _mm_max_ps(lox, _mm_max_ps(loy, _mm_min_ps(tz0, tz1)));
    const __m128 tmax =
        _mm_mul_ps(_mm_min_ps(_mm_max_ps(tx0, tx1), _mm_min_ps(_mm_max_ps(ty0, ty1), _mm_max_ps(tz0, tz1))),
                   _mm_set1_ps(geometry::kExitWiden));
    const __m128 ok = _mm_and_ps(_mm_and_ps(_mm_cmple_ps(tmin, tmax), _mm_cmpgt_ps(tmax, _mm_setzero_ps())),
                                 _mm_cmple_ps(tmin, _mm_set1_ps(max_t)));
    _mm_store_ps(tmin_out, tmin);
    _mm_store_ps(lox_out, lox);
    _mm_store_ps(loy_out, loy);
    return static_cast<std::uint32_t>(_mm_movemask_ps(ok));
#else
    std::uint32_t mask = 0;
    for (int k = 0; k < 4; ++k) {
        const Vec3 o = origin - Vec3(bp.cx[k], bp.cy[k], bp.cz[k]), half(bp.hx[k], bp.hy[k], bp.hz[k]);
        const Vec3 t0 = (-half - o) * inv, t1 = (half - o) * inv;
        const Vec3 lo = glm::min(t0, t1), hi = glm::max(t0, t1);
        const float tmin = std::max(lo.x, std::max(lo.y, lo.z));
        const float tmax = std::min(hi.x, std::min(hi.y, hi.z)) * geometry::kExitWiden;
        tmin_out[k] = tmin, lox_out[k] = lo.x, loy_out[k] = lo.y;
        if (tmin <= tmax && tmax > 0.0f && tmin <= max_t) mask |= 1u << k;
    }
    return mask;
#endif
}
} // namespace

template <class BoxHit, class OtherHit>
bool World::ray_leaf(std::uint32_t leaf, const geometry::Ray& ray, const Vec3& inv, const float& max_t,
                     const RayFilter& filter, BoxHit&& box, OtherHit&& other) const {
    const BoxPacket& bp = static_packets_[leaf];
    alignas(16) float tmin[4], lox[4], loy[4];
    std::uint32_t lanes = packet_slab(bp, ray.origin, inv, max_t, tmin, lox, loy) & (bp.boxes | bp.others);
    while (lanes) {
        const int k = std::countr_zero(lanes);
        lanes &= lanes - 1;
        if (!(bp.layers[k] & filter.layers) || !passes(filter, bp.body[k])) continue;
        if (!(bp.boxes >> k & 1u)) {
            if (!other(bp.first_slot + k)) return false;
            continue;
        }
        // What ray_centred_aabb returns, read from the lanes (max_t may have shrunk since the slab test).
        if (tmin[k] > max_t) continue;
        ShapeHit h;
        if (tmin[k] <= 0.0f) { // starts inside (or on the surface, heading in)
            h.distance = 0.0f;
            h.normal = -ray.direction;
        } else {
            const int axis = tmin[k] == lox[k] ? 0 : (tmin[k] == loy[k] ? 1 : 2);
            h.distance = tmin[k];
            h.normal = Vec3(0.0f);
            h.normal[axis] = ray.direction[axis] > 0.0f ? -1.0f : 1.0f;
        }
        if (!box(k, h)) return false;
    }
    return true;
}

bool World::ray_static(const geometry::Ray& ray, const Vec3& inv, const StaticPrim& p, ShapeHit& hit) const {
    if (p.kind == ShapeKind::Box) {
        if (p.axis_aligned) return ray_centred_aabb(ray, inv, p.position, p.half, hit);
        return ray_box(ray, p.half, {p.position, p.rotation}, hit);
    }
    const Body& b = bodies_[p.body];
    return ray_shape(ray, b.shape, b.transform, hit);
}

bool World::ray_body(const geometry::Ray& ray, std::uint32_t index, ShapeHit& hit) const {
    const Body& b = bodies_[index];
    return ray_shape(ray, b.shape, b.transform, hit);
}

namespace {
bool finite_ray(const geometry::Ray& r) {
    return is_finite(r.origin) && is_finite(r.direction) && !std::isnan(r.max_distance) &&
           glm::dot(r.direction, r.direction) > 0.5f;
}
} // namespace

bool World::ray_closest(const geometry::Ray& ray, RayHit& out, const RayFilter& filter) const {
    if (!finite_ray(ray)) return false;
    build_static();
    float best = ray.max_distance;
    std::uint32_t best_body = kNone;
    Vec3 best_normal(0.0f);
    // Equal distances go to the lower body index (best_body starts as kNone, above every index), so the
    // answer does not depend on the order the BVH and the lists are visited in.
    auto closer = [&](float distance, std::uint32_t body) {
        return distance < best || (distance == best && body < best_body);
    };
    const Vec3 inv = geometry::safe_inverse(ray.direction);
    static_bvh_.ray_query_leaves(ray, inv, ray.max_distance, [&](std::uint32_t leaf, float& max_t) {
        const BoxPacket& bp = static_packets_[leaf];
        auto take = [&](std::uint32_t body, const ShapeHit& h) {
            if (closer(h.distance, body)) {
                best = h.distance, best_body = body, best_normal = h.normal;
                max_t = h.distance;
            }
            return true;
        };
        return ray_leaf(
            leaf, ray, inv, max_t, filter, [&](int k, const ShapeHit& h) { return take(bp.body[k], h); },
            [&](std::uint32_t slot) {
                const StaticPrim& p = static_prims_[slot];
                ShapeHit h;
                geometry::Ray r = ray;
                r.max_distance = max_t;
                if (ray_static(r, inv, p, h)) take(p.body, h);
                return true;
            });
    });
    for (std::uint32_t index : movers_) {
        const Body& b = bodies_[index];
        if (!b.enabled || !(b.layers & filter.layers) || !passes(filter, index)) continue;
        geometry::Ray r = ray;
        r.max_distance = best;
        ShapeHit h;
        if (ray_body(r, index, h) && closer(h.distance, index))
            best = h.distance, best_body = index, best_normal = h.normal;
    }
    if (filter.layers & layer::kTrigger)
        for (std::uint32_t index : static_triggers_) {
            const Body& b = bodies_[index];
            if (!b.enabled || !passes(filter, index)) continue;
            geometry::Ray r = ray;
            r.max_distance = best;
            ShapeHit h;
            if (ray_body(r, index, h) && closer(h.distance, index))
                best = h.distance, best_body = index, best_normal = h.normal;
        }
    if (best_body == kNone) return false;
    out.body = id_of(best_body);
    out.distance = best;
    out.normal = best_normal;
    out.point = ray.origin + ray.direction * best;
    return true;
}

bool World::ray_any(const geometry::Ray& ray, const RayFilter& filter) const {
    if (!finite_ray(ray)) return false;
    build_static();
    bool found = false;
    const Vec3 inv = geometry::safe_inverse(ray.direction);
    static_bvh_.ray_query_leaves(ray, inv, ray.max_distance, [&](std::uint32_t leaf, float& max_t) {
        return ray_leaf(
            leaf, ray, inv, max_t, filter, [&](int, const ShapeHit&) { return !(found = true); },
            [&](std::uint32_t slot) {
                ShapeHit h;
                found = ray_static(ray, inv, static_prims_[slot], h);
                return !found;
            });
    });
    if (found) return true;
    for (std::uint32_t index : movers_) {
        const Body& b = bodies_[index];
        ShapeHit h;
        if (b.enabled && (b.layers & filter.layers) && passes(filter, index) && ray_body(ray, index, h))
            return true;
    }
    if (filter.layers & layer::kTrigger)
        for (std::uint32_t index : static_triggers_) {
            ShapeHit h;
            if (bodies_[index].enabled && passes(filter, index) && ray_body(ray, index, h)) return true;
        }
    return false;
}

int World::ray_all(const geometry::Ray& ray, std::vector<RayHit>& hits, HitOrder order,
                   const RayFilter& filter) const {
    if (!finite_ray(ray)) return 0;
    build_static();
    const std::size_t start = hits.size();
    auto add = [&](std::uint32_t index, const ShapeHit& h) {
        hits.push_back({id_of(index), ray.origin + ray.direction * h.distance, h.normal, h.distance});
    };
    static_bvh_.ray_query(ray, ray.max_distance, [&](std::uint32_t slot, const Vec3& inv, float&) {
        const StaticPrim& p = static_prims_[slot];
        if (!p.enabled || !(p.layers & filter.layers) || !passes(filter, p.body)) return true;
        ShapeHit h;
        if (ray_static(ray, inv, p, h)) add(p.body, h);
        return true;
    });
    auto scan = [&](const std::vector<std::uint32_t>& list, bool triggers) {
        for (std::uint32_t index : list) {
            const Body& b = bodies_[index];
            if (!b.enabled || !passes(filter, index)) continue;
            if (!triggers && !(b.layers & filter.layers)) continue;
            ShapeHit h;
            if (ray_body(ray, index, h)) add(index, h);
        }
    };
    scan(movers_, false);
    if (filter.layers & layer::kTrigger) scan(static_triggers_, true);
    auto first = hits.begin() + static_cast<std::ptrdiff_t>(start);
    // Ties broken by body index so the order is deterministic.
    if (order == HitOrder::Ascending)
        std::sort(first, hits.end(), [](const RayHit& a, const RayHit& b) {
            return a.distance < b.distance || (a.distance == b.distance && a.body.index < b.body.index);
        });
    else
        std::sort(first, hits.end(), [](const RayHit& a, const RayHit& b) {
            return a.distance > b.distance || (a.distance == b.distance && a.body.index < b.body.index);
        });
    return static_cast<int>(hits.size() - start);
}

int World::overlap_capsule(const Segment& s, float radius, std::vector<BodyId>& out,
                           std::uint32_t layers) const {
    build_static();
    geometry::Aabb region{glm::min(s.p0, s.p1) - Vec3(radius), glm::max(s.p0, s.p1) + Vec3(radius)};
    const std::size_t start = out.size();
    auto test = [&](std::uint32_t index) {
        const Body& b = bodies_[index];
        if (!b.enabled || !(b.layers & layers) || !b.bounds.overlaps(region)) return;
        if (auto c = collide_capsule_shape(s, radius, b.shape, b.transform); c && c->penetration > 0.0f)
            out.push_back(id_of(index));
    };
    static_bvh_.aabb_query(region, [&](std::uint32_t slot) {
        test(static_prims_[slot].body);
        return true;
    });
    for (std::uint32_t index : movers_) test(index);
    for (std::uint32_t index : static_triggers_) test(index);
    return static_cast<int>(out.size() - start);
}

} // namespace ks::physics
