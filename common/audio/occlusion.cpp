#include "audio/occlusion.h"

#include <algorithm>
#include <cmath>

namespace ks::audio {

OcclusionScheduler::OcclusionScheduler(int capacity, OcclusionSettings settings)
    : settings_(settings), slots_(static_cast<std::size_t>(std::max(capacity, 1))) {}

void OcclusionScheduler::start(int slot) {
    Slot& s = slots_[static_cast<std::size_t>(slot)];
    if (!s.tracked) ++tracked_count_;
    s = Slot{};
    s.tracked = true;
    s.fresh = true;
    s.started = next_start_++;
}

void OcclusionScheduler::stop(int slot) {
    Slot& s = slots_[static_cast<std::size_t>(slot)];
    if (s.tracked) --tracked_count_;
    s = Slot{};
}

int OcclusionScheduler::oldest_unmeasured() const {
    int best = -1;
    for (int i = 0; i < static_cast<int>(slots_.size()); ++i) {
        const Slot& s = slots_[static_cast<std::size_t>(i)];
        if (s.tracked && !s.measured &&
            (best < 0 || s.started < slots_[static_cast<std::size_t>(best)].started))
            best = i;
    }
    return best;
}

void OcclusionScheduler::cast(int slot, Vec3 listener, std::span<const Vec3> positions,
                              BlockedQuery blocked) {
    Slot& s = slots_[static_cast<std::size_t>(slot)];
    s.target = blocked(listener, positions[static_cast<std::size_t>(slot)]) ? 1.0f : 0.0f;
    if (s.fresh) s.amount = s.target;
    s.measured = true;
    s.last_cast = update_count_;
}

int OcclusionScheduler::update(float dt, Vec3 listener, std::span<const Vec3> positions,
                               BlockedQuery blocked) {
    ++update_count_;
    const int budget = std::max(settings_.ray_budget, 0);
    int rays = 0;
    for (int slot = rays < budget ? oldest_unmeasured() : -1; slot >= 0;
         slot = rays < budget ? oldest_unmeasured() : -1) {
        cast(slot, listener, positions, blocked);
        ++rays;
    }
    // Smooth before the round robin's answers arrive, so each new answer is followed from the next update on
    // and the amount moves by at most 1 - exp(-dt / time_constant) per update.
    const bool moves = dt > 0.0f && std::isfinite(dt);
    const float step = !moves                           ? 0.0f
                       : settings_.time_constant > 0.0f ? 1.0f - std::exp(-dt / settings_.time_constant)
                                                        : 1.0f;
    for (Slot& s : slots_)
        if (s.tracked && s.measured && s.last_cast != update_count_) s.amount += (s.target - s.amount) * step;

    const int count = static_cast<int>(slots_.size());
    for (int visited = 0; visited < count && rays < budget; ++visited) {
        const int slot = cursor_;
        cursor_ = (cursor_ + 1) % count;
        const Slot& s = slots_[static_cast<std::size_t>(slot)];
        if (!s.tracked || s.last_cast == update_count_) continue;
        cast(slot, listener, positions, blocked);
        ++rays;
    }
    for (Slot& s : slots_) s.fresh = false;
    return rays;
}

} // namespace ks::audio
