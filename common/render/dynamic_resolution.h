#pragma once
// Dynamic resolution: the 3D scene's render scale picked from measured frame times, so that the automatic
// setting on a software rasteriser draws at full resolution whenever the machine holds the target frame
// rate and scales down, a step at a time, only when it must (issue 28: "the default path renders at full
// resolution whenever it can hold 60 fps"). Pure logic (no GL), fed one frame at a time, so it is tested
// with made-up machines.
//
// It starts at the lowest step (what the automatic setting drew before: never a slow first second) and
// climbs while a window of frames has headroom. A step that turns out too slow is left at once and not
// tried again for a while, the wait doubling on each failure until the step has held for the longest wait (a
// machine that cannot hold a step pays a few slow frames every minute, not every second). A frame far over
// budget (a level load, a shader compile, a window dragged) is not counted.
#include <array>
#include <cstddef>

namespace ks::render {

struct DynamicResolutionSettings {
    double target_ms = 1000.0 / 60.0; // the frame time to hold (60 fps)
    float lowest_scale = 0.5f;        // the bottom step (the renderer's automatic scale on software)
    int window = 20;                  // frames measured at a step before deciding
    double down_at = 1.0;       // step down when two windows in a row exceed target x this (one by 10 % more)
    double up_below = 0.9;      // step up (a try) when the median is under target x this
    double retry_seconds = 4.0; // after a step proved too slow: first wait before trying it again
    double max_retry_seconds = 64.0; // the longest wait (it doubles on each failure)
    double outlier_ms = 250.0;       // frames longer than this are hitches, not load: not counted
};

class DynamicResolution {
  public:
    // The steps from full resolution down to settings.lowest_scale (clamped to 0.25..1).
    static constexpr std::array<float, 7> kSteps{1.0f, 0.875f, 0.75f, 0.625f, 0.5f, 0.375f, 0.25f};

    explicit DynamicResolution(const DynamicResolutionSettings& settings = {});

    // One frame: the time its work took (ms, from the start of its update to the end of its swap) and the
    // time since the last frame (s, for the retry clock). Returns the scale to draw the next frame at.
    // NaN, negative or infinite inputs are ignored.
    float update(double work_ms, double frame_seconds);
    float scale() const { return kSteps[static_cast<std::size_t>(step_)]; }
    // Back to the lowest step with nothing measured and no step waiting to be retried.
    void reset();
    // Steps taken since construction (tests count oscillation with it).
    long long changes() const { return changes_; }
    const DynamicResolutionSettings& settings() const { return settings_; }

  private:
    double window_median() const;
    void move_to(int step);

    DynamicResolutionSettings settings_;
    int lowest_step_ = 4;
    int step_ = 4;
    std::array<double, 64> samples_{}; // the current window (settings.window, at most 64)
    int sample_count_ = 0;
    double clock_ = 0.0;
    // Per step: when it may be tried again after proving too slow, and how long the next wait is.
    std::array<double, kSteps.size()> retry_at_{};
    std::array<double, kSteps.size()> retry_wait_{};
    double reached_at_ = 0.0; // when the current step was reached (the retry clock)
    int strikes_ = 0;         // windows in a row over budget
    long long changes_ = 0;
};

} // namespace ks::render
