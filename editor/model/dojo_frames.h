#pragma once
// Seconds or frames in the dojo: the frame rate a clip is authored at (the common rate whose grid holds
// every key time and event, 30 when none or several do), snapping times to that grid, and times as the
// animator reads and types them ("12 f" or "0.4 s"). The file always stores seconds; in frames mode every
// time the dojo writes is a whole frame (k / fps, the nearest double).
#include "anim/clip.h"

#include <optional>
#include <string>
#include <string_view>

namespace ks::editor {

inline constexpr double kDefaultFrameRate = 30.0;

// How the dojo shows and snaps times: seconds (on the microsecond grid, kTimeSteps) or frames at `fps`.
struct TimeUnits {
    bool frames = false;
    double fps = kDefaultFrameRate;

    // The nearest time on the grid: a whole frame in frames mode, else a whole microsecond.
    double snap(double seconds) const;
    // Seconds in the shown unit (frames may be fractional: a key between frames shows where it is).
    double shown(double seconds) const { return frames ? seconds * fps : seconds; }
    double seconds(double shown_value) const { return frames ? shown_value / fps : shown_value; }
    // "12 f" / "12.5 f", or "0.4 s" (shortest text of the value shown, up to 4 decimals).
    std::string text(double seconds) const;
    const char* suffix() const { return frames ? "f" : "s"; }
};

// The frame rate clip `def` is authored at: the first of 30, 24, 25, 60, 50, 120 whose frame grid holds
// every key time (phase end) and event time of the clip (within a microsecond); 30 when none does.
double clip_frame_rate(const anim::ClipDef& def);

// Reads a time typed by the animator: a number in the shown unit, or with "s" / "f" naming the unit
// ("0.5s", "15 f"). nullopt when it is not a finite number.
std::optional<double> parse_time_text(std::string_view text, const TimeUnits& units);

} // namespace ks::editor
