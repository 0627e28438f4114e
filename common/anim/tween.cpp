#include "anim/tween.h"

#include <cmath>

namespace ks::anim {

double TweenTiming::total() const {
    if (repeat == kRepeatForever) return std::numeric_limits<double>::infinity();
    return delay + (repeat + 1) * duration + repeat * gap();
}

TweenPhase tween_phase(const TweenTiming& timing, double local_time) {
    TweenPhase p;
    if (!(local_time >= timing.delay)) return p; // NaN stays "not started"
    p.started = true;
    const double t = local_time - timing.delay;
    const double period = timing.duration + timing.gap();
    const long long last =
        timing.repeat == kRepeatForever ? std::numeric_limits<long long>::max() : timing.repeat;
    long long i = 0;
    double into = t;
    if (period > 0) {
        double fi = std::floor(t / period);
        i = fi >= static_cast<double>(last) ? last : static_cast<long long>(fi);
        into = t - static_cast<double>(i) * period;
    } else {
        i = last == std::numeric_limits<long long>::max() ? 0
                                                          : last; // zero-length iterations all pass at once
        into = 0;
    }
    p.iteration = i;
    if (timing.duration <= 0 || into >= timing.duration) {
        p.progress = 1; // in the gap after iteration i, or a zero-length tween
        p.finished = (i == last);
    } else {
        p.progress = into / timing.duration;
    }
    p.reversed = timing.yoyo && (i % 2 == 1);
    return p;
}

TweenBase& TweenBase::chain(TweenBase& next) {
    chained_.push_back(&next);
    next.chained_after_ = this;
    return *this;
}

double TweenGroup::start_time(const TweenBase& tween) const {
    if (!tween.chained_after_) return tween.start_time_;
    return end_time(*tween.chained_after_);
}

double TweenGroup::end_time(const TweenBase& tween) const {
    double local_total = tween.timing.total();
    double scale = tween.timing.time_scale > 0 ? tween.timing.time_scale : 1.0;
    return start_time(tween) + local_total / scale;
}

void TweenGroup::seek(double time) {
    const bool backwards = time < time_;
    time_ = time;
    for (auto& owned : tweens_) {
        TweenBase& tw = *owned;
        if (tw.stopped_) continue;
        const double start = start_time(tw);
        if (!std::isfinite(start)) continue; // chained after an endless tween: never starts
        const double local = (time - start) * tw.timing.time_scale;
        const TweenPhase phase = tween_phase(tw.timing, local);
        if (backwards) { // re-arm: the state is whatever the new time implies, without callbacks
            tw.started_ = phase.started;
            tw.completed_ = phase.finished;
            tw.last_iteration_ = phase.iteration;
            if (phase.started) tw.apply(local);
            continue;
        }
        if (!phase.started) continue;
        if (tw.completed_) continue;
        if (!tw.started_) {
            tw.started_ = true;
            if (tw.on_start) tw.on_start();
        }
        tw.apply(local);
        while (tw.last_iteration_ < phase.iteration) {
            ++tw.last_iteration_;
            if (tw.on_repeat) tw.on_repeat(tw.last_iteration_);
        }
        if (phase.finished) {
            tw.completed_ = true;
            if (tw.on_complete) tw.on_complete();
        }
    }
}

void TweenGroup::stop(TweenBase& tween) {
    if (tween.stopped_) return;
    tween.stopped_ = true;
    tween.stopped_local_time_ = (time_ - start_time(tween)) * tween.timing.time_scale;
    if (tween.on_stop) tween.on_stop();
    for (TweenBase* next : tween.chained_) stop(*next);
}

bool TweenGroup::idle() const {
    for (const auto& tw : tweens_)
        if (!tw->stopped_ && !tw->completed_) return false;
    return true;
}

} // namespace ks::anim
