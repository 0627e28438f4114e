#include "render/dynamic_resolution.h"

#include <algorithm>
#include <cmath>

namespace ks::render {

DynamicResolution::DynamicResolution(const DynamicResolutionSettings& settings) : settings_(settings) {
    settings_.window = std::clamp(settings_.window, 1, static_cast<int>(samples_.size()));
    const float lowest = std::isfinite(settings_.lowest_scale)
                             ? std::clamp(settings_.lowest_scale, 0.25f, 1.0f)
                             : kSteps.back();
    // The step nearest the requested floor (the floor itself when it is a step).
    lowest_step_ = 0;
    for (int i = 0; i < static_cast<int>(kSteps.size()); ++i)
        if (std::abs(kSteps[static_cast<std::size_t>(i)] - lowest) <
            std::abs(kSteps[static_cast<std::size_t>(lowest_step_)] - lowest))
            lowest_step_ = i;
    reset();
}

void DynamicResolution::reset() {
    step_ = lowest_step_;
    sample_count_ = 0;
    reached_at_ = clock_;
    strikes_ = 0;
    retry_at_.fill(0.0);
    retry_wait_.fill(0.0);
}

double DynamicResolution::window_median() const {
    std::array<double, 64> sorted = samples_;
    const auto n = static_cast<std::ptrdiff_t>(sample_count_);
    std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.begin() + n);
    return sorted[static_cast<std::size_t>(n / 2)];
}

void DynamicResolution::move_to(int step) {
    step_ = step;
    sample_count_ = 0;
    reached_at_ = clock_;
    strikes_ = 0;
    ++changes_;
}

float DynamicResolution::update(double work_ms, double frame_seconds) {
    if (std::isfinite(frame_seconds) && frame_seconds > 0.0) clock_ += std::min(frame_seconds, 1.0);
    if (!std::isfinite(work_ms) || work_ms < 0.0 || work_ms > settings_.outlier_ms) return scale();
    samples_[static_cast<std::size_t>(sample_count_++)] = work_ms;
    if (sample_count_ < settings_.window) return scale();
    const double median = window_median();
    sample_count_ = 0;
    const auto at = [](int step) { return static_cast<std::size_t>(step); };
    // Over budget by a little: two windows in a row before stepping down (one is noise on a marginal
    // machine); by more than 10 %: at once.
    const bool over = median > settings_.target_ms * settings_.down_at;
    strikes_ = over ? strikes_ + 1 : 0;
    if (over && step_ < lowest_step_ &&
        (strikes_ >= 2 || median > settings_.target_ms * settings_.down_at * 1.1)) {
        // Too slow here: this step waits twice as long as last time before it is tried again (a marginal
        // machine whose noise crosses the budget settles instead of flickering between two sizes).
        double& wait = retry_wait_[at(step_)];
        wait = std::clamp(wait * 2.0, settings_.retry_seconds, settings_.max_retry_seconds);
        retry_at_[at(step_)] = clock_ + wait;
        move_to(step_ + 1);
    } else if (median < settings_.target_ms * settings_.up_below && step_ > 0 &&
               clock_ >= retry_at_[at(step_ - 1)]) {
        move_to(step_ - 1);
    } else if (clock_ - reached_at_ >= settings_.max_retry_seconds) {
        retry_wait_[at(step_)] = 0.0; // held for a long while: a later slowdown starts from the shortest wait
    }
    return scale();
}

} // namespace ks::render
