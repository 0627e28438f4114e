#include "model/dojo_playback.h"

#include <algorithm>
#include <cmath>

namespace ks::editor {

void dojo_restart_at(anim::Player& player, const DojoPlayPlan& plan, double seconds) {
    if (!plan.transition) {
        player.play(plan.clip, 0.0f);
        player.advance(seconds);
        return;
    }
    player.play(plan.from, 0.0f);
    player.advance(std::min(seconds, plan.switch_at));
    if (seconds > plan.switch_at) {
        player.play(plan.to, plan.blend);
        player.advance(seconds - plan.switch_at);
    }
}

void dojo_advance(anim::Player& player, const DojoPlayPlan& plan, double now, double step,
                  const std::function<void(const anim::Player&)>& after_advance) {
    auto advance = [&](double dt) {
        player.advance(dt);
        if (after_advance) after_advance(player);
    };
    // The same rule as dojo_restart_at: `to` starts once the time is past the switch, not at it.
    if (plan.transition && now <= plan.switch_at && now + step > plan.switch_at) {
        advance(plan.switch_at - now);
        player.play(plan.to, plan.blend);
        advance(now + step - plan.switch_at);
        return;
    }
    advance(step);
}

double dojo_pass_time(anim::LoopMode loop, double duration, double time) {
    if (duration <= 0) return 0.0;
    switch (loop) {
    case anim::LoopMode::Loop:
        return std::fmod(time, duration);
    case anim::LoopMode::PingPong: {
        const double u = std::fmod(time, 2.0 * duration);
        return u <= duration ? u : 2.0 * duration - u;
    }
    default:
        return std::min(time, duration);
    }
}

DojoKeysAround dojo_keys_around(const anim::ClipDef& clip, double time) {
    DojoKeysAround around;
    const double duration = clip.duration();
    if (duration <= 0) return around;
    const double now =
        clip.loop == anim::LoopMode::Once ? std::min(time, duration) : std::fmod(time, duration);
    constexpr double kAtKey = 1e-4; // the playhead on a key: the neighbours are the keys around it
    if (now > kAtKey) around.previous = 0.0;
    double t = 0.0;
    for (const anim::PhaseDef& phase : clip.phases) {
        t += phase.duration;
        if (t < now - kAtKey) around.previous = t;
        if (t > now + kAtKey && around.next < 0) around.next = t;
    }
    return around;
}

void DojoPlayback::set_rig(anim::Rig rig) {
    player_.reset();
    clips_ = {};
    rig_ = std::move(rig);
}

void DojoPlayback::set_clips(anim::ClipSet clips) {
    clips_ = std::move(clips);
    const int last = std::max(0, static_cast<int>(clips_.clips.size()) - 1);
    plan_.clip = std::clamp(plan_.clip, 0, last);
    plan_.from = std::clamp(plan_.from, 0, last);
    plan_.to = std::clamp(plan_.to, 0, last);
    player_ = std::make_unique<anim::Player>(clips_, rig_);
    restart_at(time_);
}

bool DojoPlayback::show_clip(int index) {
    if (index < 0 || index >= static_cast<int>(clips_.clips.size())) return false;
    plan_.clip = index;
    plan_.transition = false;
    playing_ = true;
    restart_at(0.0);
    return true;
}

bool DojoPlayback::test_transition(int from, int to) {
    const int count = static_cast<int>(clips_.clips.size());
    if (from < 0 || to < 0 || from >= count || to >= count) return false;
    plan_.from = from;
    plan_.to = to;
    plan_.blend = clips_.blend_time(from, to);
    plan_.transition = true;
    playing_ = true;
    restart_at(0.0);
    return true;
}

void DojoPlayback::set_transition(bool on, int from, int to, double switch_at, float blend) {
    const int count = static_cast<int>(clips_.clips.size());
    plan_.transition = on;
    if (from >= 0 && from < count) plan_.from = from;
    if (to >= 0 && to < count) plan_.to = to;
    plan_.switch_at = switch_at;
    plan_.blend = blend;
}

void DojoPlayback::restart_at(double seconds) {
    if (!player_ || clips_.clips.empty()) return;
    player_ = std::make_unique<anim::Player>(clips_, rig_);
    dojo_restart_at(*player_, plan_, seconds);
    time_ = seconds;
}

void DojoPlayback::advance(double dt, const std::function<void(const anim::Player&)>& after_advance) {
    if (!player_ || !playing_ || !(dt > 0) || clips_.clips.empty()) return;
    const double step = dt * speed_;
    const double length = timeline_length();
    if (loop_ && length > 0 && time_ + step > length &&
        (plan_.transition || clips_.clips[static_cast<size_t>(plan_.clip)].loop == anim::LoopMode::Once)) {
        restart_at(0.0);
        return;
    }
    dojo_advance(*player_, plan_, time_, step, after_advance);
    time_ += step;
}

double DojoPlayback::timeline_length() const {
    if (clips_.clips.empty()) return 0.0;
    if (plan_.transition)
        return plan_.switch_at + plan_.blend + clips_.clips[static_cast<size_t>(plan_.to)].duration;
    return clips_.clips[static_cast<size_t>(plan_.clip)].duration;
}

} // namespace ks::editor
