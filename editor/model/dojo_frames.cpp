#include "model/dojo_frames.h"

#include "model/dojo_edit_support.h"
#include "model/dojo_keys.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <vector>

namespace ks::editor {

double TimeUnits::snap(double seconds) const {
    return frames ? std::round(seconds * fps) / fps : editor::snap(seconds, kTimeSteps);
}

std::string TimeUnits::text(double seconds) const {
    char out[48];
    std::snprintf(out, sizeof(out), "%.4f", shown(seconds));
    std::string s = out;
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    if (s == "-0") s = "0";
    return s + (frames ? " f" : " s");
}

double clip_frame_rate(const anim::ClipDef& def) {
    if (def.frame_rate) return *def.frame_rate;
    std::vector<double> times;
    double end = 0;
    for (const anim::PhaseDef& phase : def.phases) times.push_back(end += phase.duration);
    for (const anim::ClipEvent& event : def.events) times.push_back(event.time);
    for (const double fps : {30.0, 24.0, 25.0, 60.0, 50.0, 120.0}) {
        bool fits = true;
        for (const double t : times) fits = fits && std::abs(t * fps - std::round(t * fps)) < 1e-6 * fps;
        if (fits) return fps;
    }
    return kDefaultFrameRate;
}

TimeUnits clip_time_units(const anim::ClipDef& def) {
    return {def.frame_rate.has_value(), clip_frame_rate(def)};
}

Result<void> set_clip_frame_rate(anim::AnimationFile& file, std::size_t clip, std::optional<double> fps) {
    if (auto found = dojo_support::clip_at(file, clip); !found) return found.error();
    anim::AnimationFile edited = file;
    edited.clips[clip].frame_rate = fps;
    // The rate's limits are the file's (anim::validate): refused with its message and hint.
    if (auto valid = dojo_support::no_new_clip_issues(file, edited, clip); !valid) return valid.error();
    file = std::move(edited);
    return ok();
}

double scrub_time(const anim::ClipDef& def, const TimeUnits& units, double seconds, double reach) {
    double best = seconds, nearest = reach, end = 0;
    for (const anim::PhaseDef& phase : def.phases) {
        end += phase.duration;
        if (const double d = std::abs(end - seconds); d <= nearest) nearest = d, best = end;
    }
    if (best == seconds && units.frames) best = units.snap(seconds);
    return std::clamp(best, 0.0, def.duration());
}

std::optional<double> parse_time_text(std::string_view text, const TimeUnits& units) {
    while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
    while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
    std::optional<bool> frames;
    if (!text.empty() && (text.back() == 'f' || text.back() == 's')) {
        frames = text.back() == 'f';
        text.remove_suffix(1);
        while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
    }
    double value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
        return std::nullopt;
    const bool in_frames = frames.value_or(units.frames);
    return in_frames ? value / units.fps : value;
}

} // namespace ks::editor
