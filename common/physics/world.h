#pragma once
// The physics world: static bodies (in a SAH BVH, rebuilt only when the static set changes), kinematic
// bodies (door leaves: moved by the game), characters (player, robots: moved by the character controller)
// and triggers (pickups, gas-cylinder surrounds, door sensors: report enter/stay/exit, never block).
// Bodies are named by handles with a generation, so a stale handle is detected instead of dangling.
// One step: integrate and move every character (index order, deterministic), collect contacts and trigger
// overlaps (broadphase: BVH for statics, a hash grid for everything that moves), then dispatch
// callbacks. Callbacks run after the step's collision pass, so adding or removing bodies inside one is safe
// (removed bodies get no further events). Nothing allocates per step once buffers are warm.
#include "core/fixed_step.h"
#include "core/result.h"
#include "physics/bvh.h"
#include "physics/character.h"
#include "physics/mover_grid.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

namespace ks::physics {

// What a body is (its `layers`) and what a query or a character looks for (masks).
namespace layer {
inline constexpr std::uint32_t kSolid = 1u << 0;       // blocks characters
inline constexpr std::uint32_t kShootable = 1u << 1;   // shots stop on it
inline constexpr std::uint32_t kBlocksSight = 1u << 2; // robots cannot see through it
inline constexpr std::uint32_t kCharacter = 1u << 3;
inline constexpr std::uint32_t kTrigger = 1u << 4;
inline constexpr std::uint32_t kAll = 0xffffffffu;
inline constexpr std::uint32_t kDefault = kSolid | kShootable | kBlocksSight;
} // namespace layer

struct BodyId {
    std::uint32_t index = 0xffffffffu;
    std::uint32_t generation = 0;
    bool is_null() const { return index == 0xffffffffu; }
    bool operator==(const BodyId&) const = default;
};

enum class Motion : std::uint8_t { Static, Kinematic, Character };

struct BodyDesc {
    Shape shape;
    geometry::Transform transform;
    Motion motion = Motion::Static;
    bool trigger = false; // overlaps reported, never blocks; its layers become kTrigger (plus custom bits)
    std::uint32_t layers = layer::kDefault;                          // what this body is
    std::uint32_t collides_with = layer::kSolid | layer::kCharacter; // characters: what blocks them
    std::uint64_t user_data = 0;
    CharacterSettings character; // Motion::Character only
    MovementState movement;      // Motion::Character only: initial velocity, gravity, max speed
};

// The reference's onCollision(other, point, normal, penetration, dt), for body `self`.
struct Collision {
    BodyId self, other;
    Vec3 point{0.0f};
    Vec3 normal{0.0f}; // points from `other` toward `self`
    float penetration = 0.0f;
    float dt = 0.0f;
};

struct TriggerEvent {
    enum class Kind : std::uint8_t { Enter, Stay, Exit } kind = Kind::Enter;
    BodyId trigger, other;
};

struct RayHit {
    BodyId body;
    Vec3 point{0.0f};
    Vec3 normal{0.0f};
    float distance = 0.0f;
};

struct RayFilter {
    std::uint32_t layers = layer::kAll & ~layer::kTrigger; // hit bodies having any of these layers
    BodyId ignore;                                         // e.g. the shooter's own capsule
    // When set, bodies whose user data it rejects are passed over (the ray goes on to what lies behind):
    // what layers cannot say, e.g. a robot's shots passing through other robots. A plain function, so a
    // filter stays cheap to copy and a query allocates nothing.
    bool (*accept_user_data)(std::uint64_t user_data) = nullptr;
    RayFilter() = default;
    RayFilter(std::uint32_t layers_, BodyId ignore_ = {}) : layers(layers_), ignore(ignore_) {}
};

enum class HitOrder : std::uint8_t { Ascending, Descending };

// How a step finds the movers near a character or a trigger. Both give the same candidates in the same
// (body) order, so a world steps bit for bit the same with either: AllPairs, every mover against every
// other, is the reference the grid is tested and benchmarked against.
enum class MoverBroadphase : std::uint8_t { Grid, AllPairs };

struct WorldSettings {
    double step = 1.0 / 120.0;     // fixed step, seconds
    int max_steps_per_frame = 240; // a 2 s hitch is caught up in one frame; more waits for the next
    MoverBroadphase movers = MoverBroadphase::Grid;
};

class World {
  public:
    using CollisionCallback = std::function<void(World&, const Collision&)>;
    using TriggerCallback = std::function<void(World&, const TriggerEvent&)>;

    explicit World(WorldSettings settings = {});

    // Validates the shape and transform (finite, sane sizes); errors name the body's `what`.
    Result<BodyId> add(const BodyDesc& desc, const std::string& what = "body");
    void remove(BodyId id);
    bool valid(BodyId id) const;
    // Disabled bodies are skipped by every query and the step (a collected pickup, a dead robot).
    void set_enabled(BodyId id, bool enabled);
    bool enabled(BodyId id) const;

    geometry::Transform transform(BodyId id) const;
    // Moves a body (kinematic doors; teleporting a character). Static bodies trigger a BVH refit later.
    void set_transform(BodyId id, const geometry::Transform& xf);
    // Position between the previous and the current step (alpha from advance()).
    Vec3 interpolated_position(BodyId id, float alpha) const;
    const Shape& shape(BodyId id) const;
    std::uint64_t user_data(BodyId id) const;
    std::uint32_t layers(BodyId id) const;

    // Characters: velocity, gravity etc.; grounded state. A handle that is not a live character gets a
    // warning and a scratch state (never a crash).
    CharacterState& character(BodyId id);
    const CharacterState& character(BodyId id) const;
    // Sets vy = speed when grounded; returns whether it jumped.
    bool jump(BodyId id, float speed);

    void set_on_collision(BodyId id, CollisionCallback callback);
    void set_on_trigger(BodyId trigger, TriggerCallback callback);

    // One fixed step of `dt` seconds (dt <= 0 or NaN does nothing).
    void step(float dt);
    // Frame time in; runs the fixed steps due; returns the interpolation alpha in [0, 1).
    float advance(double frame_dt);
    const FixedStepClock& clock() const { return clock_; }

    // Events of the last step (also dispatched to callbacks).
    std::span<const Collision> collisions() const { return collisions_; }
    std::span<const TriggerEvent> trigger_events() const { return trigger_events_; }

    // Ray queries over static, kinematic and character bodies (triggers only if the filter asks).
    // ray_closest breaks ties in distance by the lower body index, as ray_all's order does, so it returns
    // exactly ray_all's first hit.
    bool ray_closest(const geometry::Ray& ray, RayHit& hit, const RayFilter& filter = {}) const;
    bool ray_any(const geometry::Ray& ray, const RayFilter& filter = {}) const;
    // Appends every hit (one per body) to `hits`, sorted; returns how many. No allocation when `hits` has
    // capacity.
    int ray_all(const geometry::Ray& ray, std::vector<RayHit>& hits, HitOrder order = HitOrder::Ascending,
                const RayFilter& filter = {}) const;
    // Bodies whose shape overlaps a capsule (the editor's walkability check, spawn checks).
    int overlap_capsule(const Segment& s, float radius, std::vector<BodyId>& out,
                        std::uint32_t layers = layer::kSolid) const;

    // Rebuilds the static BVH now (otherwise done lazily by the next query or step after a change).
    void build_static() const;
    std::size_t body_count() const { return live_count_; }
    const Bvh& static_bvh() const;

  private:
    struct Body {
        // What broadphase queries test for every candidate first, together in the first cache line.
        geometry::Aabb bounds;
        std::uint32_t generation = 0;
        std::uint32_t layers = 0;
        std::uint32_t collides_with = 0;
        std::uint32_t character_slot = 0xffffffffu;
        Motion motion = Motion::Static;
        bool trigger = false;
        bool alive = false;
        bool enabled = true;
        bool yaw_only = false;
        geometry::Transform transform;
        Shape shape;
        Vec3 previous_position{0.0f};
        std::uint64_t user_data = 0;
    };
    // The static bodies near a character, kept across steps: the BVH is queried for a box
    // `kStaticCacheMargin` wider than the controller's region and asked again only when the region leaves
    // that box, the static set is rebuilt or the body array has moved (the cached obstacles point at the
    // bodies' shapes). Reusing it gives exactly the obstacles (and order) a fresh query would: the entries
    // are in slot order and go through the same filters (enabled, layers, the region itself).
    struct StaticCache {
        struct Entry {
            Obstacle obstacle; // as gather hands it to the controller
            std::uint32_t slot;
        };
        geometry::Aabb region = geometry::Aabb::empty();
        std::uint64_t epoch = 0;      // static_epoch_ it was gathered in (0: never)
        const void* bodies = nullptr; // bodies_.data() then (the obstacles point into bodies_)
        std::vector<Entry> entries;   // static bodies whose bounds overlap `region`, in slot order
        // The entries that pass the filters (enabled, layers & mask), for the mask and enabled_epoch_
        // they were chosen with: a step reads only these, not every entry's body.
        std::vector<Obstacle> usable;
        std::uint64_t usable_epoch = ~std::uint64_t{0};
        std::uint32_t usable_mask = 0;
    };
    static constexpr float kStaticCacheMargin = 1.0f;
    struct CharacterData {
        std::uint32_t body = 0;
        CharacterSettings settings;
        CharacterState state;
        StaticCache statics;
    };
    class Obstacles;
    friend class Obstacles;
    static constexpr std::uint32_t kNone = 0xffffffffu; // no slot, no character, no body

    Body* get(BodyId id);
    const Body* get(BodyId id) const;
    BodyId id_of(std::uint32_t index) const { return {index, bodies_[index].generation}; }
    void mark_static_dirty() { static_dirty_ = true; }
    bool ray_body(const geometry::Ray& ray, std::uint32_t index, ShapeHit& hit) const;
    // The filter's checks besides layers: the ignored body and the user-data test.
    bool passes(const RayFilter& filter, std::uint32_t index) const {
        return index != filter.ignore.index &&
               (!filter.accept_user_data || filter.accept_user_data(bodies_[index].user_data));
    }
    void update_triggers(float dt);
    void dispatch();

    WorldSettings settings_;
    FixedStepClock clock_;
    std::vector<Body> bodies_;
    std::vector<std::uint32_t> free_slots_;
    std::vector<CharacterData> characters_;
    // By body index. Shared so a callback that adds bodies (growing these arrays) or replaces itself keeps
    // running on a live object.
    std::vector<std::shared_ptr<CollisionCallback>> on_collision_;
    std::vector<std::shared_ptr<TriggerCallback>> on_trigger_;
    std::size_t collision_callbacks_ = 0; // non-null entries of on_collision_
    std::size_t live_count_ = 0;

    // Static set: BVH over static bodies (non-trigger), rebuilt lazily. What rays need of each static body
    // is copied into a compact array in BVH leaf order, so leaves are read contiguously.
    struct StaticPrim {
        Vec3 position;
        std::uint32_t body;
        Quat rotation;
        Vec3 half;
        std::uint32_t layers;
        ShapeKind kind;
        bool axis_aligned;
        bool enabled;
    };
    mutable Bvh static_bvh_;
    mutable std::vector<StaticPrim> static_prims_;      // by BVH leaf slot
    mutable std::vector<std::uint32_t> static_slot_of_; // body index -> leaf slot (or ~0)
    // Each BVH leaf's static prims as one packet (leaves hold at most four), axis-aligned boxes lane-wise
    // (centre, half extents) with the filter data rays need, so a ray tests a leaf with one SIMD slab test
    // doing exactly the float operations of ray_centred_aabb (same hits, same distances) and takes the hit
    // of a box lane from the lanes; rotated boxes, wedges and hulls run their scalar test when the ray
    // enters their (padded) world bounds.
    struct alignas(16) BoxPacket {
        float cx[4], cy[4], cz[4], hx[4], hy[4], hz[4];
        std::uint32_t layers[4];  // the body's layers; 0 while it is disabled (no filter matches)
        std::uint32_t body[4];    // body index
        std::uint32_t first_slot; // lane k is leaf slot first_slot + k
        std::uint32_t boxes = 0;  // lanes holding an axis-aligned box
        std::uint32_t others = 0; // lanes holding anything else (cx.. hz: their padded world bounds)
    };
    mutable std::vector<BoxPacket> static_packets_;     // by BVH leaf
    mutable std::vector<std::uint32_t> static_leaf_of_; // leaf slot -> its BVH leaf (packet)
    // Calls box(k, distance, normal) for the box lanes of `leaf` the ray enters within max_t (re-checked
    // against max_t, which the callbacks may shrink) and other(slot) for its other lanes the ray enters the
    // padded bounds of, in lane order, both only for lanes whose layers and body pass `filter`; stops when a
    // callback returns false.
    template <class BoxHit, class OtherHit>
    bool ray_leaf(std::uint32_t leaf, const geometry::Ray& ray, const Vec3& inv, const float& max_t,
                  const RayFilter& filter, BoxHit&& box, OtherHit&& other) const;
    mutable bool static_dirty_ = true;
    mutable std::uint64_t static_epoch_ = 0; // counts static rebuilds (invalidates the characters' caches)
    std::uint64_t enabled_epoch_ = 0;        // counts static bodies switched on or off (refilters the caches)
    bool ray_static(const geometry::Ray& ray, const Vec3& inv_dir, const StaticPrim& prim,
                    ShapeHit& hit) const;
    // Moving set (kinematic bodies, characters, kinematic triggers).
    std::vector<std::uint32_t> movers_;
    // Movers' broadphase (physics/mover_grid.h), rebuilt each step from the bounds at its start; valid only
    // inside a step (nothing is added or removed then).
    MoverGrid mover_grid_;
    std::vector<geometry::Aabb> mover_start_bounds_; // by position in movers_, the grid's input
    std::vector<std::uint32_t> mover_position_;      // by body index: its position in movers_ (this step)
    bool grid_valid_ = false;
    std::vector<std::uint32_t> static_triggers_;
    void index_movers(float dt);
    template <class Visit>
    void movers_overlapping(const geometry::Aabb& region, Visit&& visit) const;

    // Per-step buffers, reused.
    CharacterScratch scratch_;
    std::vector<Collision> collisions_;
    std::vector<TriggerEvent> trigger_events_;
    std::vector<std::uint64_t> trigger_pairs_;      // (trigger index << 32 | other index), sorted, this step
    std::vector<std::uint64_t> trigger_pairs_prev_; // last step
};

} // namespace ks::physics
