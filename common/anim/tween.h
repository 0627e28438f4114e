#pragma once
// Tweens of floats, vectors and quaternions, in the manner of Tween.js (delay, repeat, yoyo, chain, time
// scale, start/update/repeat/complete/stop callbacks, groups) but seekable: a tween's value is a pure
// function of its local time, so scrubbing, stepping and playing backwards are just `seek`.
//
// Timeline of one tween (local seconds, after time scale):
//   [0, delay)                      waiting, value = from
//   iteration i (0-based) starts at delay + i * (duration + repeat_delay)
//   during an iteration             value = interp(from, to, ease(progress)), reversed on odd ones with yoyo
//   between iterations              holds the previous iteration's end value
//   after the last                  holds the final value (to, or from after an even yoyo count)
#include "anim/easing.h"
#include "anim/rotation.h"
#include "core/math.h"

#include <functional>
#include <limits>
#include <memory>
#include <vector>

namespace ks::anim {

inline constexpr int kRepeatForever = -1;

struct TweenTiming {
    double delay = 0;
    double duration = 1;
    int repeat = 0;           // extra iterations after the first; kRepeatForever for endless
    double repeat_delay = -1; // pause between iterations; negative = same as delay (Tween.js rule)
    bool yoyo = false;
    double time_scale = 1; // local time = group time since start * time_scale
    Ease ease;

    double gap() const { return repeat_delay < 0 ? delay : repeat_delay; }
    // delay + every iteration; infinity for kRepeatForever.
    double total() const;
};

// Where a local time falls on the timeline.
struct TweenPhase {
    bool started = false;  // local time >= delay
    bool finished = false; // past the last iteration
    long long iteration = 0;
    double progress = 0;   // raw progress in the current iteration, [0, 1]
    bool reversed = false; // yoyo on an odd iteration
};
TweenPhase tween_phase(const TweenTiming& timing, double local_time);

template <class T>
T interpolate(const T& a, const T& b, double w) {
    return a + (b - a) * static_cast<float>(w);
}
template <>
inline Quat interpolate<Quat>(const Quat& a, const Quat& b, double w) {
    return slerp_shortest(a, b, static_cast<float>(w));
}

class TweenGroup;

// The untyped part a group drives.
class TweenBase {
  public:
    virtual ~TweenBase() = default;

    TweenTiming timing;
    std::function<void()> on_start, on_complete, on_stop;
    std::function<void(long long iteration)> on_repeat;

    // Starts `next` when this tween completes (Tween.js chain). Several may be chained.
    TweenBase& chain(TweenBase& next);
    bool stopped() const { return stopped_; }
    bool started() const { return started_; }
    bool completed() const { return completed_; }

  protected:
    virtual void apply(double local_time) = 0; // evaluate, write the target, call on_update

  private:
    friend class TweenGroup;
    double start_time_ = 0; // group time of local time 0 (resolved for chained tweens)
    TweenBase* chained_after_ = nullptr;
    std::vector<TweenBase*> chained_;
    bool started_ = false, completed_ = false, stopped_ = false;
    long long last_iteration_ = 0;
    double stopped_local_time_ = 0;
};

template <class T>
class Tween final : public TweenBase {
  public:
    Tween(T from_value, T to_value, TweenTiming timing_, T* target_ = nullptr)
        : from(from_value), to(to_value), target(target_) {
        timing = timing_;
    }

    T from, to;
    T* target = nullptr; // written on every update while running, if set
    std::function<void(const T& value, double eased)> on_update;

    // The value at a local time (pure: no callbacks, no target write).
    T value_at(double local_time) const {
        TweenPhase p = tween_phase(timing, local_time);
        if (!p.started) return from;
        double w = timing.ease(p.progress);
        return p.reversed ? interpolate(to, from, w) : interpolate(from, to, w);
    }

  protected:
    void apply(double local_time) override {
        T value = value_at(local_time);
        if (target) *target = value;
        if (on_update) on_update(value, timing.ease(tween_phase(timing, local_time).progress));
    }
};

// Owns tweens and drives them from one clock. Callbacks fire when time moves forward across their moment
// (start, each repeat, complete); moving backwards (seek) re-arms them silently.
class TweenGroup {
  public:
    template <class T>
    Tween<T>& add(Tween<T> tween, double start_at = 0) {
        auto owned = std::make_unique<Tween<T>>(std::move(tween));
        Tween<T>& ref = *owned;
        ref.start_time_ = start_at;
        tweens_.push_back(std::move(owned));
        return ref;
    }

    void update(double dt) { seek(time_ + dt * time_scale_); }
    void seek(double time);
    // Stops a tween (and the ones chained after it, as Tween.js does): on_stop fires, the value freezes.
    void stop(TweenBase& tween);
    void remove_all() { tweens_.clear(); }

    double time() const { return time_; }
    void set_time_scale(double scale) { time_scale_ = scale; }
    double time_scale() const { return time_scale_; }
    // Group time at which a tween's local time 0 falls (follows chains); +inf after an endless tween.
    double start_time(const TweenBase& tween) const;
    double end_time(const TweenBase& tween) const;
    // True when every tween has completed or stopped (an endless tween keeps the group busy).
    bool idle() const;
    std::size_t size() const { return tweens_.size(); }

  private:
    std::vector<std::unique_ptr<TweenBase>> tweens_;
    double time_ = 0, time_scale_ = 1;
};

} // namespace ks::anim
