#include "physics/world.h"

#include "core/log.h"

#include <algorithm>
#include <cmath>

namespace ks::physics {

namespace {
constexpr float kMaxCoordinate = 1e7f; // beyond this float spacing is > 1 unit: refuse instead of drifting
} // namespace

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
    if (desc.shape.kind == ShapeKind::Mesh && desc.motion != Motion::Static)
        return Error(what + ": a triangle mesh can only be static", Location(what),
                     "give a moving body a box or a hull");
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
        grid_valid_ = false; // the grid names movers by position: re-indexed by the next step
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
            if (static_prims_[slot].enabled != enabled) ++enabled_epoch_;
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

geometry::Transform World::transform(BodyId id) const {
    const Body* b = get(id);
    return b ? b->transform : geometry::Transform{};
}

void World::set_transform(BodyId id, const geometry::Transform& xf) {
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

} // namespace ks::physics
