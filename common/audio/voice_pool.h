#pragma once
// The voice limit: a fixed number of voice slots, and the rule for who gets one when all are busy. Pure
// bookkeeping (no OpenAL), so the stealing rule is tested without a sound card.
//
// When every slot is busy, the least important voice is the one with the lowest priority, then (same
// priority) the quietest at the listener (gain after distance attenuation and volume), then (same gain) the
// oldest. A new sound takes that voice's slot unless it is itself less important than it (lower priority,
// or the same priority and quieter): then the new sound is dropped, since it would lose to every voice.
#include <cstdint>
#include <vector>

namespace ks::audio {

// Names one playing sound. A slot is reused by later sounds; the generation tells the old sound's handle
// apart, so calls through a handle whose sound has ended (or was stolen) do nothing.
struct VoiceHandle {
    static constexpr std::uint32_t kNoSlot = 0xFFFFFFFFu;
    std::uint32_t slot = kNoSlot;
    std::uint32_t generation = 0;

    bool valid() const { return slot != kNoSlot; }
    friend bool operator==(const VoiceHandle&, const VoiceHandle&) = default;
};

struct VoiceClaim {
    int slot = -1;       // -1: dropped (every playing voice is more important)
    bool stolen = false; // the slot held a playing voice, which the caller must stop first
};

class VoicePool {
  public:
    static constexpr int kDefaultVoices = 32;

    explicit VoicePool(int capacity = kDefaultVoices);

    // A slot for a new sound of `priority` heard at `audible_gain` (0 silent .. 1 full).
    VoiceClaim claim(int priority, float audible_gain);
    void release(int slot);
    void set_audible_gain(int slot, float audible_gain);

    bool active(int slot) const { return slots_[static_cast<std::size_t>(slot)].active; }
    int capacity() const { return static_cast<int>(slots_.size()); }
    int active_count() const { return active_count_; }
    VoiceHandle handle(int slot) const;
    // The slot a handle names, or -1 when its sound has ended, was stolen, or the handle is invalid.
    int find(VoiceHandle handle) const;

    // Totals since construction.
    int stolen() const { return stolen_; }
    int dropped() const { return dropped_; }

  private:
    struct Slot {
        bool active = false;
        int priority = 0;
        float audible_gain = 0.0f;
        std::uint64_t started = 0; // start order: lower is older
        std::uint32_t generation = 0;
    };
    int least_important() const;

    std::vector<Slot> slots_;
    std::uint64_t next_start_ = 0;
    int active_count_ = 0;
    int stolen_ = 0;
    int dropped_ = 0;
};

} // namespace ks::audio
