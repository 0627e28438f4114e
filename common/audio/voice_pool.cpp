#include "audio/voice_pool.h"

#include <algorithm>

namespace ks::audio {

VoicePool::VoicePool(int capacity) : slots_(static_cast<std::size_t>(std::max(capacity, 1))) {}

int VoicePool::least_important() const {
    int victim = -1;
    for (int i = 0; i < capacity(); ++i) {
        const Slot& s = slots_[static_cast<std::size_t>(i)];
        if (!s.active) continue;
        if (victim < 0) {
            victim = i;
            continue;
        }
        const Slot& v = slots_[static_cast<std::size_t>(victim)];
        const bool less = s.priority != v.priority           ? s.priority < v.priority
                          : s.audible_gain != v.audible_gain ? s.audible_gain < v.audible_gain
                                                             : s.started < v.started;
        if (less) victim = i;
    }
    return victim;
}

VoiceClaim VoicePool::claim(int priority, float audible_gain) {
    VoiceClaim result;
    for (int i = 0; i < capacity(); ++i) {
        if (!slots_[static_cast<std::size_t>(i)].active) {
            result.slot = i;
            break;
        }
    }
    if (result.slot < 0) {
        const int victim = least_important();
        const Slot& v = slots_[static_cast<std::size_t>(victim)];
        const bool loses = priority < v.priority || (priority == v.priority && audible_gain < v.audible_gain);
        if (loses) {
            ++dropped_;
            return result;
        }
        result.slot = victim;
        result.stolen = true;
        ++stolen_;
        --active_count_;
    }
    Slot& s = slots_[static_cast<std::size_t>(result.slot)];
    s.active = true;
    s.priority = priority;
    s.audible_gain = audible_gain;
    s.started = next_start_++;
    ++s.generation; // the stolen voice's handle (if any) goes stale here
    ++active_count_;
    return result;
}

void VoicePool::release(int slot) {
    Slot& s = slots_[static_cast<std::size_t>(slot)];
    if (!s.active) return;
    s.active = false;
    ++s.generation;
    --active_count_;
}

void VoicePool::set_audible_gain(int slot, float audible_gain) {
    slots_[static_cast<std::size_t>(slot)].audible_gain = audible_gain;
}

VoiceHandle VoicePool::handle(int slot) const {
    return {static_cast<std::uint32_t>(slot), slots_[static_cast<std::size_t>(slot)].generation};
}

int VoicePool::find(VoiceHandle handle) const {
    if (!handle.valid() || handle.slot >= slots_.size()) return -1;
    const Slot& s = slots_[handle.slot];
    return s.active && s.generation == handle.generation ? static_cast<int>(handle.slot) : -1;
}

} // namespace ks::audio
