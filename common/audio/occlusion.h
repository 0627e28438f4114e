#pragma once
// Occlusion: is there a wall between the listener and a sound? Each update casts at most `ray_budget` rays
// (the caller's blocked(listener, source) query): first to voices never measured (in the order they started),
// then round robin over the other positional voices, so the cost per frame is bounded however many sounds
// play. The occlusion amount (0 clear .. 1 blocked) follows the last ray's answer with a time constant, so a
// sound going behind a wall fades to muffled instead of clicking. A voice measured in the first update after
// it started takes that answer at once (the engine starts sources after the update, so it has not been heard
// yet); a voice the budget could not reach in time starts clear and fades like any other. Pure (no OpenAL):
// the engine turns the amount into a low-pass filter.
#include "audio/function_ref.h"
#include "core/math.h"

#include <cstdint>
#include <span>
#include <vector>

namespace ks::audio {

using BlockedQuery = FunctionRef<bool(Vec3 listener, Vec3 source)>;

struct OcclusionSettings {
    int ray_budget = 8;          // rays per update, at most
    float time_constant = 0.08f; // seconds for the amount to move 63% of the way to its target
};

class OcclusionScheduler {
  public:
    explicit OcclusionScheduler(int capacity, OcclusionSettings settings = {});

    // A positional voice started in `slot`: it is measured before any older voice. Starting a slot again
    // (a stolen voice) forgets the old sound's state.
    void start(int slot);
    void stop(int slot);

    // Casts up to the budget of rays from `listener` to positions[slot], then moves every tracked amount
    // toward its target. Returns the number of rays cast. Allocates nothing.
    int update(float dt, Vec3 listener, std::span<const Vec3> positions, BlockedQuery blocked);

    float amount(int slot) const { return slots_[static_cast<std::size_t>(slot)].amount; }
    float target(int slot) const { return slots_[static_cast<std::size_t>(slot)].target; }
    bool measured(int slot) const { return slots_[static_cast<std::size_t>(slot)].measured; }
    bool tracked(int slot) const { return slots_[static_cast<std::size_t>(slot)].tracked; }
    int tracked_count() const { return tracked_count_; }
    const OcclusionSettings& settings() const { return settings_; }
    void set_ray_budget(int budget) { settings_.ray_budget = budget; }

  private:
    struct Slot {
        bool tracked = false;
        bool measured = false; // has had at least one ray
        bool fresh = false;    // started since the last update: not heard yet
        float amount = 0.0f;
        float target = 0.0f;
        std::uint64_t started = 0;   // start order, to measure new voices oldest first
        std::uint64_t last_cast = 0; // the update that last cast this voice's ray
    };
    int oldest_unmeasured() const;
    void cast(int slot, Vec3 listener, std::span<const Vec3> positions, BlockedQuery blocked);

    OcclusionSettings settings_;
    std::vector<Slot> slots_;
    int cursor_ = 0; // where the round robin over measured voices goes on next update
    int tracked_count_ = 0;
    std::uint64_t next_start_ = 0;
    std::uint64_t update_count_ = 0;
};

} // namespace ks::audio
