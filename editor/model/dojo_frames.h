#pragma once
// Seconds or frames in the dojo: the frame rate a clip is authored at (its stored "frame_rate", else the
// common rate whose grid holds every key time and event, 30 when none or several do), snapping times to that
// grid, and times as the animator reads and types them ("12 f" or "0.4 s"). The file always stores seconds;
// a clip with a stored frame rate is shown in frames, and every time the dojo writes for it is a whole frame
// (k / fps, the nearest double, written as its shortest round-trip text).
#include "anim/clip.h"
#include "core/result.h"

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

// The frame rate clip `def` is authored at: its stored frame_rate, else the first of 30, 24, 25, 60, 50, 120
// whose frame grid holds every key time (phase end) and event time of the clip (within a microsecond); 30
// when none does.
double clip_frame_rate(const anim::ClipDef& def);
// How the dojo shows clip `def`: in frames at its stored rate, in seconds when it stores none.
TimeUnits clip_time_units(const anim::ClipDef& def);

// The frame rates offered in the dojo (film, PAL, NTSC-whole, double rates, high speed).
inline constexpr double kFrameRates[] = {24.0, 25.0, 30.0, 48.0, 50.0, 60.0, 120.0};
// Stores `fps` as clip `clip`'s frame rate (frames mode, saved with the file), or removes it (nullopt:
// seconds). Key and event times are left where they are (a time between frames shows as a fraction).
// Refused, file unchanged, for a rate the file refuses (anim::validate: [1, 1000]) or a missing clip.
Result<void> set_clip_frame_rate(anim::AnimationFile& file, std::size_t clip, std::optional<double> fps);

// Where a scrub of the timeline puts the playhead: on key time (phase end) of `def` when `seconds` is within
// `reach` seconds of one (the nearest; so Key and auto-key write that key instead of splitting its phase a
// hair away), else on the frame grid in frames mode, else `seconds`. Kept in [0, duration].
double scrub_time(const anim::ClipDef& def, const TimeUnits& units, double seconds, double reach);

// Reads a time typed by the animator: a number in the shown unit, or with "s" / "f" naming the unit
// ("0.5s", "15 f"). nullopt when it is not a finite number.
std::optional<double> parse_time_text(std::string_view text, const TimeUnits& units);

} // namespace ks::editor
