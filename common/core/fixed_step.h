#pragma once
// Fixed-step clock: real frame time goes into an accumulator that is drained in steps of exactly `step`
// seconds, so simulation results do not depend on the frame rate. A long hitch is sub-stepped, never
// skipped; `max_steps_per_frame` only bounds how much is caught up in one frame (the rest stays queued
// rather than being dropped), which keeps a slow machine from a spiral of death while losing no time.
#include <algorithm>

namespace ks {

class FixedStepClock {
public:
    explicit FixedStepClock(double step = 1.0 / 120.0, int max_steps_per_frame = 1000)
        : step_(step), max_steps_(max_steps_per_frame) {}

    // Adds frame time and returns how many fixed steps to run now.
    int advance(double frame_dt) {
        if (!(frame_dt > 0.0)) frame_dt = 0.0; // dt = 0, negative or NaN adds nothing
        accumulator_ += frame_dt;
        // The small tolerance keeps rounding in the running sum from losing a step (1.0 s at 120 Hz must be
        // 120 steps, not 119 and a remainder of 0.99999 step).
        int steps = static_cast<int>(accumulator_ / step_ + 1e-7);
        steps = std::min(steps, max_steps_);
        accumulator_ = std::max(0.0, accumulator_ - steps * step_);
        total_steps_ += steps;
        return steps;
    }

    // How far between the last step and the next one the frame lies, in [0, 1): for render interpolation.
    double alpha() const { return std::clamp(accumulator_ / step_, 0.0, 1.0); }
    double step() const { return step_; }
    long long total_steps() const { return total_steps_; }
    double simulated_time() const { return static_cast<double>(total_steps_) * step_; }

private:
    double step_;
    int max_steps_;
    double accumulator_ = 0.0;
    long long total_steps_ = 0;
};

} // namespace ks
