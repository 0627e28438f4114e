// Clip event (timeline marker) edits (dojo_clips.h).
#include "model/dojo_clips.h"

#include "model/dojo_edit_support.h"

#include <algorithm>
#include <cmath>

namespace ks::editor {
namespace {
using dojo_support::clip_at;
using dojo_support::seconds_text;

Result<anim::ClipEvent*> event_at(anim::AnimationFile& file, std::size_t clip, std::size_t event) {
    auto found = clip_at(file, clip);
    if (!found) return found.error();
    auto& events = (*found)->events;
    if (event >= events.size())
        return Error("clip '" + (*found)->name + "' has no event " + std::to_string(event + 1), {},
                     "it has " + std::to_string(events.size()) + " events");
    return &events[event];
}

Result<void> check_name(const std::string& name) {
    if (name.empty()) return Error("an event needs a name", {}, "e.g. muzzle_flash or footstep");
    return ok();
}

Result<void> check_sound(const std::string& sound) {
    const bool spelled = std::all_of(sound.begin(), sound.end(), [](char ch) {
        return (ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9') || ch == '_';
    });
    if (!spelled)
        return Error("sound name '" + sound + "' has characters other than a-z, 0-9 and _", {},
                     "name a file of assets/sounds/ without its .wav, or leave it empty for none");
    return ok();
}

// Puts events[index] in its place by time, after events at the same time, and the others in time order too
// (a file written by hand may list them in any order); returns where events[index] went.
std::size_t resort(std::vector<anim::ClipEvent>& events, std::size_t index) {
    anim::ClipEvent moved = std::move(events[index]);
    events.erase(events.begin() + static_cast<std::ptrdiff_t>(index));
    const auto by_time = [](const anim::ClipEvent& a, const anim::ClipEvent& b) { return a.time < b.time; };
    std::stable_sort(events.begin(), events.end(), by_time);
    const auto placed = events.insert(std::upper_bound(events.begin(), events.end(), moved, by_time), moved);
    return static_cast<std::size_t>(placed - events.begin());
}

} // namespace

Result<std::size_t> add_event(anim::AnimationFile& file, std::size_t clip, double seconds,
                              const std::string& name, const std::string& sound) {
    auto found = clip_at(file, clip);
    if (!found) return found.error();
    anim::ClipDef& c = **found;
    const double length = c.duration();
    if (!std::isfinite(seconds) || seconds < 0 || seconds > length)
        return Error("event time " + seconds_text(seconds) + " is outside clip '" + c.name + "'", {},
                     "a time in [0, " + seconds_text(length) + "]");
    if (auto r = check_name(name); !r) return r.error();
    if (auto r = check_sound(sound); !r) return r.error();
    c.events.push_back({seconds, name, sound});
    return resort(c.events, c.events.size() - 1);
}

Result<std::size_t> move_event(anim::AnimationFile& file, std::size_t clip, std::size_t event,
                               double seconds) {
    auto found = event_at(file, clip, event);
    if (!found) return found.error();
    if (!std::isfinite(seconds))
        return Error("event time is not a number", {}, "seconds from the clip's start");
    auto& events = file.clips[clip].events;
    (*found)->time = std::clamp(seconds, 0.0, file.clips[clip].duration());
    return resort(events, event);
}

Result<void> rename_event(anim::AnimationFile& file, std::size_t clip, std::size_t event,
                          const std::string& name) {
    auto found = event_at(file, clip, event);
    if (!found) return found.error();
    if (auto r = check_name(name); !r) return r;
    (*found)->name = name;
    return ok();
}

Result<void> set_event_sound(anim::AnimationFile& file, std::size_t clip, std::size_t event,
                             const std::string& sound) {
    auto found = event_at(file, clip, event);
    if (!found) return found.error();
    if (auto r = check_sound(sound); !r) return r;
    (*found)->sound = sound;
    return ok();
}

Result<void> remove_event(anim::AnimationFile& file, std::size_t clip, std::size_t event) {
    auto found = event_at(file, clip, event);
    if (!found) return found.error();
    auto& events = file.clips[clip].events;
    events.erase(events.begin() + static_cast<std::ptrdiff_t>(event));
    return ok();
}

} // namespace ks::editor
